#include "engine3d/force_pass3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "talus/contact_force.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {

namespace {

// Calls on_pair(e, j, geometry, parameters, spring) for every touching entry of sphere i's row,
// then on_plate(e, plate, geometry, parameters, spring) for its touching plates; the spring of
// an entry no longer touching is cleared (and `apart(e, is_plate)` told).
template <class S, class L, class Pair, class OnPlate, class Apart>
[[gnu::flatten]] void contacts_of(std::size_t i, S& scene, L& list, const PairTable& table,
                                  LeverShares shares, Pair&& on_pair, OnPlate&& on_plate,
                                  Apart&& apart) {
  const Spheres& s = scene.spheres;
  for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
    const std::uint32_t j = list.neighbour[e];
    const Vec3 d = s.position[i] - (s.position[j] + list.offset(e, scene.domain));
    const double reach = s.radius[i] + s.radius[j];
    const double dist2 = norm2(d);
    if (dist2 >= reach * reach || dist2 == 0.0) {
      apart(e, false);
      continue;
    }
    const ContactGeometry3 g = pair_geometry(
        d, std::sqrt(dist2), s.radius[i], s.radius[j], s.mass[i], s.mass[j], s.velocity[i],
        s.velocity[j], s.angular_velocity[i], s.angular_velocity[j], true, shares);
    on_pair(e, j, g, table(s.material[i], s.material[j]), list.spring[e]);
  }
  for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e) {
    const auto& plate = scene.plates[list.plate[e]];
    const Vec3 touch = closest_point(plate, s.position[i]);
    const Vec3 d = s.position[i] - touch;
    const double dist2 = norm2(d);
    if (dist2 >= s.radius[i] * s.radius[i] || dist2 == 0.0) {
      apart(e, true);
      continue;
    }
    const ContactGeometry3 g =
        wall_geometry(d, std::sqrt(dist2), s.radius[i], s.mass[i], s.velocity[i],
                      s.angular_velocity[i], plate.velocity_at(touch), shares);
    on_plate(e, list.plate[e], g, table(s.material[i], plate.material), list.plate_spring[e]);
  }
}

// A sphere's inertia about a point of its rim, which rolling resistance's dashpot takes.
double rim_of(const Spheres& s, std::size_t i) {
  return rim_inertia(s.inertia[i], s.mass[i], s.radius[i]);
}

// Rolling resistance's torque on i of a contact with rolling spring `theta` (turned into the
// tangent plane and advanced a step here), against a sphere or plate of spin w_j and rim inertia
// rim_j (0: a plate, infinitely heavy). None where the pair does not roll with resistance.
template <class N>
Vec3 rolling_torque(const PairParameters& p, const ContactGeometry3& g, double normal_force,
                    const Vec3& w_i, const Vec3& w_j, double rim_i, double rim_j, Vec3& theta,
                    double dt) {
  if (p.rolling_friction == 0.0) return {};
  theta = into_tangent_plane(theta, g.normal);
  return RollingLaw::torque<N>(p, g, not_below_zero(normal_force), rolling_spin(w_i, w_j, g.normal),
                               rolling_inertia(rim_i, rim_j), theta, dt);
}

// The elastic energy of a rolling spring as it stands (turned into the tangent plane).
template <class N>
double rolling_energy(const PairParameters& p, const ContactGeometry3& g, const Vec3& theta) {
  if (p.rolling_friction == 0.0) return 0.0;
  return RollingLaw::elastic_energy<N>(p, g, into_tangent_plane(theta, g.normal));
}

} // namespace

std::size_t ForcePass3::bytes() const {
  return sizeof(Vec3) * (force_.capacity() + torque_i_.capacity() + torque_j_.capacity() +
                         plate_force_.capacity() + plate_torque_.capacity());
}

