#pragma once
// Reads one TOML table key by key, checking each value, and rejects keys it was not asked for
// (with a suggestion). Every error names the file, the line, the key and the allowed values.
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/vec2.hpp"
#include "talus/error.hpp"

namespace talus {

namespace keys {
/// A number key's bound where there is none.
inline constexpr double inf = std::numeric_limits<double>::infinity();
} // namespace keys

/// A scenario that cannot be used; what() reads "FILE:LINE: key 'K': problem; allowed: ...".
class ScenarioError : public InvalidArgument {
public:
  using InvalidArgument::InvalidArgument;
};

/// Edit distance between two words (for "did you mean" suggestions).
std::size_t edit_distance(std::string_view a, std::string_view b);

class TableReader {
public:
  /// `path` is the dotted name of the table ("" for the root, "simulation", "materials.0").
  TableReader(const toml::table& table, std::string file, std::string path);

  bool has(std::string_view key);
  double number(std::string_view key, double fallback, double min, double max, const char* allowed);
  std::optional<double> optional_number(std::string_view key, double min, double max,
                                        const char* allowed);
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t min,
                       std::int64_t max);
  bool boolean(std::string_view key, bool fallback);
  std::string text(std::string_view key, std::string fallback);
  std::string choice(std::string_view key, std::string fallback,
                     std::initializer_list<std::string_view> allowed) {
    return choice(key, std::move(fallback), std::span(allowed.begin(), allowed.size()));
  }
  std::string choice(std::string_view key, std::string fallback,
                     std::span<const std::string_view> allowed);
  Vec2 vec2(std::string_view key, Vec2 fallback);
  /// An array of strings (empty if absent).
  std::vector<std::string> texts(std::string_view key);
  std::vector<double> numbers(std::string_view key, double min, double max, const char* allowed);
  std::optional<std::vector<double>> optional_numbers(std::string_view key);
  /// The sub-table at key, or nullptr.
  const toml::table* table(std::string_view key);
  /// The array of tables at key (empty if absent).
  std::vector<const toml::table*> tables(std::string_view key);

  /// Throws for the first key that was never read, suggesting the nearest known one.
  void finish() const;
  /// Whether the key holds a number (an integer or a float).
  bool is_number(std::string_view key) const {
    const toml::node* n = table_.get(key);
    return n && (n->is_integer() || n->is_floating_point());
  }
  /// Error at a key of this table (its line if present).
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  /// Error at this table.
  [[noreturn]] void fail_table(const std::string& problem) const;

  const std::string& file() const { return file_; }
  std::string qualified(std::string_view key) const;

  /// Every key any reader was asked for, as "table.key" (tables of arrays without index).
  static const std::set<std::string>& known_keys();

private:
  const toml::node* get(std::string_view key);
  std::string where(const toml::node* node) const;

  const toml::table& table_;
  std::string file_;
  std::string path_;
  std::set<std::string, std::less<>> read_;
};

} // namespace talus
