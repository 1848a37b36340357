#pragma once
// The thesis' frost heave (sec. 5.2), shared by every engine: when the grains have come to
// rest, each free grain's height above the table is multiplied by the heave factor. The native
// uniform freeze (native/frost) and fix frost/heave move grains by this one expression.

namespace talus {

/// The height of a grain at `height` after a heave by `factor` above a table at `table` (m).
inline double heaved_height(double height, double table, double factor) {
  return table + (height - table) * factor;
}

} // namespace talus
