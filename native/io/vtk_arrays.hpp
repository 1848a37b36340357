#pragma once
// The pieces of a VTK XML file the ParaView writers share.
#include <cstddef>
#include <string>

#include <fmt/format.h>

namespace talus::vtk_detail {

/// A DataArray of n tuples of `components` numbers, value(i) giving tuple i's text.
template <class F>
void array(std::string& out, const char* name, int components, std::size_t n, F value) {
  out += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                     "format=\"ascii\">\n",
                     name, components);
  for (std::size_t i = 0; i < n; ++i) out += value(i) + "\n";
  out += "        </DataArray>\n";
}

/// The cells of a PolyData of n points as vertices, one each, and the file's end.
inline void end_with_verts(std::string& out, std::size_t n) {
  out += "      <Verts>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("{}\n", i);
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("{}\n", i + 1);
  out += "        </DataArray>\n      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

} // namespace talus::vtk_detail
