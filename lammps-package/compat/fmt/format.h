#pragma once
// Debian's liblammps-dev headers include "fmt/format.h", the fmt 7 that is built into liblammps
// (in namespace fmt::v7_lmp) and that Debian does not ship; Debian's libfmt-dev 9 lacks what those
// headers name (make_args_checked). This header declares just the names the LAMMPS headers
// mention, so that they parse. The package never instantiates LAMMPS' formatting templates: it
// hands Error and utils whole std::string messages (host_api.hpp), so nothing declared here is
// called or linked.
#include <string_view>

namespace fmt {
using string_view = std::string_view;
struct format_args {};
template <class... Args, class S, class... Given>
format_args make_args_checked(const S& format, const Given&... args);
} // namespace fmt
