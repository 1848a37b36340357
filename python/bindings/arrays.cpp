#include "arrays.hpp"

#include <cstring>

#include "analysis/observables.hpp"
#include "run/records.hpp"

namespace py = pybind11;

namespace talus::python {

namespace {

template <class T> py::array_t<T> column(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
  return a;
}

// A field of one value per element from `get`.
template <class T, class V, class F> py::array_t<T> column_of(const std::vector<V>& v, F get) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  auto out = a.template mutable_unchecked<1>();
  for (std::size_t k = 0; k < v.size(); ++k) out(static_cast<py::ssize_t>(k)) = get(v[k]);
  return a;
}

// (n, 2) rows of x and y from `get`.
template <class V, class F> py::array_t<double> pairs_of(const std::vector<V>& v, F get) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{2}});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 p = get(v[k]);
    out(static_cast<py::ssize_t>(k), 0) = p.x;
    out(static_cast<py::ssize_t>(k), 1) = p.y;
  }
  return a;
}

py::array_t<double> vectors(const std::vector<Vec2>& v) {
  return pairs_of(v, [](Vec2 p) { return p; });
}

py::tuple pair(Vec2 v) {
  return py::make_tuple(v.x, v.y);
}

} // namespace

namespace {

constexpr const char* particle_fields[] = {"position", "velocity", "force",  "image", "angle",
                                           "spin",     "torque",   "radius", "mass",  "inertia",
                                           "material", "kind",     "id"};

py::array images(const std::vector<Image>& v) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{2}});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < v.size(); ++k) {
    out(static_cast<py::ssize_t>(k), 0) = v[k].x;
    out(static_cast<py::ssize_t>(k), 1) = v[k].y;
  }
  return a;
}

} // namespace

py::array particle_field(const Simulation& sim, const std::string& name) {
  const Particles& p = sim.world().particles;
  if (name == "position") return vectors(p.position);
  if (name == "velocity") return vectors(p.velocity);
  if (name == "force") return vectors(p.force);
  if (name == "image") return images(p.image);
  if (name == "angle") return column(p.angle);
  if (name == "spin") return column(p.angular_velocity);
  if (name == "torque") return column(p.torque);
  if (name == "radius") return column(p.radius);
  if (name == "mass") return column(p.mass);
  if (name == "inertia") return column(p.inertia);
  if (name == "material") return column(p.material);
  if (name == "kind")
    return column_of<std::uint8_t>(p.kind, [](Kind k) { return static_cast<std::uint8_t>(k); });
  if (name == "id") return column(p.id);
  std::string names;
  for (const char* f : particle_fields) names += (names.empty() ? "" : ", ") + std::string(f);
  throw std::invalid_argument("no particle field '" + name + "'; allowed: " + names);
}

py::dict particle_arrays(const Simulation& sim) {
  py::dict d;
  for (const char* f : particle_fields) d[f] = particle_field(sim, f);
  return d;
}

py::dict wall_arrays(const Simulation& sim) {
  const Segments& w = sim.world().walls;
  py::dict d;
  d["a"] = pairs_of(w, [](const Segment& s) { return s.a; });
  d["b"] = pairs_of(w, [](const Segment& s) { return s.b; });
  d["velocity"] = pairs_of(w, [](const Segment& s) { return s.velocity; });
  d["force"] = pairs_of(w, [](const Segment& s) { return s.force; });
  d["angular_velocity"] = column_of<double>(w, [](const Segment& s) { return s.angular_velocity; });
  d["material"] = column_of<std::uint16_t>(w, [](const Segment& s) { return s.material; });
  return d;
}

py::dict contact_arrays(const Simulation& sim) {
  const std::vector<ContactRecord> c = contact_forces(sim);
  using R = ContactRecord;
  py::dict d;
  d["i"] = column_of<std::uint32_t>(c, [](const R& r) { return r.i; });
  d["j"] = column_of<std::int64_t>(c, [](const R& r) { return r.j < 0 ? std::int64_t{-1} : r.j; });
  d["wall"] = column_of<std::int64_t>(c, [](const R& r) { return r.j < 0 ? -1 - r.j : -1; });
  d["point"] = pairs_of(c, [](const R& r) { return r.point; });
  d["branch"] = pairs_of(c, [](const R& r) { return r.to - r.from; });
  d["force"] = pairs_of(c, [](const R& r) { return r.force; });
  d["overlap"] = column_of<double>(c, [](const R& r) { return r.overlap; });
  d["overlap_rate"] = column_of<double>(c, [](const R& r) { return r.overlap_rate; });
  d["normal_force"] = column_of<double>(c, [](const R& r) { return r.normal_force; });
  d["tangential_force"] = column_of<double>(c, [](const R& r) { return r.tangential_force; });
  return d;
}

py::dict measures(const Simulation& sim, const run::RunBook& book) {
  const Energies e = energies(sim);
  py::dict d;
  d["time"] = sim.time();
  d["step"] = sim.step_count();
  d["kinetic_translational"] = e.translational;
  d["kinetic_rotational"] = e.rotational;
  d["kinetic"] = e.kinetic();
  d["elastic"] = e.elastic;
  d["gravitational"] = e.gravitational;
  d["total_energy"] = e.total();
  d["momentum"] = pair(linear_momentum(sim));
  d["coordination"] = coordination_number(sim);
  d["contacts"] = contact_count(sim);
  py::dict forces;
  for (const auto& [name, g] : book.groups) forces[py::str(name)] = pair(run::group_force(sim, g));
  d["wall_forces"] = forces;
  return d;
}

py::dict group_arrays(const run::RunBook& book) {
  py::dict d;
  for (const auto& [name, g] : book.groups) {
    py::dict one;
    one["particles"] = column(g.particles);
    one["segments"] = column(g.segments);
    d[py::str(name)] = one;
  }
  return d;
}

} // namespace talus::python
