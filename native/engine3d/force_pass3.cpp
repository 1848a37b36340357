#include "engine3d/force_pass3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <omp.h>

#include "engine3d/contact_visit3.hpp"
#include "engine3d/pair_lanes3.hpp"
#include "neighbours/neighbour_list.hpp"

namespace talus {

int pair_contact_lanes() {
  return lane_count<ContactLanes3>;
}

std::size_t ForcePass3::bytes() const {
  std::size_t found = 0;
  for (const auto& f : found_) found += f.capacity() * sizeof(Touching3);
  return found + touched_.capacity() +
         sizeof(Vec3) * (deferred_force_.capacity() + deferred_torque_j_.capacity() +
                         plate_force_.capacity() + plate_torque_.capacity());
}

void ForcePass3::take_touching_from_springs(const SphereList& list) {
  const std::size_t n = list.pair_count();
  const auto some = [](const Vec3& v) { return v.x != 0.0 || v.y != 0.0 || v.z != 0.0; };
  touched_.resize(n);
  for (std::size_t e = 0; e < n; ++e)
    touched_[e] =
        (list.with_springs && some(list.spring[e])) || (list.with_rolling && some(list.rolling[e]))
            ? 1
            : 0;
  deferred_force_.assign(n, Vec3{});
  deferred_torque_j_.assign(n, Vec3{});
  list_changed_ = false;
}

namespace {

// f.template operator()<Springs, Rolling>() with what the list keeps.
template <class F> std::size_t touching_in(const SphereList& list, F&& f) {
  if (list.with_springs)
    return list.with_rolling ? f.template operator()<true, true>()
                             : f.template operator()<true, false>();
  return list.with_rolling ? f.template operator()<false, true>()
                           : f.template operator()<false, false>();
}

} // namespace

template <class N, class T, bool Rotation>
ContactPass3 ForcePass3::compute_with(Scene3& scene, SphereList& list, const PairTable& table,
                                      const Settings3& settings, int threads, bool one_material) {
  Spheres& s = scene.spheres;
  const std::size_t n = s.size();
  const double dt = settings.timestep;
  const LeverShares shares = lever_shares(settings.lever_arm);
  const std::uint32_t rows = force_block_rows(n);
  const auto blocks = static_cast<std::ptrdiff_t>(n == 0 ? 0 : (n + rows - 1) / rows);
  if (list_changed_ || touched_.size() != list.pair_count()) take_touching_from_springs(list);
  plate_force_.resize(list.plate.size());
  plate_torque_.resize(list.plate.size());
  found_.resize(static_cast<std::size_t>(std::max(threads, 1)));
  const PairLanes3<ContactLanes3> pairs(table, one_material);
  std::size_t contacts = 0, on_plates = 0;
  double deepest = 0.0;
  // each block's spheres sum their weights, the contacts among them in entry order, then their
  // plates'
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) \
    reduction(+ : contacts, on_plates) reduction(max : deepest)
  for (std::ptrdiff_t block = 0; block < blocks; ++block) {
    const auto first = static_cast<std::uint32_t>(block) * rows;
    const auto last = static_cast<std::uint32_t>(std::min<std::size_t>(n, first + rows));
    for (std::uint32_t i = first; i < last; ++i) {
      s.force[i] = s.is_free(i) ? s.mass[i] * scene.gravity : Vec3{};
      if constexpr (Rotation) s.torque[i] = {};
    }
    const BlockSums3 sums{s,
                          first,
                          last,
                          deferred_force_.data(),
                          deferred_torque_j_.data(),
                          scene.domain.shear_velocity};
    std::vector<Touching3>& found = found_[static_cast<std::size_t>(omp_get_thread_num())];
    // by stretches of rows, so that the touching entries written down are still in the cache
    // when their forces are computed
    for (std::uint32_t r0 = first; r0 < last; r0 += stretch_rows) {
      const std::uint32_t r1 = std::min(last, r0 + stretch_rows);
      found.resize(std::max<std::size_t>(found.size(), list.row_offset[r1] - list.row_offset[r0]));
      const std::size_t touching = touching_in(list, [&]<bool Springs, bool Rolling>() {
        return touching_entries<Springs, Rolling>(s, list, scene.domain, sums, r0, r1,
                                                  touched_.data(), found.data());
      });
      const ContactTally3 tally = pair_forces3<N, T, Rotation>(sums, list, pairs, table,
                                                               found.data(), touching, dt, shares);
      contacts += tally.contacts, deepest = std::max(deepest, tally.deepest);
    }
    const ContactTally3 plates =
        plate_forces<N, T, Rotation>(scene, list, table, first, last, dt, shares);
    contacts += plates.contacts, on_plates += plates.contacts;
    deepest = std::max(deepest, plates.deepest);
  }
  // then the contacts with spheres of the blocks before, in entry order
  // (the first block has none before it)
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t block = 1; block < blocks; ++block) {
    const auto first = static_cast<std::uint32_t>(block) * rows;
    const auto last = static_cast<std::uint32_t>(std::min<std::size_t>(n, first + rows));
    const std::uint32_t block_entries = list.row_offset[first];
    for (std::uint32_t i = first; i < last; ++i) {
      Vec3 f = s.force[i], m = s.torque[i];
      for (std::uint32_t q = list.second_offset[i]; q < list.second_offset[i + 1]; ++q) {
        const std::uint32_t e = list.second_entry[q];
        if (e >= block_entries) break;
        f -= deferred_force_[e];
        if constexpr (Rotation) m += deferred_torque_j_[e];
      }
      s.force[i] = f;
      if constexpr (Rotation) s.torque[i] = m;
    }
  }
  for (Plane& p : scene.plates) p.force = {};
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e)
      scene.plates[list.plate[e]].force -= plate_force_[e];
  return ContactPass3{contacts, on_plates, deepest};
}

