#pragma once
// Reads back the snapshots talus writes (io/vtk.hpp): a run folder's .pvd collection and .vtp
// files, into frames for pictures and movies.
#include <string>
#include <utility>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/frame3.hpp"

namespace talus {

/// The (time, file) entries of a .pvd collection, files relative to the .pvd's folder.
std::vector<std::pair<double, std::string>> read_pvd(const std::string& path);

/// One frame from a particles .vtp file and, if not empty, the matching walls .vtp file.
/// Throws std::runtime_error naming the file and the array that is missing or malformed.
/// The normal forces (N) of a contacts .vtp file.
std::vector<double> read_contact_normal_forces(const std::string& contacts);

/// `contacts`, if not empty and present, adds the force chains.
Frame read_vtp_frame(const std::string& particles, const std::string& walls, double time,
                     const std::string& contacts = {});

/// One frame of a 3D run from its spheres' .vtp file and, if not empty and present, its contacts'
/// (io/vtk_spheres.hpp). Throws std::runtime_error naming the file and the array that is missing
/// or malformed; a snapshot written before the box was recorded leaves the frame's box empty.
Frame3 read_vtp_frame3(const std::string& spheres, double time, const std::string& contacts = {});

} // namespace talus
