#include "run/records.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <utility>

#include <fmt/core.h>
#include <sys/resource.h>

#include "analysis/energy_ledger.hpp"
#include "analysis/rattlers.hpp"
#include "analysis/stress.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "io/vtk.hpp"
#include "scenario/build_checks.hpp"
#include "scenario/file/load.hpp"

namespace fs = std::filesystem;

namespace talus::run {

namespace {

// The packing region's top corner: the fill region's, or below a pressing lid (the grain
// press' "lid" group), so the packing fraction is of the packing, not of the empty box above.
Vec2 packing_top(const Simulation& sim, const RunBook& book) {
  Vec2 hi = book.fill.hi;
  if (const auto lid = book.groups.find("lid"); lid != book.groups.end())
    for (const auto s : lid->second.segments) {
      const Segment& w = sim.world().walls[s];
      hi.y = std::min({hi.y, w.a.y, w.b.y});
    }
  return hi;
}

// The packing fraction of the container: in the drum, of the whole drum (how full it is; the
// fill region is a square inside it); elsewhere of the fill region, up to a lid.
double packing(const Simulation& sim, const Scenario& s, const RunBook& book) {
  const Domain& box = sim.world().domain;
  if (sim.cell_driver() != nullptr) return packing_fraction(sim, box.lo, box.hi); // as it is now
  if (s.geometry.builder == "drum") {
    const double r = s.geometry.radius;
    return disc_area_fraction(sim, Vec2{r, r}, r);
  }
  return packing_fraction(sim, book.fill.lo, packing_top(sim, book));
}

} // namespace

Rect stress_region(const Simulation& sim, const Scenario& s, const RunBook& book) {
  if (s.output.stress_region) return *s.output.stress_region;
  if (sim.cell_driver() != nullptr) return {sim.world().domain.lo, sim.world().domain.hi};
  return book.bounds;
}

namespace {

// One region's stress and structure columns (analysis/stress.hpp, analysis/rattlers.hpp).
std::string region_columns(const Simulation& sim, const Rect& region) {
  const RegionStress s = region_stress(sim, region.lo, region.hi);
  const Tensor2 total = s.total();
  const Principal p = principal(total);
  const LoadBearing network = load_bearing(sim, region.lo, region.hi, contacts_needed(sim));
  return fmt::format(
      ",{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6f},"
      "{:.6f},{:.6f},{:.6f},{:.9f},{:.6f},{:.6f}",
      s.contact(0, 0), s.contact(0, 1), s.contact(1, 0), s.contact(1, 1), s.kinetic(0, 0),
      s.kinetic(0, 1), s.kinetic(1, 1), 0.5 * total.trace(), p.major, p.minor,
      p.angle * 180.0 / std::numbers::pi, s.fabric(0, 0), s.fabric(0, 1), s.fabric(1, 1),
      packing_fraction(sim, region.lo, region.hi), network.coordination,
      network.grains > 0
          ? static_cast<double>(network.rattlers) / static_cast<double>(network.grains)
          : 0.0);
}

// One region's stress column names, each with `prefix`.
std::string region_header(const std::string& prefix) {
  std::string head;
  for (const char* name :
       {"stress_xx", "stress_xy", "stress_yx", "stress_yy", "kinetic_stress_xx",
        "kinetic_stress_xy", "kinetic_stress_yy", "pressure", "stress_major", "stress_minor",
        "stress_major_angle", "fabric_xx", "fabric_xy", "fabric_yy", "region_packing_fraction",
        "load_bearing_coordination", "rattler_fraction"})
    head += "," + prefix + name;
  return head;
}

} // namespace

std::string stress_columns(const Simulation& sim, const Rect& region, const OutputSection& output) {
  std::string out = region_columns(sim, region);
  for (const StressRegion& r : output.stress_regions) out += region_columns(sim, r.region);
  return out;
}

std::string thermo_header(const RunBook& book, bool ledger, const OutputSection& output) {
  std::string head = "time,step,kinetic_translational,kinetic_rotational,elastic,gravitational,"
                     "total,momentum_x,momentum_y,angular_momentum,coordination,contacts,"
                     "packing_fraction";
  if (ledger) head += ledger_thermo_header;
  if (output.stress) head += region_header("");
  for (const StressRegion& r : output.stress_regions) head += region_header(r.name + "_");
  for (const std::string& name : book.force_columns)
    head += ",force_" + name + "_x,force_" + name + "_y";
  return head + "\n";
}

std::string thermo_columns(const Simulation& sim, const Scenario& s, const RunBook& book,
                           const Energies& e) {
  const Vec2 p = linear_momentum(sim);
  return fmt::format(
      "{:.9g},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6f},{},{:.6f}",
      sim.time(), sim.step_count(), e.translational, e.rotational, e.elastic, e.gravitational,
      e.total(), p.x, p.y, angular_momentum(sim), coordination_number(sim), contact_count(sim),
      packing(sim, s, book));
}

std::string cell_header() {
  return ",cell_x,cell_y,cell_strain_rate_x,cell_strain_rate_y,cell_shear_rate,cell_shear_strain";
}

std::string cell_columns(const Simulation& sim) {
  const Cell* c = sim.cell_driver();
  if (c == nullptr) return "";
  const Domain& d = sim.world().domain;
  const Vec2 size = d.size(), rate = cell_strain_rate(*c, d);
  return fmt::format(",{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{:.9e}", size.x, size.y, rate.x, rate.y,
                     c->shear_rate, c->shear_strain);
}

Vec2 group_force(const Simulation& sim, const DriverTargets& g) {
  Vec2 f = force_on_particles(sim, g.particles);
  for (const auto sidx : g.segments) f += sim.world().walls[sidx].force;
  return f;
}

double group_height(const Simulation& sim, const DriverTargets& g) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto i : g.particles) sum += sim.world().particles.position[i].y, ++n;
  for (const auto sidx : g.segments) {
    const Segment& w = sim.world().walls[sidx];
    sum += w.a.y + w.b.y, n += 2;
  }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