template <class N, class T, bool Rotation>
ContactTally3 ForcePass3::plate_forces(Scene3& scene, SphereList& list, const PairTable& table,
                                       std::uint32_t first, std::uint32_t last, double dt,
                                       LeverShares shares) {
  Spheres& s = scene.spheres;
  ContactTally3 tally;
  for (std::uint32_t i = first; i < last; ++i) {
    for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e) {
      const std::uint32_t w = list.plate[e];
      const Plane& plate = scene.plates[w];
      const Vec3 touch = closest_point(plate, s.position[i]);
      const Vec3 d = s.position[i] - touch;
      const double dist2 = norm2(d);
      if (dist2 >= s.radius[i] * s.radius[i] || dist2 == 0.0) {
        plate_force_[e] = plate_torque_[e] = {};
        if (list.with_springs) list.plate_spring[e] = {};
        if (list.with_rolling) list.plate_rolling[e] = {};
        continue;
      }
      const ContactGeometry3 g =
          wall_geometry(d, std::sqrt(dist2), s.radius[i], s.mass[i], s.velocity[i],
                        spin_of<Rotation>(s, i), plate.velocity_at(touch), shares);
      const PairParameters& p = table(s.material[i], plate.material);
      Vec3 none{}; // the spring of a law without history, which it leaves alone
      const ContactForce3 c =
          contact_force<N, T>(p, g, list.with_springs ? list.plate_spring[e] : none, dt);
      plate_force_[e] = c.force, plate_torque_[e] = c.torque_i;
      if (list.with_rolling)
        plate_torque_[e] +=
            rolling_torque<N>(p, g, c.normal_force, s.angular_velocity[i], plate.angular_velocity,
                              rim_of(s, i), 0.0, list.plate_rolling[e], dt);
      s.force[i] += plate_force_[e];
      if constexpr (Rotation) s.torque[i] += plate_torque_[e];
      ++tally.contacts;
      tally.deepest = std::max(tally.deepest, g.overlap / s.radius[i]);
    }
  }
  return tally;
}

ContactPass3 ForcePass3::compute(Scene3& scene, SphereList& list, const PairTable& table,
                                 const Settings3& settings, int threads, bool rotation,
                                 bool one_material) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    // only a frictionless law has a step without rotation
    if constexpr (!T::has_friction)
      if (!rotation)
        return compute_with<N, T, false>(scene, list, table, settings, threads, one_material);
    return compute_with<N, T, true>(scene, list, table, settings, threads, one_material);
  });
}

double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    double e = 0.0;
    const auto add = [&](const std::vector<Vec3>& spring, const std::vector<Vec3>& rolling) {
      return [&](std::uint32_t, std::uint32_t k, std::uint32_t, const ContactGeometry3& g,
                 const PairParameters& p) {
        const Vec3 stretch = list.with_springs ? spring[k] : Vec3{}; // none without history
        e += contact_elastic_energy<N, T>(p, g, into_tangent_plane(stretch, g.normal));
        if (list.with_rolling) e += rolling_energy<N>(p, g, rolling[k]);
      };
    };
    for_each_contact3(scene, list, table, lever_shares(settings.lever_arm),
                      add(list.spring, list.rolling), add(list.plate_spring, list.plate_rolling));
    return e;
  });
}

std::string deepest_contact(const Scene3& scene, const SphereList& list,
                            const Settings3& settings) {
  const Spheres& s = scene.spheres;
  const PairTable table(scene.materials, settings.impact_speed, settings.linear_damping);
  double deepest = -1.0;
  std::ostringstream words;
  for_each_contact3(
      scene, list, table, lever_shares(settings.lever_arm),
      [&](std::uint32_t i, std::uint32_t, std::uint32_t j, const ContactGeometry3& g,
          const PairParameters&) {
        const double f = g.overlap / std::min(s.radius[i], s.radius[j]);
        if (f <= deepest) return;
        deepest = f;
        words.str("");
        words << "sphere " << s.id[i] << " overlaps sphere " << s.id[j] << " by " << f;
      },
      [&](std::uint32_t i, std::uint32_t, std::uint32_t w, const ContactGeometry3& g,
          const PairParameters&) {
        const double f = g.overlap / s.radius[i];
        if (f <= deepest) return;
        deepest = f;
        words.str("");
        words << "sphere " << s.id[i] << " overlaps plate " << w << " by " << f;
      });
  return words.str() + " of the smaller radius";
}

} // namespace talus
