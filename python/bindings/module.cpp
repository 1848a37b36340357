// talus._talus: the native engine's run layer for Python (the talus package wraps it; see
// docs/python.md). Errors carry the scenario's key and the allowed values, as on the command line.
#include <Python.h>

#include <array>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.hpp"
#include "cli/analyze/analyses.hpp"
#include "cli/builtin_scenarios.hpp"
#include "cli/run/scenario_source.hpp"
#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/stages.hpp"
#include "session.hpp"
#include "talus/error.hpp"

namespace py = pybind11;
using talus::python::Session;

namespace {

// A Ctrl-C in Python, seen between stretches of steps: the run checkpoints and stops, and the
// KeyboardInterrupt it leaves pending is raised when go returns.
bool python_signal() {
  py::gil_scoped_acquire gil;
  return PyErr_CheckSignals() != 0;
}

const char* outcome_name(talus::run::RunOutcome r) {
  switch (r) {
  case talus::run::RunOutcome::completed:
    return "completed";
  case talus::run::RunOutcome::stopped_at:
    return "stopped";
  case talus::run::RunOutcome::interrupted:
    return "interrupted";
  case talus::run::RunOutcome::paused:
    break;
  }
  return "paused";
}

py::dict analyze(const std::string& dir, const std::string& what, const std::string& frames,
                 double from, std::size_t bins, double cell, const std::string& axis,
                 const std::string& kernel, double width, bool map) {
  talus::cli::check_analysis_name(what);
  talus::cli::AnalysisOptions o;
  o.frames = frames;
  o.from = from;
  o.bins = bins;
  o.cell = cell;
  o.axis = axis;
  o.kernel = kernel;
  o.width = width;
  o.map = map;
  talus::cli::RunData run{std::filesystem::path(dir)};
  const talus::cli::Section s = talus::cli::analyze_one(run, what, o);
  py::dict d;
  d["title"] = s.title;
  d["summary"] = s.summary;
  d["numbers"] = s.numbers;
  d["charts"] = s.charts;
  d["folder"] = run.out();
  return d;
}

void bind_session(py::module_& m) {
  py::class_<Session>(m, "Session")
      .def(py::init([](const talus::Scenario& s, const std::string& dir, int threads, bool quiet) {
             return std::make_unique<Session>(s, dir, threads, quiet, python_signal);
           }),
           py::arg("scenario"), py::arg("folder"), py::arg("threads"), py::arg("quiet"))
      .def_static(
          "resume",
          [](const std::string& dir, int threads, bool quiet) {
            return Session::resume(dir, threads, quiet, python_signal);
          },
          py::arg("folder"), py::arg("threads"), py::arg("quiet"))
      .def("go",
           [](Session& s, std::uint64_t until) {
             talus::run::RunOutcome r;
             {
               py::gil_scoped_release nogil;
               r = s.go(until);
             }
             if (r == talus::run::RunOutcome::interrupted && PyErr_Occurred())
               throw py::error_already_set();
             return outcome_name(r);
           })
      .def("change", &Session::change, py::arg("set"), py::arg("source"))
      .def("extend_to", &Session::extend_to)
      .def("add_grains",
           [](Session& s, const std::vector<std::array<double, 2>>& position,
              const std::vector<double>& radius, const std::vector<std::array<double, 2>>& velocity,
              const std::vector<double>& spin, std::uint16_t material, const std::string& source) {
             const std::size_t n = position.size();
             if (radius.size() != n || velocity.size() != n || spin.size() != n)
               throw std::invalid_argument("add_grains: positions, radii, velocities and spins "
                                           "must be as many");
             std::vector<talus::ParticleSpec> grains(n);
             for (std::size_t k = 0; k < grains.size(); ++k) {
               grains[k].position = {position[k][0], position[k][1]};
               grains[k].radius = radius[k];
               grains[k].velocity = {velocity[k][0], velocity[k][1]};
               grains[k].angular_velocity = spin[k];
               grains[k].material = material;
             }
             return s.add_grains(grains, source);
           })
      .def("remove_grains", &Session::remove_grains)
      .def("material_names",
           [](const Session& s) {
             std::vector<std::string> names;
             for (const talus::Material& material : s.scenario().materials)
               names.push_back(material.name);
             return names;
           })
      .def("checkpoint", &Session::checkpoint)
      .def("stop_here", &Session::stop_here)
      .def("flush", &Session::flush)
      .def_property_readonly("folder", &Session::folder)
      .def_property_readonly("ended", &Session::ended)
      .def_property_readonly("time", [](const Session& s) { return s.simulation().time(); })
      .def_property_readonly("step", [](const Session& s) { return s.simulation().step_count(); })
      .def_property_readonly("timestep",
                             [](const Session& s) { return s.simulation().config().timestep; })
      .def_property_readonly("threads", [](const Session& s) { return s.simulation().threads(); })
      .def_property_readonly("duration",
                             [](const Session& s) { return s.scenario().simulation.duration; })
      .def_property_readonly("stage", [](const Session& s) { return s.book().stage; })
      .def_property_readonly("stage_count",
                             [](const Session& s) { return s.scenario().stages.size(); })
      .def("step_at", [](const Session& s, double t) { return s.simulation().step_at(t); })
      .def("scenario_toml", [](const Session& s) { return talus::to_toml(s.scenario()); })
      .def("particles",
           [](const Session& s) { return talus::python::particle_arrays(s.simulation()); })
      .def("particle_field",
           [](const Session& s, const std::string& name) {
             return talus::python::particle_field(s.simulation(), name);
           })
      .def("walls", [](const Session& s) { return talus::python::wall_arrays(s.simulation()); })
      .def("contacts",
           [](const Session& s) { return talus::python::contact_arrays(s.simulation()); })
      .def("measures",
           [](const Session& s) { return talus::python::measures(s.simulation(), s.book()); })
      .def("groups", [](const Session& s) { return talus::python::group_arrays(s.book()); });
}

} // namespace

PYBIND11_MODULE(_talus, m) {
  m.doc() = "talus' native engine (use the talus package)";
  py::register_exception<talus::ScenarioError>(m, "ScenarioError", PyExc_ValueError);
  py::register_exception<talus::InstabilityError>(m, "InstabilityError", PyExc_RuntimeError);
  py::register_exception<talus::CheckpointError>(m, "CheckpointError", PyExc_RuntimeError);

  py::class_<talus::Scenario>(m, "Scenario")
      .def_readonly("name", &talus::Scenario::name)
      .def_property_readonly("duration",
                             [](const talus::Scenario& s) { return s.simulation.duration; })
      .def("to_toml", [](const talus::Scenario& s) { return talus::to_toml(s); });
  m.def("resolve_scenario", &talus::cli::resolve_scenario, py::arg("what"), py::arg("set"),
        "a scenario file (.toml, thesis .in) or a built-in name, with key=value changes");
  m.def("load_scenario", &talus::load_scenario, py::arg("text"), py::arg("source"), py::arg("set"),
        "a scenario from TOML text; `source` names it in errors");
  m.def("builtin_names", [] {
    std::vector<std::string> names;
    for (const auto& b : talus::cli::builtin_scenarios()) names.emplace_back(b.name);
    return names;
  });
  m.def("changeable_keys", &talus::changeable_keys_text);
  m.def("changeable", &talus::changeable_during_run);
  m.def("analyze", &analyze, py::arg("folder"), py::arg("what"), py::arg("frames"),
        py::arg("start"), py::arg("bins"), py::arg("cell"), py::arg("axis"), py::arg("kernel"),
        py::arg("width"), py::arg("map"));
  bind_session(m);
}