std::string group_force_columns(const Simulation& sim, const RunBook& book) {
  std::string out;
  for (const std::string& name : book.force_columns) {
    const auto g = book.groups.find(name);
    const Vec2 f = g == book.groups.end() ? Vec2{} : group_force(sim, g->second);
    out += fmt::format(",{:.9e},{:.9e}", f.x, f.y);
  }
  return out;
}

std::string track_rows(const Simulation& sim, const std::vector<std::uint32_t>& tracked) {
  const Particles& p = sim.world().particles;
  const Domain& domain = sim.world().domain;
  std::string out;
  for (const auto i : tracked) {
    // every number as the shortest text that reads back to the engine's double: the tracks
    // compare with another engine's to rounding
    const Vec2 u = domain.unwrapped(p.position[i], p.image[i]);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", sim.time(), p.id[i], p.position[i].x,
                       p.position[i].y, p.angle[i], p.velocity[i].x, p.velocity[i].y,
                       p.angular_velocity[i], u.x, u.y);
  }
  return out;
}

namespace {

// Snapshot n's file of one kind ("particles", "walls", "contacts") in the snapshots folder: the
// name the writer, the collections and the resume's check all use.
std::string snapshot_name(const char* kind, std::uint64_t n, const char* ext = "vtp") {
  return fmt::format("{}_{:06d}.{}", kind, n, ext);
}

} // namespace

void write_snapshot_files(const fs::path& dir, const Simulation& sim, std::uint64_t n,
                          bool with_contacts_csv, bool with_stress) {
  const fs::path snapshots = dir / "snapshots";
  write_file_atomically((snapshots / snapshot_name("particles", n)).string(),
                        vtp_particles(sim, with_stress));
  if (!sim.world().walls.empty())
    write_file_atomically((snapshots / snapshot_name("walls", n)).string(), vtp_walls(sim));
  write_file_atomically((snapshots / snapshot_name("contacts", n)).string(), vtp_contacts(sim));
  if (with_contacts_csv)
    write_file_atomically((snapshots / snapshot_name("contacts", n, "csv")).string(),
                          contacts_csv(sim));
}

