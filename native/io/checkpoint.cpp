#include "io/checkpoint.hpp"

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <unistd.h>

#include "io/checkpoint_codec.hpp"

namespace talus {

using namespace checkpoint_codec;

namespace {

constexpr char magic[8] = {'T', 'A', 'L', 'U', 'S', 'C', 'K', 'P'};

// The structs with padding are stored member by member: a padding byte's value is unspecified,
// and written whole they would put it in the file (the same state, different files). Format 7
// stored them whole; a member added to one of them must be added here, in a new format version
// (SimulationConfig::linear_damping, of format 12, is written after the list).
template <either<Domain> D, class F> void for_each_member(D& d, F&& f) {
  f(d.lo), f(d.hi), f(d.periodic_x), f(d.periodic_y);
}
template <either<Segment> S, class F> void for_each_member(S& s, F&& f) {
  f(s.a), f(s.b), f(s.material), f(s.velocity), f(s.angular_velocity), f(s.pivot), f(s.force);
}
template <either<SimulationConfig> C, class F> void for_each_member(C& c, F&& f) {
  f(c.timestep), f(c.integrator), f(c.normal_law), f(c.tangential_law), f(c.verlet_velocity);
  f(c.skin), f(c.impact_speed), f(c.threads), f(c.min_particles_per_thread);
  f(c.max_overlap_fraction), f(c.escape_lo), f(c.escape_hi), f(c.sort_interval), f(c.lever_arm);
}
// (Domain's Lees-Edwards offset and velocity, of format 16, are written after the list too.)
static_assert(sizeof(Domain) == 56 && sizeof(Segment) == 96 && sizeof(SimulationConfig) == 104,
              "a member was added or changed: add it to the lists above and raise the version");

template <class T> void write_members(Writer& w, const T& v) {
  for_each_member(v, [&](const auto& m) {
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, bool>)
      w.pod<std::uint8_t>(m ? 1 : 0);
    else
      w.pod(m);
  });
}
template <class T> T read_members(Reader& r) {
  T v;
  for_each_member(v, [&](auto& m) { r.member(m); });
  return v;
}

// Format 7's whole struct, its periodic flags checked before it is copied out: a bool holding
// another byte than 0 or 1 is undefined behaviour to read.
struct Domain7 {
  Vec2 lo, hi;
  bool periodic_x, periodic_y;
};
Domain read_domain7(Reader& r) {
  const auto raw = r.pod<std::array<unsigned char, sizeof(Domain7)>>();
  for (const std::size_t at : {offsetof(Domain7, periodic_x), offsetof(Domain7, periodic_y)})
    if (raw[at] > 1) r.fail("a flag is neither 0 nor 1");
  Domain7 old;
  std::memcpy(&old, raw.data(), sizeof(Domain7));
  return Domain{
      .lo = old.lo, .hi = old.hi, .periodic_x = old.periodic_x, .periodic_y = old.periodic_y};
}

void write_particles(Writer& w, const Particles& p) {
  p.for_each_field([&](const auto& v) { w.vec(v); });
}

void read_particles(Reader& r, Particles& p, std::uint32_t version) {
  p.for_each_field([&](auto& v) {
    // the image counts came with format 10: before, no boundary had been counted
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::vector<Image>>)
      if (version < 10) return;
    r.vec(v);
  });
  if (version < 10) p.image.assign(p.position.size(), {});
  // every field read is checked: one of another length would be read out of its bounds later
  const std::size_t n = p.position.size();
  p.for_each_state_field([&](const auto& v) {
    if (v.size() != n) r.fail("particle arrays of different lengths");
  });
  // an integrator's history is empty (the other integrator's) or one entry per particle
  p.for_each_integrator_field([&](const auto& v) {
    if (!v.empty() && v.size() != n)
      r.fail("integrator arrays of another length than the particles'");
  });
  const GearDerivatives& g = p.gear;
  for (const std::size_t m :
       {g.r3.size(), g.r4.size(), g.phi2.size(), g.phi3.size(), g.phi4.size()})
    if (m != g.r2.size()) r.fail("Gear's derivatives of different lengths");
  if (p.force_previous.size() != p.torque_previous.size())
    r.fail("Verlet's previous force and torque of different lengths");
}

