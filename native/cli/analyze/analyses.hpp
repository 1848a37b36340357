#pragma once
// The analyses of `talus analyze`: each reads a run folder, writes CSV files with documented
// columns (docs/file-formats.md), a JSON of key numbers and a matplotlib chart into
// DIR/analysis, and returns what the report shows.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/frame.hpp"
#include "post/chute.hpp"
#include "post/discharge.hpp"
#include "post/rheology.hpp"
#include "scenario/scenario.hpp"

namespace talus::cli {

/// A run folder, with its scenario and snapshots read once and shared by the analyses.
class RunData {
public:
  explicit RunData(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }
  /// DIR/analysis, made on first use: an analysis that fails its checks leaves nothing behind.
  const std::filesystem::path& out();
  const Scenario& scenario() const { return scenario_; }
  bool has_snapshots() const;
  /// The snapshots (particles and walls, no contacts) from time `from` on; throws
  /// InvalidArgument when there are none.
  const std::vector<Frame>& frames(double from = 0.0);
  /// The snapshots from `from` on with their contacts (force chains and force vectors).
  std::vector<Frame> frames_with_contacts(double from);
  /// The mean radius of the free grains in the first snapshot, m.
  double mean_radius();

private:
  std::filesystem::path dir_, out_;
  Scenario scenario_;
  std::vector<Frame> all_, picked_;
  double picked_from_ = -1.0;
};

struct AnalysisOptions {
  std::string frames = "all";                    ///< forces: all or last
  std::optional<std::pair<double, double>> band; ///< profiles: y0, y1 in m
  std::size_t bins = 0;                          ///< profiles: bins across (0: automatic)
  double from = -1.0; ///< s: ignore snapshots before this; < 0: each analysis' default
                      ///< (profiles of a driven flow leave the start-up out, start_up_end;
                      ///< the others nothing)
  double cell = 0.0;  ///< speed map cell, m (0: automatic)
  std::optional<std::pair<double, double>> window; ///< discharge: t0, t1 in s (none: steady)
  std::string axis; ///< fields: the profile's axis, x, y or z (empty: y in 2D; in 3D gravity's)
  std::string kernel = "gaussian"; ///< fields: gaussian or lucy
  double width = 0.0;              ///< fields: the kernel's width, m (0: the mean grain radius)
  bool map = false;                ///< fields: a map of the plane instead of profiles
};

/// What one analysis gives the report: its charts and key numbers.
struct Section {
  std::string title;
  std::string summary;
  std::vector<std::filesystem::path> charts;
  std::vector<std::pair<std::string, std::string>> numbers;
};

/// A number for a JSON file: "null" when it is not finite.
std::string json_number(double v);
/// A number for a CSV cell: empty when it is not finite.
std::string csv_number(double v);
/// A text for a CSV cell: quoted (its quotes doubled, RFC 4180) when it holds a comma or a quote,
/// as a swept vector's value does ("[2.87,-9.38]").
std::string csv_cell(const std::string& text);

/// The times of a run's frost.csv at which the bed was at rest: each freeze, and the end if the
/// run logged one. Throws InvalidArgument when the file is missing or a row is malformed.
std::vector<double> freeze_times(const std::filesystem::path& file);

/// Draws a chart with the compiled-in matplotlib script; false (with a note) when matplotlib is
/// missing or the script fails, so the CSV files still stand. A script that fails is counted in
/// failed_charts().
bool plot(const std::filesystem::path& out, const std::string& kind,
          const std::filesystem::path& csv, const std::filesystem::path& png,
          const std::filesystem::path& json = {});

/// Charts whose script failed in this process: talus analyze then exits non-zero.
int& failed_charts();

/// Where a run's start-up ends, for analyses of its steady state: the first quarter of the time
/// its snapshots span (a drum spinning up, a silo's first outflow).
double start_up_end(RunData& run);

/// Where the steady state of a flow measured over its second half starts: --from, else the
/// middle of the span of the run's snapshots (a shear cell or a chute gaining speed).
double steady_from(RunData& run, const AnalysisOptions& o);
/// The coarse-graining kernel's width: --width, else the mean grain radius (Gaussian) or two
/// (Lucy's kernel, which reaches its width and no farther).
double kernel_width(RunData& run, const AnalysisOptions& o);

Section analyze_thermo(RunData& run);
/// The same of any run folder `dir` (a 3D run's too), into `out`.
Section analyze_thermo(const std::filesystem::path& dir, const std::filesystem::path& out);
Section analyze_forces(RunData& run, const AnalysisOptions& o);
/// The same of any run folder `dir` with contacts.pvd (a 3D run's too), into `out`.
Section analyze_forces(const std::filesystem::path& dir, const std::filesystem::path& out,
                       const AnalysisOptions& o);
Section analyze_profiles(RunData& run, const AnalysisOptions& o);
Section analyze_tracks(RunData& run);
/// contact_events.csv (output.contacts): durations, peak forces and restitutions per kind of
/// contact; throws InvalidArgument when the run wrote none.
Section analyze_contacts(RunData& run);

/// The discharge through the run's orifice (post/discharge.hpp); throws InvalidArgument when the
/// container has none.
Discharge run_discharge(RunData& run, const AnalysisOptions& o);
/// One line: the rate with its error and window, or why there is none.
std::string discharge_text(const Discharge& q);
/// discharge.csv and discharge.json in `out`.
void write_discharge(const std::filesystem::path& out, const Discharge& q);
Section analyze_segregation(RunData& run, const AnalysisOptions& o);
Section analyze_frost(RunData& run);
/// The angle of repose of the heap in the last snapshot (post/repose.hpp).
Section analyze_repose(RunData& run);
/// Coarse-grained profiles (post/coarse_grain.hpp) of density, velocity and stress along an
/// axis, averaged over the snapshots from AnalysisOptions::from on.
Section analyze_fields(RunData& run, const AnalysisOptions& o);
/// The side walls' stress against depth in a silo, and Janssen's fit (post/janssen.hpp).
Section analyze_janssen(RunData& run, const AnalysisOptions& o);
/// A run let down in steps of pressure: the jamming point (post/jamming.hpp).
Section analyze_jamming(RunData& run, const AnalysisOptions& o);

/// A plane shear flow's mu, phi and I (post/rheology.hpp), from --from or the second half of the
/// snapshots; throws InvalidArgument for a run that is not periodic along x.
RheologyPoint run_rheology(RunData& run, const AnalysisOptions& o);
/// Whether the scenario is simple shear in a sheared cell (a cell driver with a shear_rate),
/// which the rheology analysis measures from the cell's own stress.
bool sheared_cell(const Scenario& s);
/// One point in a line: I, mu and phi with their errors, the shear rate and the pressure (in
/// `stress_unit`: N/m in 2D, Pa in 3D), or why it was not measured.
std::string rheology_point_text(const RheologyPoint& r, const char* stress_unit = "N/m");
/// One point as a JSON object (rheology.json).
std::string rheology_json(const RheologyPoint& r);
Section analyze_rheology(RunData& run, const AnalysisOptions& o);
/// A flow down a rough incline, periodic along it: profiles and Bagnold's fit (post/chute.hpp).
Section analyze_chute(RunData& run, const AnalysisOptions& o);

/// The same of spheres in 3D (analyze3.cpp gathers the frames and options), into `out`.
Section analyze_chute3(const std::filesystem::path& out, const std::vector<Frame3>& frames,
                       const ChuteOptions3& o);

/// Throws InvalidArgument, naming the allowed names, unless `what` names one analysis of a run
/// folder (thermo, forces, profiles, tracks, segregation, frost, contacts, repose, fields,
/// janssen, jamming, rheology, chute).
void check_analysis_name(const std::string& what);
/// The analysis `what` names (check_analysis_name), as `talus analyze DIR WHAT` runs it.
Section analyze_one(RunData& run, const std::string& what, const AnalysisOptions& o);

/// DIR/analysis/report.html: one page, images embedded, readable offline.
std::filesystem::path write_report(RunData& run, const std::vector<Section>& sections);
/// The same page for any run folder `dir`, into `out`: its name, description and scenario's rows.
std::filesystem::path
write_report_page(const std::filesystem::path& dir, const std::filesystem::path& out,
                  const std::string& name, const std::string& description,
                  const std::vector<std::pair<std::string, std::string>>& scenario,
                  const std::vector<Section>& sections);

/// `talus analyze DIR [WHAT]` for a run of spheres in 3D (analyze3.cpp): fields, rheology (of a
/// sheared cell), or all (every analysis of a 3D run that applies, and report.html); throws
/// InvalidArgument naming what a 3D run has for any other.
void analyze_3d_run(const std::filesystem::path& dir, const std::string& what,
                    const AnalysisOptions& o);
/// A 3D sheared cell's mu, phi and I (post/rheology.hpp) from --from or the second half of the
/// snapshots; throws InvalidArgument for a run that is not one.
RheologyPoint run_rheology3(const std::filesystem::path& dir, const AnalysisOptions& o);

} // namespace talus::cli