void write_collections_of(const fs::path& dir, const std::vector<double>& times, bool walls) {
  std::vector<std::pair<double, std::string>> particles, wall_files, contacts;
  for (std::uint64_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    particles.emplace_back(t, fmt::format("snapshots/{}", snapshot_name("particles", k)));
    wall_files.emplace_back(t, fmt::format("snapshots/{}", snapshot_name("walls", k)));
    contacts.emplace_back(t, fmt::format("snapshots/{}", snapshot_name("contacts", k)));
  }
  write_file_atomically((dir / "particles.pvd").string(), pvd_collection(particles));
  if (walls) write_file_atomically((dir / "walls.pvd").string(), pvd_collection(wall_files));
  write_file_atomically((dir / "contacts.pvd").string(), pvd_collection(contacts));
}

namespace {

// This process's peak resident memory so far.
std::uint64_t peak_memory_bytes() {
  rusage usage{};
  if (::getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024; // Linux gives kilobytes
}

} // namespace

std::string run_json(const Scenario& s, const Simulation& sim, const RunBook& book, double wall,
                     double session_wall, std::uint64_t steps_done, const std::string& ended) {
  const std::size_t n = sim.world().particles.size();
  const double rate = session_wall > 0
                          ? static_cast<double>(steps_done) * static_cast<double>(n) / session_wall
                          : 0.0;
  return fmt::format(
      "{{\n  \"talus_version\": \"{}\",\n  \"scenario\": \"{}\",\n  \"seed\": {},\n"
      "  \"particles\": {},\n  \"steps\": {},\n  \"time\": {:.9g},\n  \"timestep\": {:.9g},\n"
      "  \"collision_time\": {:.9g},\n  \"integrator\": \"{}\",\n  \"threads\": {},\n"
      "  \"threads_asked\": {},\n  \"step\": \"{}\",\n"
      "  \"settle_time\": {:.6g},\n  \"wall_seconds\": {:.6f},\n"
      "  \"particle_steps_per_second\": {:.6g},\n  \"memory_estimate_bytes\": {:.0f},\n"
      "  \"peak_memory_bytes\": {},\n  \"freezes\": {},\n  \"ended_by\": \"{}\"\n}}\n",
      TALUS_VERSION, s.name, s.simulation.seed, n, sim.step_count(), sim.time(),
      sim.config().timestep, book.collision_time, to_string(sim.config().integrator), sim.threads(),
      sim.config().threads, sim.step_description(), book.settle_time, wall, rate,
      memory_estimate(n), peak_memory_bytes(), book.freezes, ended);
}

std::string outputs_short_of(const fs::path& dir,
                             const std::map<std::string, std::uint64_t>& file_bytes,
                             std::uint64_t snapshots) {
  for (const auto& [name, bytes] : file_bytes) {
    std::error_code e;
    const std::uint64_t size = fs::file_size(dir / name, e);
    if (e) return fmt::format("{} is missing; it held {} bytes", (dir / name).string(), bytes);
    if (size < bytes)
      return fmt::format("{} holds {} bytes, fewer than the {} it held then (its tail was lost)",
                         (dir / name).string(), size, bytes);
  }
  for (std::uint64_t k = 0; k < snapshots; ++k) {
    const fs::path f = dir / "snapshots" / snapshot_name("particles", k);
    if (!fs::exists(f)) return f.string() + " is missing";
  }
  return {};
}

void cut_back_outputs(const fs::path& dir, const std::map<std::string, std::uint64_t>& file_bytes,
                      std::uint64_t snapshots, std::error_code& ec) {
  const auto keep = [&](std::error_code e) {
    if (e && !ec) ec = e;
  };
  for (const auto& [name, bytes] : file_bytes) {
    std::error_code e;
    if (fs::exists(dir / name, e)) fs::resize_file(dir / name, bytes, e);
    keep(e);
  }
  std::error_code e;
  for (const auto& entry : fs::directory_iterator(dir / "snapshots", e)) {
    unsigned long k = 0;
    const std::string f = entry.path().filename().string();
    std::error_code r;
    if (std::sscanf(f.c_str(), "%*[a-z]_%lu", &k) == 1 && k >= snapshots)
      fs::remove(entry.path(), r);
    keep(r);
  }
  keep(e);
}

} // namespace talus::run