void write_driver(Writer& w, const Driver& d) {
  w.pod<std::uint32_t>(static_cast<std::uint32_t>(d.motion.index()));
  std::visit([&](const auto& m) { w.pod(m); }, d.motion);
  w.vec(d.targets.particles), w.vec(d.targets.segments);
  w.vec(d.particle_origin), w.vec(d.angle_origin), w.vec(d.segment_origin);
  w.pod(d.start_time);
}

// A servo as format 13 stored it, before its slide speed.
struct Servo13 {
  Vec2 direction;
  double force, stress, max_speed, relaxation, displacement, speed;
};
static_assert(sizeof(Servo) == sizeof(Servo13) + sizeof(double),
              "a member was added to Servo: read it in a new format version");

Servo read_servo(Reader& r, std::uint32_t version) {
  if (version >= 14) return r.pod<Servo>();
  const auto s = r.pod<Servo13>();
  return Servo{.direction = s.direction,
               .force = s.force,
               .stress = s.stress,
               .max_speed = s.max_speed,
               .relaxation = s.relaxation,
               .displacement = s.displacement,
               .speed = s.speed};
}

// A cell as format 15 stored it, before its shear.
struct Cell15 {
  Vec2 strain_rate;
  double pressure, max_strain_rate, relaxation, rate;
  Vec2 strain;
};
static_assert(sizeof(Cell) == sizeof(Cell15) + 2 * sizeof(double),
              "a member was added to Cell: read it in a new format version");

Cell read_cell(Reader& r, std::uint32_t version) {
  if (version >= 16) return r.pod<Cell>();
  const auto c = r.pod<Cell15>();
  return Cell{.strain_rate = c.strain_rate,
              .pressure = c.pressure,
              .max_strain_rate = c.max_strain_rate,
              .relaxation = c.relaxation,
              .rate = c.rate,
              .strain = c.strain};
}

// Format 9 added the driver's start time (a driver changed during a run); before, every driver
// started at 0.
Driver read_driver(Reader& r, std::uint32_t version) {
  Driver d;
  switch (r.pod<std::uint32_t>()) {
  case 0:
    d.motion = r.pod<Vibrate>();
    break;
  case 1:
    d.motion = r.pod<Translate>();
    break;
  case 2:
    d.motion = r.pod<Rotate>();
    break;
  case 3:
    d.motion = read_servo(r, version);
    break;
  case 4: // from format 15
    d.motion = read_cell(r, version);
    break;
  default:
    r.fail("unknown driver type");
  }
  r.vec(d.targets.particles), r.vec(d.targets.segments);
  r.vec(d.particle_origin), r.vec(d.angle_origin), r.vec(d.segment_origin);
  if (version >= 9) d.start_time = r.pod<double>();
  return d;
}

} // namespace

std::uint64_t fnv1a_hash(std::string_view bytes) {
  return fnv1a(bytes.data(), bytes.size());
}

std::string encode_checkpoint(const Checkpoint& c) {
  Writer w;
  const World& world = c.state.world;
  write_particles(w, world.particles);
  w.pod<std::uint64_t>(world.walls.size());
  for (const Segment& wall : world.walls) write_members(w, wall);
  w.pod<std::uint64_t>(world.materials.size());
  for (const Material& m : world.materials) write_material(w, m);
  write_members(w, world.domain);
  w.pod(world.gravity), w.pod(world.disk_thickness);
  w.pod<std::uint64_t>(world.drivers.size());
  for (const Driver& d : world.drivers) write_driver(w, d);
  const NeighbourList& l = c.state.neighbours;
  w.vec(l.row_offset), w.vec(l.neighbour), w.vec(l.image), w.vec(l.history);
  w.vec(l.wall_offset), w.vec(l.wall_segment);
  w.vec(l.wall_history), w.vec(l.reference), w.vec(l.segment_reference);
  w.vec(l.rolling), w.vec(l.wall_rolling);
  w.pod(l.skin), w.pod(l.builds);
  w.pod(c.state.time), w.pod(c.state.steps);
  write_members(w, c.config);
  w.pod(static_cast<std::uint8_t>(c.config.linear_damping));            // from format 12
  w.pod(c.state.clock_time), w.pod(c.state.clock_step);                 // from format 13
  w.pod(l.box);                                                         // from format 15
  w.pod(world.domain.shear_offset), w.pod(world.domain.shear_velocity); // from format 16
  w.pod(l.shear_offset);
  w.str(c.run_data);

  return seal_checkpoint(w.bytes());
}

