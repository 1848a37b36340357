#pragma once
// What the scenario files of both dimensions share: the text parsed with its --set overrides,
// the dimension it asks for, the name, the materials and a size distribution.
#include <string>
#include <string_view>
#include <vector>

#include "materials/material.hpp"
#include "scenario/file/toml_reader.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// The TOML of a scenario with each "dotted.key=value" override applied (value in TOML syntax;
/// a bare word is taken as a string). `file` names the source in errors.
toml::table parse_with_overrides(std::string_view text, const std::string& file,
                                 const std::vector<std::string>& overrides);
/// Applies one "dotted.key=value" override.
void apply_override(toml::table& root, const std::string& assignment);
/// simulation.dimension: 2 (disks, the default) or 3 (spheres); anything else is refused.
int scenario_dimension(const toml::table& root, const std::string& file);

/// Reads the table `name` of the root, if there is one, with `read`, then refuses its unread keys.
template <class F>
void section(TableReader& top, const char* name, const std::string& file, F&& read) {
  if (const toml::table* t = top.table(name)) {
    TableReader r(*t, file, name);
    read(r);
    r.finish();
  }
}

/// Index of the material named `name` (0 for ""); throws ScenarioError (naming `key` and the
/// materials defined) when there is none.
std::uint16_t material_index(const std::vector<Material>& materials, const std::string& name,
                             const std::string& key);

/// The root's `name`, checked as a run folder's name.
std::string read_name(TableReader& top, std::string fallback);
/// One [[materials]] table.
Material read_material(TableReader& r, std::size_t index);
/// Every [[materials]] table (one "grain" of default keys if none), their names distinct.
std::vector<Material> read_materials(TableReader& top, const std::string& file);
/// A [particles.size] table.
void read_size(TableReader& r, SizeSpec& s);

/// An [[output.stress_regions]] entry's name: a word of lower-case letters, digits and _ (its
/// thermo.csv columns' prefix), none of `taken`.
std::string read_region_name(TableReader& r, const std::vector<std::string>& taken);

/// The same sections written back, for a resolved scenario.
toml::array materials_array(const std::vector<Material>& materials);
toml::table size_table(const SizeSpec& s);

} // namespace talus
