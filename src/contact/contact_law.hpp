#pragma once
// ContactLaw = a normal law + a tangential law, chosen per run. The pair is resolved to a
// concrete type once per step (with_contact_law), so the per-contact code has no virtual call.
#include <string_view>

#include "contact/geometry.hpp"
#include "contact/normal_laws.hpp"
#include "contact/tangential_laws.hpp"

namespace talus {

enum class NormalLaw { linear, hertz };
enum class TangentialLaw { coulomb, cundall_strack, mindlin };

std::string_view to_string(NormalLaw law);
std::string_view to_string(TangentialLaw law);
/// Parses "linear" / "hertz"; throws InvalidArgument listing the allowed names otherwise.
NormalLaw parse_normal_law(std::string_view name);
/// Parses "coulomb" / "cundall_strack" / "mindlin".
TangentialLaw parse_tangential_law(std::string_view name);

/// Force and torques of one contact for the law pair (N, T). `history` is the tangential spring.
template <class N, class T>
inline ContactForce contact_force(const PairParameters& p, const ContactGeometry& g,
                                  double& history, double dt) {
  ContactForce c;
  c.normal_force = N::force(p, g);
  const double kn = N::stiffness(p, g);
  const double ft = T::force(p, g, c.normal_force, kn, history, dt);
  c.force = c.normal_force * g.normal + ft * g.tangent();
  c.torque_i = -g.arm_i * ft;
  c.torque_j = -g.arm_j * ft;
  return c;
}

/// Elastic energy stored in one contact: normal part plus 1/2 k_t s^2 for the spring laws.
template <class N, class T>
inline double contact_elastic_energy(const PairParameters& p, const ContactGeometry& g,
                                     double history) {
  double e = N::elastic_energy(p, g);
  if constexpr (T::has_history) {
    const double kt = T::stiffness(p, g, N::stiffness(p, g));
    e += 0.5 * kt * history * history;
  }
  return e;
}

/// Calls f.template operator()<N, T>() with the concrete law types.
template <class F> decltype(auto) with_contact_law(NormalLaw n, TangentialLaw t, F&& f) {
  const auto with_t = [&]<class N>() -> decltype(auto) {
    switch (t) {
    case TangentialLaw::coulomb:
      return f.template operator()<N, ViscousCoulomb>();
    case TangentialLaw::cundall_strack:
      return f.template operator()<N, CundallStrack>();
    case TangentialLaw::mindlin:
      break;
    }
    return f.template operator()<N, MindlinNoSlip>();
  };
  if (n == NormalLaw::linear) return with_t.template operator()<LinearSpringDashpot>();
  return with_t.template operator()<HertzViscoelastic>();
}

} // namespace talus
