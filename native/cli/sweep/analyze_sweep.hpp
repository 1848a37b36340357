#pragma once
// The analyses of a sweep folder (cli/sweep.hpp), written to SWEEP/analysis.
#include <filesystem>
#include <string>

#include "cli/analyze/analyses.hpp"

namespace talus::cli {

/// One result of the index (a number every finished run reports) against the varied keys:
/// RESULT.csv with the mean, standard deviation, least and greatest over the seeds of each
/// combination, and RESULT.png. Throws InvalidArgument listing the results for an unknown one.
void analyze_sweep_result(const std::filesystem::path& dir, const std::string& result);

/// Every run's discharge (post/discharge.hpp, with o.window and o.from) in discharge.csv, and
/// when the sweep varies geometry.orifice, the Beverloo fit over the widths, n free and n = 3/2,
/// for each combination of the other keys: beverloo.csv, beverloo.json, beverloo.png.
void analyze_sweep_discharge(const std::filesystem::path& dir, const AnalysisOptions& o);

/// Every finished run's rheology (run_rheology, with o.from): rheology_points.csv, and the fits
/// of mu(I) (mu_s, mu_2, I_0; and mu_1 + b I) and phi(I) = phi_max - a I over them:
/// rheology.json, rheology.png.
void analyze_sweep_rheology(const std::filesystem::path& dir, const AnalysisOptions& o);

/// Layers of several depths on one slope (the built-in chute_stop swept over particles.count):
/// each run's depth and whether it still flows at its end (the mean over its last 2 s, or from
/// o.from), and h_stop between the deepest stopped and the shallowest flowing layer:
/// chute_stop.csv, chute_stop.json, chute_stop.png.
void analyze_sweep_chute(const std::filesystem::path& dir, const AnalysisOptions& o);

} // namespace talus::cli
