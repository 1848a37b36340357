#include "contact/contact_law.hpp"

#include <string>

#include "core/error.hpp"

namespace talus {

std::string_view to_string(NormalLaw law) {
  return law == NormalLaw::linear ? "linear" : "hertz";
}

std::string_view to_string(TangentialLaw law) {
  switch (law) {
  case TangentialLaw::coulomb:
    return "coulomb";
  case TangentialLaw::cundall_strack:
    return "cundall_strack";
  case TangentialLaw::mindlin:
    return "mindlin";
  }
  return "?";
}

NormalLaw parse_normal_law(std::string_view name) {
  if (name == "linear") return NormalLaw::linear;
  if (name == "hertz") return NormalLaw::hertz;
  throw InvalidArgument("unknown normal law '" + std::string(name) + "'; allowed: linear, hertz");
}

TangentialLaw parse_tangential_law(std::string_view name) {
  if (name == "coulomb") return TangentialLaw::coulomb;
  if (name == "cundall_strack") return TangentialLaw::cundall_strack;
  if (name == "mindlin") return TangentialLaw::mindlin;
  throw InvalidArgument("unknown tangential law '" + std::string(name) +
                        "'; allowed: coulomb, cundall_strack, mindlin");
}

} // namespace talus
