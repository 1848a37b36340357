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

/// The contacts' cell arrays of both dimensions' contact records: normal_force and
/// tangential_force (N), overlap (m), to 9 digits.
template <class Records> void contact_scalars(std::string& out, const Records& c) {
  array(out, "normal_force", 1, c.size(),
        [&](std::size_t k) { return fmt::format("{:.9g}", c[k].normal_force); });
  array(out, "tangential_force", 1, c.size(),
        [&](std::size_t k) { return fmt::format("{:.9g}", c[k].tangential_force); });
  array(out, "overlap", 1, c.size(),
        [&](std::size_t k) { return fmt::format("{:.9g}", c[k].overlap); });
}

/// A PolyData of n straight lines: `cells` writes the CellData arrays, `end(k, second)` gives the
/// text of the first or second end point of line k (three coordinates).
template <class Cells, class End>
std::string line_polydata(std::size_t n, const char* scalars, Cells cells, End end) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\">\n  <PolyData>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfLines=\"{}\">\n", 2 * n, n);
  out +=
      *scalars ? fmt::format("      <CellData Scalars=\"{}\">\n", scalars) : "      <CellData>\n";
  cells(out);
  out += "      </CellData>\n      <Points>\n";
  array(out, "position", 3, 2 * n, [&](std::size_t k) { return end(k / 2, k % 2 == 1); });
  out += "      </Points>\n      <Lines>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < 2 * n; ++k) out += fmt::format("{}\n", k);
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out += fmt::format("{}\n", 2 * (k + 1));
  out += "        </DataArray>\n      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

} // namespace talus::vtk_detail
