// DIR/analysis/report.html: every chart and key number of a run on one page, images embedded
// (base64) so the single file reads offline and can be mailed or moved.
#include <algorithm>
#include <fstream>
#include <iterator>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "cli/analyze/report_tables.hpp"
#include "io/checkpoint.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

std::string base64(const std::string& bytes) {
  static constexpr char digits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    std::uint32_t v = 0;
    for (std::size_t j = 0; j < 3; ++j)
      v = (v << 8) | (j < n ? static_cast<unsigned char>(bytes[k + j]) : 0u);
    for (std::size_t j = 0; j < 4; ++j) out += j <= n ? digits[(v >> (18 - 6 * j)) & 63u] : '=';
  }
  return out;
}

std::string escape(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '<')
      out += "&lt;";
    else if (ch == '>')
      out += "&gt;";
    else if (ch == '&')
      out += "&amp;";
    else
      out += ch;
  }
  return out;
}

std::string image(const fs::path& png) {
  std::ifstream in(png, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  return fmt::format("<figure><img alt=\"{0}\" src=\"data:image/png;base64,{1}\">"
                     "<figcaption>{0}</figcaption></figure>\n",
                     escape(png.filename().string()), base64(bytes));
}

std::string table(const Rows& rows) {
  std::string html = "<table>\n";
  for (const auto& [k, v] : rows)
    html += fmt::format("<tr><td>{}</td><td>{}</td></tr>\n", escape(k), escape(v));
  return html + "</table>\n";
}

} // namespace

fs::path write_report(RunData& run, const std::vector<Section>& sections) {
  const Scenario& s = run.scenario();
  return write_report_page(run.dir(), run.out(), s.name, s.description, scenario_rows(s), sections);
}

fs::path write_report_page(const fs::path& dir, const fs::path& out, const std::string& name,
                           const std::string& description, const Rows& scenario,
                           const std::vector<Section>& sections) {
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>talus: "
      "{0}</title>\n"
      "<style>body{{font-family:sans-serif;max-width:1000px;margin:auto;padding:1em}}"
      "img{{max-width:100%}}table{{border-collapse:collapse}}td{{border:1px solid #ccc;"
      "padding:2px 8px}}figure{{margin:1em 0}}figcaption{{color:#666;font-size:80%}}</style>\n"
      "</head><body>\n<h1>{0}</h1>\n<p>{1}</p>\n<p>Run folder: <code>{2}</code></p>\n",
      escape(name), escape(description), escape(fs::absolute(dir).string()));
  html += "<h2>Scenario</h2>\n" + table(scenario);
  if (std::ifstream in(dir / "run.json"); in) {
    try {
      html += "<h2>Run</h2>\n" + table(run_rows(nlohmann::json::parse(in)));
    } catch (const nlohmann::json::exception& e) {
      html += "<h2>Run</h2>\n<p>run.json cannot be read: " + escape(e.what()) + "</p>\n";
    }
  }
  std::vector<fs::path> pictures;
  if (fs::exists(dir / "final.png")) pictures.push_back(dir / "final.png");
  if (fs::is_directory(dir / "pictures"))
    for (const auto& e : fs::directory_iterator(dir / "pictures"))
      if (e.path().extension() == ".png") pictures.push_back(e.path());
  std::sort(pictures.begin() + (pictures.empty() ? 0 : 1), pictures.end());
  if (!pictures.empty()) {
    html += "<h2>Pictures</h2>\n";
    for (const auto& p : pictures) html += image(p);
  }
  for (const Section& sec : sections) {
    html += fmt::format("<h2>{}</h2>\n<p>{}</p>\n", escape(sec.title), escape(sec.summary));
    if (!sec.numbers.empty()) html += table(sec.numbers);
    for (const auto& c : sec.charts) html += image(c);
  }
  html += "<p>Made by <code>talus analyze</code>; the CSV files beside this page hold the numbers "
          "(columns in docs/file-formats.md).</p>\n</body></html>\n";
  const fs::path page = out / "report.html";
  write_file_atomically(page.string(), html);
  return page;
}

} // namespace talus::cli
