#pragma once
// The keys that 2D and 3D scenarios share (of [simulation]: the clock, the laws, the seed, the
// skin, the renumbering; of [output]: the intervals), read and written for either section type: the
// 2D sections and the 3D ones name these fields alike.
#include <cstdint>
#include <limits>
#include <string>

#include <toml++/toml.h>

#include "integrate/integrator.hpp"
#include "scenario/file/toml_reader.hpp"
#include "talus/law_table.hpp"

namespace talus {

template <class S> void read_clock_and_laws(TableReader& r, S& s) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  s.duration = r.number("duration", s.duration, 0.0, inf, "> 0 s");
  if (s.duration <= 0.0) r.fail("duration", "must be > 0 s");
  // a number, or "auto" (the collision time / timestep_factor)
  if (r.has("timestep")) {
    if (r.is_number("timestep")) {
      s.timestep = r.optional_number("timestep", 0.0, inf, "> 0 s or \"auto\"");
      if (!(*s.timestep > 0.0)) r.fail("timestep", "must be > 0 s or \"auto\"");
    } else if (r.text("timestep", "auto") != "auto") {
      r.fail("timestep", "allowed: a number in s, or \"auto\"");
    }
  }
  s.timestep_factor = r.number("timestep_factor", s.timestep_factor, 1.0, 1e6, ">= 1");
  s.verlet_velocity =
      parse_verlet_velocity(r.choice("verlet_velocity", "predicted", {"predicted", "half_step"}));
  s.lever_arm = parse_lever_arm(
      r.choice("lever_arm", "contact_point", {"contact_point", "radius", "granular"}));
  s.normal_law = parse_normal_law(r.choice("normal_law", "linear", NormalLaws::names));
  const std::string damping = r.choice("linear_damping", "never_attractive", linear_damping_names);
  for (std::size_t k = 0; k < linear_damping_names.size(); ++k)
    if (damping == linear_damping_names[k]) s.linear_damping = static_cast<LinearDamping>(k);
  if (s.linear_damping != LinearDamping::never_attractive &&
      s.normal_law != law_id<LinearSpringDashpot>)
    r.fail("linear_damping", "applies to the linear normal law only (the Hertz law's dashpot never "
                             "pulls); allowed with normal_law = \"" +
                                 std::string(name_of(s.normal_law)) + "\": never_attractive");
  s.tangential_law =
      parse_tangential_law(r.choice("tangential_law", "cundall_strack", TangentialLaws::names));
  s.seed = static_cast<std::uint64_t>(r.integer("seed", static_cast<std::int64_t>(s.seed), 0,
                                                std::numeric_limits<std::int64_t>::max()));
  s.skin = r.number("skin", s.skin, 0.0, inf, ">= 0 m (0: automatic)");
  s.sort_every =
      static_cast<std::uint64_t>(r.integer("sort_every", static_cast<std::int64_t>(s.sort_every), 0,
                                           std::numeric_limits<std::int64_t>::max()));
  s.impact_speed = r.number("impact_speed", s.impact_speed, 1e-9, inf, "> 0 m/s");
}

/// The output intervals of [output] that 2D and 3D scenarios share (OutputSection and
/// Output3Section name them alike).
template <class O> void read_output_intervals(TableReader& r, O& o) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  o.thermo_interval = r.number("thermo_interval", o.thermo_interval, 1e-12, inf, "> 0 s");
  o.snapshot_interval =
      r.number("snapshot_interval", o.snapshot_interval, 0.0, inf, ">= 0 s (0: none)");
  o.checkpoint_interval = r.number("checkpoint_interval", o.checkpoint_interval, 0.0, inf,
                                   ">= 0 s (0: only at the end)");
}

template <class S> void write_clock_and_laws(toml::table& t, const S& s) {
  t.insert("duration", s.duration);
  if (s.timestep)
    t.insert("timestep", *s.timestep);
  else
    t.insert("timestep", "auto");
  t.insert("timestep_factor", s.timestep_factor);
  t.insert("verlet_velocity", std::string(to_string(s.verlet_velocity)));
  t.insert("lever_arm", std::string(to_string(s.lever_arm)));
  t.insert("normal_law", std::string(name_of(s.normal_law)));
  t.insert("linear_damping", std::string(to_string(s.linear_damping)));
  t.insert("tangential_law", std::string(name_of(s.tangential_law)));
  t.insert("seed", static_cast<std::int64_t>(s.seed));
  t.insert("skin", s.skin);
  t.insert("sort_every", static_cast<std::int64_t>(s.sort_every));
  t.insert("impact_speed", s.impact_speed);
}

} // namespace talus
