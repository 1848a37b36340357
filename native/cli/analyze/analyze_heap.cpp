// `talus analyze DIR repose`: the angle of repose of the heap in a run's last snapshot.
#include <cmath>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "post/repose.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

std::string flank_json(const ReposeFlank& f) {
  if (!f.measured) return fmt::format("{{\"measured\": false, \"why_not\": \"{}\"}}", f.why_not);
  return fmt::format("{{\"measured\": true, \"angle_deg\": {}, \"slope\": {}, \"intercept\": {}, "
                     "\"rms\": {}, \"points\": {}}}",
                     json_number(f.angle_deg), json_number(f.slope), json_number(f.intercept),
                     json_number(f.rms), f.points);
}

std::string flank_words(const char* side, const ReposeFlank& f) {
  if (!f.measured) return fmt::format("{} flank not measured ({})", side, f.why_not);
  return fmt::format("{} flank {:.1f} deg ({} bins, {:.2g} m about the line)", side, f.angle_deg,
                     f.points, f.rms);
}

} // namespace

Section analyze_repose(RunData& run) {
  const Frame& last = run.frames(0.0).back();
  const ReposeProfile p = repose_profile(last);
  const fs::path out = run.out();
  std::string csv = "x,surface,flank\n";
  for (std::size_t k = 0; k < p.x.size(); ++k)
    csv += fmt::format("{:.6g},{:.6g},{}\n", p.x[k], p.surface[k],
                       p.flank[k] < 0 ? "left" : (p.flank[k] > 0 ? "right" : ""));
  write_file_atomically((out / "repose.csv").string(), csv);
  write_file_atomically(
      (out / "repose.json").string(),
      fmt::format("{{\"time\": {}, \"angle_deg\": {}, \"base\": {}, \"height\": {}, \"peak_x\": "
                  "{}, \"bin_width\": {}, \"band\": [{}, {}], \"left\": {}, \"right\": {}}}\n",
                  json_number(last.time), json_number(p.angle_deg), json_number(p.base),
                  json_number(p.height), json_number(p.peak_x), json_number(p.bin_width),
                  surface_band_low, surface_band_high, flank_json(p.left), flank_json(p.right)));
  Section s{"Angle of repose", {}, {}, {}};
  s.summary = fmt::format(
      "The heap in the last snapshot (t = {:.3g} s): its free surface is the highest grain top in "
      "bins of two mean diameters across x, and a straight line is fitted to each flank where "
      "the surface lies between {} and {} of the heap's height above its base (the toe and the "
      "rounded top left out).",
      last.time, surface_band_low, surface_band_high);
  s.numbers = {{"angle of repose", std::isfinite(p.angle_deg)
                                       ? fmt::format("{:.1f} deg", p.angle_deg)
                                       : std::string("not measured")},
               {"flanks", flank_words("left", p.left) + "; " + flank_words("right", p.right)},
               {"heap height", fmt::format("{:.3g} m", p.height)}};
  fmt::print("repose: angle {:.1f} deg; {}; {}\n", p.angle_deg, flank_words("left", p.left),
             flank_words("right", p.right));
  if (plot(out, "repose", out / "repose.csv", out / "repose.png", out / "repose.json"))
    s.charts.push_back(out / "repose.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace talus::cli
