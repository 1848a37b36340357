#pragma once
// A [[drivers]] entry of a scenario file.
#include "scenario/file/toml_reader.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// The driver in `r` (a table of [[drivers]]): its type and that type's keys, a servo's
/// max_speed by default `impact_speed` (m/s). Keys of another type are refused, naming it.
DriverSection read_driver(TableReader& r, double impact_speed);

} // namespace talus
