#include "io/thesis_format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "scenario/file/toml_reader.hpp"
#include "talus/closed_forms.hpp"
#include "talus/material_keys.hpp"

namespace talus {

namespace {
// The normal law of a thesis file's force law tag (line 2), from the laws' thesis_force_law.
std::optional<NormalLaw> law_of_thesis_tag(int tag) {
  for (std::size_t k = 0; k < NormalLaws::size; ++k) {
    const NormalLaw law{static_cast<std::uint8_t>(k)};
    if (with_normal_law(law, [&]<class N>() { return N::thesis_force_law == tag; })) return law;
  }
  return std::nullopt;
}
int thesis_tag_of(NormalLaw law) {
  return with_normal_law(law, []<class N>() { return N::thesis_force_law; });
}
// A particle's damping column: the linear law's gamma_n, or 1.5 A for Hertz. The thesis' A is
// one per particle: a damping derived from the restitution is written as the A of the particle
// against its own kind (m_eff = m/2, R* = R/2) at the impact speed.
double thesis_damping(const Material& m, bool hertz, double mass, double radius,
                      double impact_speed) {
  if (!hertz) return std::max(m.normal_damping_rate, 0.0);
  if (m.hertz_damping >= 0.0) return 1.5 * m.hertz_damping;
  return 1.5 * hertz_damping_for_restitution(m.restitution, 0.5 * mass,
                                             hertz_rho(effective_young(m, m), 0.5 * radius),
                                             impact_speed);
}
} // namespace

ThesisFile read_thesis_in(const std::string& text, const std::string& file, After after) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  const auto next = [&](const char* what) {
    while (std::getline(in, line)) {
      ++line_no;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return;
    }
    throw ScenarioError(file + ":" + std::to_string(line_no) + ": file ends before " + what);
  };
  const auto fail = [&](const std::string& what) {
    throw ScenarioError(file + ":" + std::to_string(line_no) + ": " + what);
  };
  ThesisFile f;
  f.file = file;
  long n = 0;
  next("the particle count (line 1)");
  std::string count, rest;
  std::istringstream(line) >> count >> rest;
  std::size_t used = 0;
  try {
    n = std::stol(count, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != count.size() || !rest.empty() || n < 1)
    fail("line 1 must be the number of particles N, a whole number >= 1 (it is '" + line + "')");
  next("the force law tag (line 2)");
  if (!(std::istringstream(line) >> f.force_law) || !law_of_thesis_tag(f.force_law))
    fail(
        "line 2 must be the force law tag; allowed: 0 (Hertzian viscoelastic), 1 (linear dashpot)");
  next("t_max (line 3)");
  if (!(std::istringstream(line) >> f.t_max) || !(f.t_max > 0)) fail("line 3 must be t_max > 0 s");
  next("dt (line 4)");
  if (!(std::istringstream(line) >> f.dt) || !(f.dt > 0))
    fail("line 4 must be the timestep dt > 0 s");
  next("the gravity vector (line 5)");
  if (!(std::istringstream(line) >> f.gravity[0] >> f.gravity[1] >> f.gravity[2]))
    fail("line 5 must be the gravity vector: three numbers x y z");
  if (f.gravity[2] != 0.0)
    fail(fmt::format("line 5: gravity z = {:g}: the disks move in the x-y plane, so a z "
                     "component would be dropped; allowed: z = 0 (turn the vector into the "
                     "plane)",
                     f.gravity[2]));
  static const char* columns[13] = {"x",      "y",    "angle", "vx",      "vy", "omega", "mass",
                                    "radius", "type", "mu",    "gamma_t", "Y",  "A"};
  for (long k = 0; k < n; ++k) {
    next("all N particle lines");
    std::istringstream row(line);
    double v[13];
    for (int c = 0; c < 13; ++c)
      if (!(row >> v[c]) || !std::isfinite(v[c]))
        fail("particle line: column " + std::to_string(c + 1) + " (" + columns[c] +
             ") is missing or not a number; a line has 13 columns: x y angle vx vy omega mass "
             "radius type mu gamma_t Y A");
    std::string extra;
    if (row >> extra)
      fail("particle line: more than 13 columns ('" + extra +
           "' after A); a line has 13 columns: x y angle vx vy omega mass radius type mu gamma_t "
           "Y A");
    if (v[6] <= 0 || v[7] <= 0) fail("particle line: mass and radius must be > 0");
    // check the range before converting: a double beyond int's range cannot be cast (found by
    // fuzz_thesis_in)
    if (!(v[8] == 0.0 || v[8] == 1.0 || v[8] == 2.0 || v[8] == 3.0))
      fail("particle line: column 9 (type) must be 0, 1, 2 or 3");
    const int type = static_cast<int>(v[8]);
    f.particles.push_back(
        {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], type, v[9], v[10], v[11], v[12], line_no});
  }
  // nothing but blank lines may follow the N particle lines: a surplus line means N is wrong
  while (after == After::nothing && std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      fail("a particle line beyond the N = " + std::to_string(n) +
           " of line 1; correct N, or remove the line");
  }
  return f;
}

std::string write_thesis_in(const ThesisFile& f) {
  std::string out =
      fmt::format("{}\n{}\n{:.9g}\n{:.9g}\n{:.9g} {:.9g} {:.9g}\n", f.particles.size(), f.force_law,
                  f.t_max, f.dt, f.gravity[0], f.gravity[1], f.gravity[2]);
  for (const ThesisParticle& p : f.particles)
    out += fmt::format("{:.12g} {:.12g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {} {:.9g} {:.9g} "
                       "{:.9g} {:.9g}\n",
                       p.x, p.y, p.angle, p.vx, p.vy, p.omega, p.mass, p.radius, p.type, p.mu,
                       p.gamma_t, p.young, p.damping);
  return out;
}