ContactPass3 ForcePass3::add(Scene3& scene, SphereList& list, const PairTable& table,
                             const Settings3& settings, int threads) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    Spheres& s = scene.spheres;
    const auto n = static_cast<std::ptrdiff_t>(s.size());
    const double dt = settings.timestep;
    const LeverShares shares = lever_shares(settings.lever_arm);
    force_.resize(list.pair_count());
    torque_i_.resize(list.pair_count());
    torque_j_.resize(list.pair_count());
    plate_force_.resize(list.plate.size());
    plate_torque_.resize(list.plate.size());
    std::size_t contacts = 0, on_plates = 0;
    double deepest = 0.0;
    // each entry's force, rows side by side
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : contacts, on_plates) \
    reduction(max : deepest)
    for (std::ptrdiff_t row = 0; row < n; ++row) {
      const auto i = static_cast<std::size_t>(row);
      contacts_of(
          i, scene, list, table, shares,
          [&](std::uint32_t e, std::uint32_t j, const ContactGeometry3& g, const PairParameters& p,
              Vec3& spring) {
            const ContactForce3 c = contact_force<N, T>(p, g, spring, dt);
            force_[e] = c.force, torque_i_[e] = c.torque_i, torque_j_[e] = c.torque_j;
            if (list.with_rolling) {
              const Vec3 m = rolling_torque<N>(p, g, c.normal_force, s.angular_velocity[i],
                                               s.angular_velocity[j], rim_of(s, i), rim_of(s, j),
                                               list.rolling[e], dt);
              torque_i_[e] += m, torque_j_[e] -= m;
            }
            ++contacts;
            deepest = std::max(deepest, g.overlap / std::min(s.radius[i], s.radius[j]));
          },
          [&](std::uint32_t e, std::uint32_t w, const ContactGeometry3& g, const PairParameters& p,
              Vec3& spring) {
            const ContactForce3 c = contact_force<N, T>(p, g, spring, dt);
            plate_force_[e] = c.force, plate_torque_[e] = c.torque_i;
            if (list.with_rolling)
              plate_torque_[e] += rolling_torque<N>(p, g, c.normal_force, s.angular_velocity[i],
                                                    scene.plates[w].angular_velocity, rim_of(s, i),
                                                    0.0, list.plate_rolling[e], dt);
            ++contacts, ++on_plates;
            deepest = std::max(deepest, g.overlap / s.radius[i]);
          },
          [&](std::uint32_t e, bool plate) {
            if (plate) {
              list.plate_spring[e] = plate_force_[e] = plate_torque_[e] = {};
              if (list.with_rolling) list.plate_rolling[e] = {};
            } else {
              list.spring[e] = force_[e] = torque_i_[e] = torque_j_[e] = {};
              if (list.with_rolling) list.rolling[e] = {};
            }
          });
    }
    // each sphere's sum, in a fixed order
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      Vec3 f = s.force[i], m = s.torque[i];
      for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e)
        f += force_[e], m += torque_i_[e];
      for (std::uint32_t q = list.second_offset[i]; q < list.second_offset[i + 1]; ++q) {
        const std::uint32_t e = list.second_entry[q];
        f -= force_[e], m += torque_j_[e];
      }
      for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e)
        f += plate_force_[e], m += plate_torque_[e];
      s.force[i] = f, s.torque[i] = m;
    }
    for (Plane& p : scene.plates) p.force = {};
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e)
        scene.plates[list.plate[e]].force -= plate_force_[e];
    return ContactPass3{contacts, on_plates, deepest};
  });
}

double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    double e = 0.0;
    const auto add = [&](const std::vector<Vec3>& rolling) {
      return [&](std::uint32_t k, std::uint32_t, const ContactGeometry3& g, const PairParameters& p,
                 const Vec3& spring) {
        e += contact_elastic_energy<N, T>(p, g, into_tangent_plane(spring, g.normal));
        if (list.with_rolling) e += rolling_energy<N>(p, g, rolling[k]);
      };
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
      contacts_of(i, scene, list, table, lever_shares(settings.lever_arm), add(list.rolling),
                  add(list.plate_rolling), [](std::uint32_t, bool) {});
    return e;
  });
}

std::string deepest_contact(const Scene3& scene, const SphereList& list,
                            const Settings3& settings) {
  const Spheres& s = scene.spheres;
  const PairTable table(scene.materials, settings.impact_speed, settings.linear_damping);
  double deepest = -1.0;
  std::ostringstream words;
  for (std::size_t i = 0; i < s.size(); ++i)
    contacts_of(
        i, scene, list, table, lever_shares(settings.lever_arm),
        [&](std::uint32_t, std::uint32_t j, const ContactGeometry3& g, const PairParameters&,
            const Vec3&) {
          const double f = g.overlap / std::min(s.radius[i], s.radius[j]);
          if (f <= deepest) return;
          deepest = f;
          words.str("");
          words << "sphere " << s.id[i] << " overlaps sphere " << s.id[j] << " by " << f;
        },
        [&](std::uint32_t, std::uint32_t w, const ContactGeometry3& g, const PairParameters&,
            const Vec3&) {
          const double f = g.overlap / s.radius[i];
          if (f <= deepest) return;
          deepest = f;
          words.str("");
          words << "sphere " << s.id[i] << " overlaps plate " << w << " by " << f;
        },
        [](std::uint32_t, bool) {});
  return words.str() + " of the smaller radius";
}

} // namespace talus
