#include "cli/run/thermo3.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "analysis/energy_ledger3.hpp"
#include "analysis/stress3.hpp"
#include "analysis/structure3.hpp"
#include "engine3d/cell3.hpp"
#include "scenario3d/box3.hpp"

namespace talus::cli {

namespace {

constexpr std::array<const char*, 3> structure_names{
    "region_packing_fraction", "load_bearing_coordination", "rattler_fraction"};

// A region's stress, fabric and structure columns.
std::string region_columns(const Simulation3& sim, const Region3& r, int needed) {
  const LoadBearing network = load_bearing(sim, r.lo, r.hi, needed);
  const double rattlers = network.grains > 0 ? static_cast<double>(network.rattlers) /
                                                   static_cast<double>(network.grains)
                                             : 0.0;
  return stress_thermo_columns(region_stress(sim, r.lo, r.hi)) +
         fmt::format(",{:.9f},{:.6f},{:.6f}", packing_fraction(sim, r.lo, r.hi),
                     network.coordination, rattlers);
}

// The box with each servo plate's side where the plate stands now: the default stress region of
// a box a servo presses, so that its packing fraction is of the packing, not of the space the
// plate has left behind it.
Region3 up_to_servo_plates(const Simulation3& sim, Region3 box) {
  for (const PlateServo& servo : sim.scene().servos) {
    const Vec3 n = servo.direction; // inward: +axis for a lo side, -axis for a hi side
    const Vec3& at = sim.scene().plates[servo.plate].centre;
    for (int k = 0; k < 3; ++k) {
      if (component(n, k) > 0.5) component(box.lo, k) = component(at, k);
      if (component(n, k) < -0.5) component(box.hi, k) = component(at, k);
    }
  }
  return box;
}

} // namespace

Thermo3::Thermo3(const Scenario3& s, const std::vector<double>& ledger_state) {
  for (const BoxSide& side : box3_sides(s.geometry)) plate_names_.push_back(side.name);
  for (const Driver3Section& d : s.drivers)
    if (d.servo) servo_names_.push_back(d.target);
  fixed_spheres_ = s.geometry.rough_floor;
  cell_ = std::ranges::any_of(s.drivers, [](const Driver3Section& d) { return d.cell; });
  if (s.output.stress) {
    regions_.emplace_back("",
                          s.output.stress_region.value_or(Region3{s.geometry.lo, s.geometry.hi}));
    default_region_ = !s.output.stress_region;
    for (const StressRegion3& r : s.output.stress_regions)
      regions_.emplace_back(r.name + "_", r.region);
  }
  if (!s.output.energy_ledger) return;
  ledger_.emplace();
  if (!ledger_state.empty()) ledger_->load(ledger_state);
}

void Thermo3::start(const Simulation3& sim) {
  if (ledger_) start_ledger(*ledger_, sim);
}

void Thermo3::look(const Simulation3& sim) {
  if (ledger_) observe_ledger(*ledger_, sim);
}

std::vector<double> Thermo3::save() const {
  return ledger_ ? ledger_->save() : std::vector<double>{};
}

std::string Thermo3::header() const {
  std::string head = "time,step,kinetic,rotational,potential,elastic,total,contacts,"
                     "coordination,list_builds";
  for (const std::string& name : plate_names_)
    head += fmt::format(",force_{0}_x,force_{0}_y,force_{0}_z", name);
  if (fixed_spheres_) head += ",force_fixed_x,force_fixed_y,force_fixed_z";
  for (const std::string& name : servo_names_) head += ",servo_" + name + "_displacement";
  if (cell_)
    head += ",cell_x,cell_y,cell_z,cell_strain_rate_x,cell_strain_rate_y,cell_strain_rate_z,"
            "cell_shear_rate,cell_shear_strain";
  if (ledger_) head += ledger_thermo_header;
  for (const auto& [prefix, region] : regions_) {
    head += stress_thermo_header(prefix);
    for (const char* name : structure_names) head += "," + prefix + name;
  }
  return head + "\n";
}

std::string Thermo3::row(const Simulation3& sim, double collision_time) {
  const Energies3 e = sim.energies();
  std::string out =
      fmt::format("{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.6g},{}", sim.time(),
                  sim.step_count(), e.kinetic, e.rotational, e.potential, e.elastic, e.total(),
                  sim.contact_count(), sim.coordination(), sim.list().builds);
  for (const Plane& p : sim.scene().plates)
    out += fmt::format(",{:.9e},{:.9e},{:.9e}", p.force.x, p.force.y, p.force.z);
  if (fixed_spheres_) {
    const Spheres& spheres = sim.scene().spheres;
    Vec3 f{};
    for (std::size_t i = 0; i < spheres.size(); ++i)
      if (!spheres.is_free(i)) f += spheres.force[i];
    out += fmt::format(",{:.9e},{:.9e},{:.9e}", f.x, f.y, f.z);
  }
  for (const PlateServo& servo : sim.scene().servos)
    out += fmt::format(",{:.9e}", servo.displacement);
  if (const auto& c = sim.scene().cell) {
    const Vec3 size = sim.scene().domain.size(), rate = cell_strain_rate(*c);
    out += fmt::format(",{:.9e},{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{:.6e},{:.9e}", size.x, size.y,
                       size.z, rate.x, rate.y, rate.z, c->shear_rate, c->shear_strain);
  }
  if (ledger_) {
    const LedgerRow l = ledger_row(*ledger_, e);
    if (l.growth > ledger_growth_limit)
      throw InstabilityError(energy_growth_diagnosis(sim, l, collision_time));
    out += fmt::format(",{:.9e},{:.9e},{:.9e},{:.9e}", l.dissipated_damper, l.dissipated_friction,
                       l.wall_work, l.imbalance);
  }
  if (!regions_.empty()) {
    const int needed = contacts_needed(sim);
    for (std::size_t k = 0; k < regions_.size(); ++k) {
      Region3 region = regions_[k].second;
      if (k == 0 && default_region_) // the box as the cell has made it, or up to the servos
        region = cell_ ? Region3{sim.scene().domain.lo, sim.scene().domain.hi}
                       : up_to_servo_plates(sim, region);
      out += region_columns(sim, region, needed);
    }
  }
  return out + "\n";
}

} // namespace talus::cli
