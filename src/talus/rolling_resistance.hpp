#pragma once
// Rolling resistance: a torque that opposes the relative rotation of two grains in contact, as
// the contact's finite width does for real grains, so that round grains can rest on a slope and
// a pile keeps an angle of repose. The law is the elastic-plastic spring-dashpot model (Ai, Chen,
// Rotter and Ooi, Powder Technology 206, 2011, model C; LIGGGHTS' `epsd`), for any number type
// (number.hpp). It is chosen by the materials: a pair whose mixed rolling_friction is 0 has none.
#include <string_view>

#include "talus/contact_geometry.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/number.hpp"
#include "talus/pair_parameters.hpp"
#include "talus/vector3.hpp"

namespace talus {

/// A grain's moment of inertia about a point of its rim, I + m R^2: what resists rolling on it.
inline double rim_inertia(double inertia, double mass, double radius) {
  return inertia + mass * radius * radius;
}
/// The rolling inertia of a pair, J_r = 1 / (1 / J_i + 1 / J_j) with J the rim inertias (Ai et
/// al. 2011, eq. 16); against a wall (rim_j = 0: infinitely heavy) it is J_i.
inline double rolling_inertia(double rim_i, double rim_j = 0.0) {
  return rim_j > 0.0 ? rim_i * rim_j / (rim_i + rim_j) : rim_i;
}

/// Ai et al. 2011, model C. With the relative spin w_r = w_i - w_j (the wall's rotation rate for
/// a wall), each step:
/// - the spring's moment M_k = -k_r theta grows by -k_r w_r dt, k_r = c k_n mu_r^2 R*^2 (c:
///   rolling_stiffness_factor, 2.25 in Ai et al.; k_n: the normal law's stiffness, the tangent
///   stiffness for Hertz);
/// - it is held within the full mobilisation moment mu_r R* F_n (then the grains roll on it at
///   that moment, which dissipates);
/// - a dashpot -eta_r 2 sqrt(J_r k_r) w_r acts while the spring holds, none once it is mobilised
///   (Ai et al.'s f = 0).
/// The torque on i is the sum, itself held within mu_r R* F_n (the dashpot's share is cut, as in
/// the tangential laws: Ai et al. let it pass the limit while the spring holds; the cap keeps the
/// torque a function of the state that an observer can take again after the step); j gets its
/// opposite. As for the tangential spring
/// (tangential_laws.hpp), a stiffness that grows keeps the moment and one that falls keeps the
/// angle, so that no step raises the spring's energy 1/2 k_r theta^2 beyond the work done on it.
/// The history `theta` (rad) is the spring's angle.
struct ElasticPlasticRolling {
  static constexpr std::string_view name = "epsd";
  /// k_r, N m/rad.
  template <class N, class P, class G> static auto stiffness(const P& p, const G& g) {
    return p.rolling_stiffness_factor * p.rolling_friction * p.rolling_friction * g.r_eff *
           g.r_eff * N::stiffness(p, g);
  }
  /// The torque on i (N m) of a contact whose normal force is `normal_force`, relative rolling
  /// spin `spin` (rad/s) and rolling inertia `inertia` (kg m^2); advances `theta` by dt. H: the
  /// spin's, the angle's and the torque's type: R in 2D (about z), a vector of R in 3D (in the
  /// tangent plane: contact_force.hpp's rolling_torque).
  template <class N, class P, class G, class R, class H>
  static H torque(const P& p, const G& g, R normal_force, H spin, R inertia, H& theta, double dt) {
    const R kr = stiffness<N>(p, g);
    const R limit = p.rolling_friction * g.r_eff * normal_force;
    H spring;
    if constexpr (N::stiffness_follows_overlap) {
      G before = g; // the overlap one step before, from its rate
      before.overlap = not_below_zero(g.overlap - g.overlap_rate() * dt);
      spring = -smaller(kr, stiffness<N>(p, before)) * theta - kr * (spin * dt);
    } else {
      spring = -kr * (theta + spin * dt);
    }
    // mobilised also within rounding of the limit: a spring held there and taken again from its
    // angle (theta = -M / k_r, then -k_r theta) comes back a rounding step short of it, and must
    // not then gain the dashpot that the step that held it left out
    const auto mobilised = magnitude(spring) >= (1.0 - 1e-12) * limit;
    // a spring of zero stays zero, also at a limit of zero (a contact whose normal force is cut
    // to zero): in 3D its direction, which copy_sign would take, is not defined
    spring = select(mobilised, select(magnitude(spring) > 0.0, copy_sign(limit, spring), spring),
                    spring);
    theta = select(kr > 0.0, -spring / kr, H{});
    const R dashpot = p.rolling_damping * 2.0 * square_root(inertia * kr);
    const H m = spring - select(mobilised, H{}, dashpot * spin);
    return select(magnitude(m) > limit, copy_sign(limit, m), m);
  }
  /// The spring's energy 1/2 k_r theta^2, J.
  template <class N>
  static double elastic_energy(const PairParameters& p, const ContactGeometry& g, double theta) {
    return 0.5 * stiffness<N>(p, g) * theta * theta;
  }
  /// The same in 3D, of the angle's vector.
  template <class N>
  static double elastic_energy(const PairParameters& p, const ContactGeometry3& g,
                               const Vec3& theta) {
    return 0.5 * stiffness<N>(p, g) * dot(theta, theta);
  }
};

/// The rolling part of two spheres' relative spin w_i - w_j (w_j = 0 for a wall) at a contact
/// of normal n: its part in the tangent plane. The part about n is twisting, which Ai et al.'s
/// model leaves out (as LIGGGHTS' epsd does); in a plane (spins along z, n in the plane) it is
/// the whole relative spin, as in 2D.
template <class R>
Vec3Of<R> rolling_spin(const Vec3Of<R>& w_i, const Vec3Of<R>& w_j, const Vec3Of<R>& n) {
  const Vec3Of<R> w = w_i - w_j;
  return w - dot(w, n) * n;
}

/// The rolling law of every engine.
using RollingLaw = ElasticPlasticRolling;

} // namespace talus
