#pragma once
// The automatic skin (simulation.skin = 0): chosen again at every list build from how fast the
// grains move, so that neither the list's extra entries nor its rebuilds dominate a step.
#include "core/domain.hpp"
#include "state/particles.hpp"
#include "state/walls.hpp"

namespace talus {

/// The skin that balances the two costs a skin sets, for grains of mean radius R whose fastest
/// moves at `speed` with time step dt. A wider skin puts about 2 phi / R more entries per
/// particle and metre of skin into the list (phi: packing fraction), each tested when the
/// contact candidates are chosen (a few times in a list's life); a narrower one rebuilds the list
/// more often, every skin / (2 v dt) steps, each rebuild costing about as much per particle as C
/// entry tests in a step. The sum is least at skin = sqrt(C / phi x v dt R); C / phi = 256, chosen
/// by measurement (docs/performance.md, "Automatic skin"). The skin is kept within [0.1, 1] x R,
/// and below what a periodic box allows (3 interaction ranges 2 R_max + skin per period).
double automatic_skin(double speed, double dt, double mean_radius, double max_radius,
                      const Domain& domain);

/// automatic_skin for the world as it is: the fastest of what can set off a rebuild (free grains,
/// wall grains moved by drivers, the ends of moving wall segments), the mean radius of the free
/// grains (of all, if none is free), the largest radius.
double automatic_skin(const Particles& p, const Segments& walls, const Domain& domain, double dt);

} // namespace talus
