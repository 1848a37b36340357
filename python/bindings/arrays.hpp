#pragma once
// The engine's state as numpy arrays (copies: the engine renumbers and reallocates its particles
// between steps, so a view could outlive the memory it looks at).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "run/run_book.hpp"
#include "simulation/simulation.hpp"

namespace talus::python {

/// position, velocity, force, image: (N, 2); angle, spin, torque, radius, mass, inertia, material,
/// kind, id: (N,).
pybind11::dict particle_arrays(const Simulation& sim);
/// One field of particle_arrays by its name; throws std::invalid_argument naming the fields.
pybind11::array particle_field(const Simulation& sim, const std::string& name);
/// a, b, velocity, force: (M, 2); angular_velocity, material: (M,).
pybind11::dict wall_arrays(const Simulation& sim);
/// Every touching contact (pairs, then walls): i, j (-1 for a wall), wall (-1 for a pair), point,
/// branch, force: (K, 2); overlap, overlap_rate, normal_force, tangential_force: (K,).
pybind11::dict contact_arrays(const Simulation& sim);
/// The thermo quantities now: energies, momentum, coordination, contacts, and the force on each
/// wall group of the run.
pybind11::dict measures(const Simulation& sim, const run::RunBook& book);
/// Each wall group's particle and segment indices.
pybind11::dict group_arrays(const run::RunBook& book);

} // namespace talus::python
