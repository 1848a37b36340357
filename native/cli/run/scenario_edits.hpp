#pragma once
// An edit of a run folder's scenario.toml made between sessions: the keys a run may change are
// taken as changes from the resume point (as talus resume --set makes them); any other edit is
// refused with the reason. The scenario as the run started is kept beside it (started_copy),
// bound to the checkpoints by its hash, so that what was edited can be told.
#include <filesystem>
#include <string>
#include <vector>

#include "run/run_book.hpp"

namespace talus::cli {

/// The hidden copy of a run's scenario.toml as it started.
std::filesystem::path started_copy(const std::filesystem::path& dir);

/// The edits of dir/scenario.toml (`edited`, whose hash is not the book's) as "key=value"
/// changes, with the scenario text the run started with in `started`. Throws InvalidArgument
/// naming the keys that cannot change during a run, or when the started copy is missing or
/// not the run's.
std::vector<std::string> scenario_edits(const std::filesystem::path& dir, const std::string& edited,
                                        const run::RunBook& book, std::string& started);

} // namespace talus::cli
