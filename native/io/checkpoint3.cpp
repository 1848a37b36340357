#include "io/checkpoint3.hpp"

#include <cstring>

#include "io/checkpoint_codec.hpp"

namespace talus {

using namespace checkpoint_codec;

namespace {

constexpr char magic3[8] = {'T', 'A', 'L', 'U', 'S', '3', 'C', 'K'};

template <class L, class F> void list_fields(L& l, F&& f) {
  f(l.row_offset), f(l.neighbour), f(l.shift), f(l.spring), f(l.second_offset);
  f(l.second_entry), f(l.plate_offset), f(l.plate), f(l.plate_spring), f(l.reference);
  f(l.plate_reference);
}
template <class P, class F> void plate_fields(P& p, F&& f) {
  f(p.centre, p.normal, p.axis_u, p.half_u, p.half_v, p.material, p.velocity, p.angular_velocity,
    p.pivot, p.force);
}
template <class D, class F> void driver_fields(D& d, F&& f) {
  f(d.plate, d.motion, d.velocity, d.direction, d.amplitude, d.frequency, d.phase, d.pivot,
    d.angular_velocity);
}
// Version 4's: the servos, with their controllers' state.
template <class S, class F> void servo_fields(S& s, F&& f) {
  f(s.plate, s.direction, s.force, s.max_speed, s.relaxation, s.displacement, s.speed);
}
// Version 5's: the deforming cell with its state, the Lees-Edwards images and the box and offset
// of the list's build (its drift test's reserve for the cell).
template <class C, class F> void cell_fields(C& c, F&& f) {
  f(c.strain_rate, c.pressure, c.max_strain_rate, c.relaxation, c.rate, c.strain, c.shear_rate,
    c.shear_strain);
}
template <class D, class L, class F> void shear_fields(D& d, L& l, F&& f) {
  f(d.shear_offset, d.shear_velocity, l.box, l.shear_offset);
}
template <class C, class F> void settings_fields(C& c, F&& f) {
  f(c.timestep, c.normal_law, c.tangential_law, c.verlet_velocity, c.skin, c.impact_speed,
    c.lever_arm, c.linear_damping, c.max_overlap_fraction, c.threads);
}
// Version 2's: the integrator and Gear's derivatives (a version 1 run was velocity Verlet).
template <class G, class F> void gear_fields(G& g, F&& f) {
  f(g.r2), f(g.r3), f(g.r4), f(g.w2), f(g.w3), f(g.w4);
}

// The rolling springs, which version 2 added (a version 1 file has none: its run could not
// roll with resistance). Version 2 added Gear too (gear_fields).
template <class L, class F> void rolling_fields(L& l, F&& f) {
  f(l.rolling), f(l.plate_rolling);
}

void write_state(Writer& w, const SimulationState3& st) {
  const Scene3& sc = st.scene;
  sphere_fields(sc.spheres, [&](const auto& v) { w.vec(v); });
  w.pod<std::uint64_t>(sc.plates.size());
  for (const Plane& p : sc.plates)
    plate_fields(p, [&](const auto&... v) { write_fields(w, v...); });
  w.pod<std::uint64_t>(sc.drivers.size());
  for (const PlateDriver& d : sc.drivers)
    driver_fields(d, [&](const auto&... v) { write_fields(w, v...); });
  const Domain3& d = sc.domain;
  write_fields(w, d.lo, d.hi, d.periodic[0], d.periodic[1], d.periodic[2]);
  w.pod<std::uint64_t>(sc.materials.size());
  for (const Material& m : sc.materials) write_material(w, m);
  w.pod(sc.gravity);
  list_fields(st.list, [&](const auto& v) { w.vec(v); });
  write_fields(w, st.list.with_rolling);
  rolling_fields(st.list, [&](const auto& v) { w.vec(v); });
  write_fields(w, st.list.skin, st.list.builds);
  w.vec(st.start);
  gear_fields(st.gear, [&](const auto& v) { w.vec(v); });
  write_fields(w, st.last.contacts, st.last.on_plates, st.last.deepest, st.time, st.steps);
  w.pod<std::uint64_t>(sc.servos.size());
  for (const PlateServo& servo : sc.servos)
    servo_fields(servo, [&](const auto&... v) { write_fields(w, v...); });
  write_fields(w, sc.cell.has_value());
  if (sc.cell) cell_fields(*sc.cell, [&](const auto&... v) { write_fields(w, v...); });
  shear_fields(sc.domain, st.list, [&](const auto&... v) { write_fields(w, v...); });
}

// Every array read is checked against the others, and every index against what it points
// into: a damaged file is refused, never read out of bounds later.
void check_state(Reader& r, const SimulationState3& st) {
  const Spheres& s = st.scene.spheres;
  const std::size_t n = s.size();
  sphere_fields(s, [&](const auto& v) {
    if (v.size() != n) r.fail("sphere arrays of different lengths");
  });
  for (const Kind k : s.kind)
    if (static_cast<std::uint8_t>(k) > 1) r.fail("a sphere's kind is neither free nor fixed");
  const SphereList& l = st.list;
  const auto csr = [&](const std::vector<std::uint32_t>& offset, std::size_t entries) {
    if (offset.size() != n + 1 || offset.front() != 0 || offset.back() != entries)
      r.fail("a list's rows do not add up");
    for (std::size_t k = 0; k < n; ++k)
      if (offset[k] > offset[k + 1]) r.fail("a list's rows run backwards");
  };
  csr(l.row_offset, l.neighbour.size());
  csr(l.second_offset, l.second_entry.size());
  csr(l.plate_offset, l.plate.size());
  if (l.shift.size() != l.neighbour.size() || l.second_entry.size() != l.neighbour.size())
    r.fail("a list's arrays of different lengths");
  // a list whose law keeps no history keeps no springs (Simulation3 sets which, from the law)
  const bool springs =
                 l.spring.size() == l.neighbour.size() && l.plate_spring.size() == l.plate.size(),
             none = l.spring.empty() && l.plate_spring.empty();
  if (!springs && !none) r.fail("a list's springs are not one per entry");
  const std::size_t rolling = l.with_rolling ? l.neighbour.size() : 0,
                    plate_rolling = l.with_rolling ? l.plate.size() : 0;
  if (l.rolling.size() != rolling || l.plate_rolling.size() != plate_rolling)
    r.fail("a list's rolling springs are not one per entry");
  for (const std::uint32_t j : l.neighbour)
    if (j >= n) r.fail("a list entry names a sphere that does not exist");
  for (const std::uint32_t e : l.second_entry)
    if (e >= l.neighbour.size()) r.fail("a list entry's index is out of range");
  for (const std::uint32_t w : l.plate)
    if (w >= st.scene.plates.size()) r.fail("a list entry names a plate that does not exist");
  for (const PlateServo& servo : st.scene.servos)
    if (servo.plate >= st.scene.plates.size()) r.fail("a servo names a plate that does not exist");
  gear_fields(st.gear, [&](const auto& v) {
    if (v.size() != 0 && v.size() != n) r.fail("Gear's derivatives are not one per sphere");
  });
  if (l.reference.size() != n || l.plate_reference.size() != st.scene.plates.size() ||
      st.start.size() != st.scene.plates.size())
    r.fail("the list's build positions are not one per sphere and plate");
}

SimulationState3 read_state(Reader& r, std::uint32_t version) {
  SimulationState3 st;
  Scene3& sc = st.scene;
  sphere_fields(sc.spheres, [&](auto& v) { r.vec(v); });
  sc.plates.resize(r.count(sizeof(Vec3)));
  for (Plane& p : sc.plates) plate_fields(p, [&](auto&... v) { read_fields(r, v...); });
  sc.drivers.resize(r.count(sizeof(std::uint32_t)));
  for (PlateDriver& d : sc.drivers) driver_fields(d, [&](auto&... v) { read_fields(r, v...); });
  Domain3& d = sc.domain;
  read_fields(r, d.lo, d.hi, d.periodic[0], d.periodic[1], d.periodic[2]);
  sc.materials.resize(r.count(sizeof(std::uint64_t)));
  for (Material& m : sc.materials) m = read_material(r, checkpoint_version);
  sc.gravity = r.pod<Vec3>();
  list_fields(st.list, [&](auto& v) { r.vec(v); });
  if (version >= 2) {
    read_fields(r, st.list.with_rolling);
    rolling_fields(st.list, [&](auto& v) { r.vec(v); });
  }
  read_fields(r, st.list.skin, st.list.builds);
  r.vec(st.start);
  if (version >= 2) gear_fields(st.gear, [&](auto& v) { r.vec(v); });
  read_fields(r, st.last.contacts, st.last.on_plates, st.last.deepest, st.time, st.steps);
  if (version >= 4) { // an older run had no servo
    sc.servos.resize(r.count(sizeof(std::uint32_t)));
    for (PlateServo& servo : sc.servos)
      servo_fields(servo, [&](auto&... v) { read_fields(r, v...); });
  }
  if (version >= 5) { // an older run had no cell: its list's box is the domain's
    bool cell = false;
    read_fields(r, cell);
    if (cell) cell_fields(sc.cell.emplace(), [&](auto&... v) { read_fields(r, v...); });
    shear_fields(sc.domain, st.list, [&](auto&... v) { read_fields(r, v...); });
  } else {
    st.list.box = sc.domain.size();
  }
  check_state(r, st);
  return st;
}

} // namespace

std::string encode_checkpoint3(const Checkpoint3& c) {
  Writer w;
  write_state(w, c.state);
  settings_fields(c.settings, [&](const auto&... v) { write_fields(w, v...); });
  write_fields(w, c.settings.integrator, c.settings.sort_interval);
  w.str(c.run_data);
  return seal(magic3, checkpoint3_version, w.bytes());
}

Checkpoint3 decode_checkpoint3(const std::string& bytes, const std::string& source) {
  const Header h = read_header(bytes, magic3, source, "talus 3D checkpoint");
  if (h.version < 1 || h.version > checkpoint3_version)
    throw CheckpointError(source + ": 3D checkpoint format version " + std::to_string(h.version) +
                          "; this talus reads versions 1 to " +
                          std::to_string(checkpoint3_version));
  check_payload(bytes, h, source);
  Reader r(bytes, header_bytes, header_bytes + h.size, source);
  Checkpoint3 c;
  c.state = read_state(r, h.version);
  settings_fields(c.settings, [&](auto&... v) { read_fields(r, v...); });
  if (h.version >= 2) read_fields(r, c.settings.integrator);
  // a version 2 run never renumbered its spheres: it goes on without
  if (h.version >= 3) read_fields(r, c.settings.sort_interval);
  if (c.settings.integrator != Integrator::gear && c.settings.integrator != Integrator::verlet)
    r.fail("an integrator that is neither Gear nor velocity Verlet");
  c.run_data = r.str();
  if (!r.done()) r.fail("bytes left after the last field");
  return c;
}

} // namespace talus