std::string seal_checkpoint(const std::string& payload) {
  return seal(magic, checkpoint_version, payload);
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& source) {
  const Header h = read_header(bytes, magic, source, "talus checkpoint");
  const std::uint32_t version = h.version;
  if (version < oldest_readable_version || version > checkpoint_version)
    throw CheckpointError(source + ": checkpoint format version " + std::to_string(version) +
                          "; this talus reads versions " + std::to_string(oldest_readable_version) +
                          " to " + std::to_string(checkpoint_version));
  check_payload(bytes, h, source, version == 7 ? format7_offset_basis : fnv_offset_basis);

  Reader r(bytes, header_bytes, header_bytes + h.size, source);
  Checkpoint c;
  World& world = c.state.world;
  read_particles(r, world.particles, version);
  if (version == 7) {
    r.vec(world.walls);
  } else {
    world.walls.resize(r.count(sizeof(Vec2))); // each at least its first end
    for (Segment& wall : world.walls) wall = read_members<Segment>(r);
  }
  world.materials.resize(r.count(sizeof(std::uint64_t))); // each at least its name's length
  for (Material& m : world.materials) m = read_material(r, version);
  world.domain = version == 7 ? read_domain7(r) : read_members<Domain>(r);
  world.gravity = r.pod<Vec2>();
  world.disk_thickness = r.pod<double>();
  world.drivers.resize(r.count(sizeof(std::uint32_t))); // each at least its type
  for (Driver& d : world.drivers) d = read_driver(r, version);
  NeighbourList& l = c.state.neighbours;
  r.vec(l.row_offset), r.vec(l.neighbour), r.vec(l.image), r.vec(l.history);
  r.vec(l.wall_offset), r.vec(l.wall_segment);
  r.vec(l.wall_history), r.vec(l.reference), r.vec(l.segment_reference);
  if (version >= 11) r.vec(l.rolling), r.vec(l.wall_rolling);
  l.skin = r.pod<double>();
  l.builds = r.pod<std::uint64_t>();
  c.state.time = r.pod<double>();
  c.state.steps = r.pod<std::uint64_t>();
  c.config = version == 7 ? r.pod<SimulationConfig>() : read_members<SimulationConfig>(r);
  if (version >= 12) { // before, the linear law's dashpot never pulled
    const auto damping = r.pod<std::uint8_t>();
    if (damping >= linear_damping_names.size()) r.fail("unknown linear damping convention");
    c.config.linear_damping = static_cast<LinearDamping>(damping);
  } else {
    c.config.linear_damping = LinearDamping::never_attractive;
  }
  if (version >= 13) { // before, no run changed its timestep: the clock counted from 0
    c.state.clock_time = r.pod<double>();
    c.state.clock_step = r.pod<std::uint64_t>();
    if (c.state.clock_step > c.state.steps) r.fail("the timestep's clock starts after the state");
  }
  // before 15 no cell deformed: the box at the list's build is the box
  l.box = version >= 15 ? r.pod<Vec2>() : world.domain.size();
  if (version >= 16) { // before, no images slid (Lees-Edwards)
    world.domain.shear_offset = r.pod<double>();
    world.domain.shear_velocity = r.pod<double>();
    l.shear_offset = r.pod<double>();
  }
  c.run_data = r.str();
  if (!r.done()) r.fail("unexpected bytes at the end");
  return c;
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) {
    const int error = errno;
    throw WriteError("cannot write " + path + ": " + std::strerror(error), error);
  }
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      ::unlink(tmp.c_str());
      throw WriteError("cannot write " + path + ": " + std::strerror(error), error);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw WriteError("cannot write " + path + ": " + std::strerror(error), error);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw WriteError("cannot write " + path + ": " + std::strerror(error), error);
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace talus