Scenario scenario_from_thesis(const ThesisFile& f, const std::string& name) {
  Scenario s;
  // the file's stem, as a scenario name may be (it names the run folder): other characters as _
  s.name = name.empty() ? "thesis" : name;
  for (char& c : s.name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  if (s.name == "." || s.name == "..") s.name = "thesis";
  s.description = "converted from the thesis' .in format";
  s.simulation.duration = f.t_max;
  s.simulation.timestep = f.dt;
  s.simulation.gravity = {f.gravity[0], f.gravity[1]};
  s.simulation.normal_law = *law_of_thesis_tag(f.force_law);
  s.simulation.tangential_law = law_id<ViscousCoulomb>;
  s.particles.shape = Shape::disk;
  s.output.picture = false;
  std::map<std::tuple<double, double, double, double>, std::string> materials;
  for (const ThesisParticle& p : f.particles) {
    const auto key = std::make_tuple(p.mu, p.gamma_t, p.young, p.damping);
    if (!materials.count(key)) {
      Material m;
      m.name = "thesis" + std::to_string(materials.size());
      m.friction = p.mu;
      m.tangential_damping = p.gamma_t / (0.5 * p.mass); // F_t = gamma_t v_t = (gamma_t/m*) m* v_t
      if (f.force_law == LinearSpringDashpot::thesis_force_law) {
        m.normal_stiffness = p.young;
        m.normal_damping_rate = p.damping;
      } else {
        m.young = 1.5 * p.young; // rho = 4/3 E* sqrt(R*) = Y sqrt(R*) with E* = E/2 (nu = 0)
        m.poisson = 0.0;
        m.hertz_damping = p.damping / 1.5;
        m.normal_stiffness = 1.0; // unused by the Hertz law
      }
      m.restitution = 1.0;
      // a value out of range is the particle line's, not the converted scenario's
      if (const std::string e = material_key_error(m); !e.empty())
        throw ScenarioError(fmt::format(
            "{}:{}: particle line: its mu, gamma_t, Y and A (columns 10 to 13) give a material "
            "whose {}",
            f.file.empty() ? std::string("thesis file") : f.file, p.line, e));
      s.materials.push_back(m);
      materials[key] = m.name;
    }
    ExplicitParticle e;
    e.position = {p.x, p.y};
    e.radius = p.radius;
    e.velocity = {p.vx, p.vy};
    e.angular_velocity = p.omega;
    e.mass = p.mass;
    e.kind = p.type == 0 ? "free" : "fixed";
    e.material = materials[key];
    s.particles.list.push_back(e);
  }
  return s;
}

ThesisFile thesis_from_scenario(const Scenario& s) {
  if (s.particles.count > 0)
    throw ScenarioError("convert: only scenarios whose particles are an explicit list "
                        "([[particles.list]]) can be written as .in; this one draws " +
                        std::to_string(s.particles.count) +
                        " grains (run it and convert the "
                        "run's particles instead)");
  ThesisFile f;
  f.force_law = thesis_tag_of(s.simulation.normal_law);
  f.t_max = s.simulation.duration;
  f.dt = s.simulation.timestep.value_or(1e-6);
  f.gravity[0] = s.simulation.gravity.x;
  f.gravity[1] = s.simulation.gravity.y;
  for (const ExplicitParticle& e : s.particles.list) {
    const Material* m = &s.materials.front();
    for (const Material& c : s.materials)
      if (c.name == e.material) m = &c;
    const double mass = e.mass > 0 ? e.mass : shape_mass(s.particles.shape, e.radius, m->density);
    const bool hertz = f.force_law == HertzViscoelastic::thesis_force_law;
    f.particles.push_back({e.position.x, e.position.y, 0.0, e.velocity.x, e.velocity.y,
                           e.angular_velocity, mass, e.radius, e.kind == "free" ? 0 : 1,
                           m->friction, m->tangential_damping * 0.5 * mass,
                           hertz ? m->young / 1.5 : m->normal_stiffness,
                           thesis_damping(*m, hertz, mass, e.radius, s.simulation.impact_speed)});
  }
  return f;
}

std::string thesis_out_header(const Simulation& sim, double t_max) {
  const auto& w = sim.world();
  return fmt::format("{}\n{}\n{:.9g}\n{:.9g}\n{:.9g} {:.9g} 0\n", w.particles.size(),
                     thesis_tag_of(sim.config().normal_law), t_max, sim.config().timestep,
                     w.gravity.x, w.gravity.y);
}

std::string thesis_out_block(const Simulation& sim) {
  const auto& w = sim.world();
  const Particles& p = w.particles;
  const bool hertz = sim.config().normal_law == law_id<HertzViscoelastic>;
  std::string out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Material& m = w.materials[p.material[i]];
    const int type = p.kind[i] == Kind::free ? 0 : (p.kind[i] == Kind::fixed ? 1 : 2);
    out += fmt::format("{:.12g} {:.12g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {} {:.9g} {:.9g} "
                       "{:.9g} {:.9g}\n",
                       p.position[i].x, p.position[i].y, p.angle[i], p.velocity[i].x,
                       p.velocity[i].y, p.angular_velocity[i], p.mass[i], p.radius[i], type,
                       m.friction, m.tangential_damping * 0.5 * p.mass[i],
                       hertz ? m.young / 1.5 : m.normal_stiffness,
                       thesis_damping(m, hertz, p.mass[i], p.radius[i], sim.config().impact_speed));
  }
  return out;
}

} // namespace talus
