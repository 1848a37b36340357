// The run's bookkeeping (RunBook) as the text saved inside every checkpoint: one line per
// item, numbers at full precision so a resume continues exactly.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "run/run_book.hpp"

namespace talus::run {

namespace {

// A vector of numbers as its count, then the numbers.
void write_numbers(std::ostream& o, const std::vector<double>& v) {
  o << v.size();
  for (const double x : v) o << " " << x;
}

std::vector<double> read_numbers(std::istream& in) {
  std::size_t n = 0;
  in >> n;
  std::vector<double> v(n);
  for (double& x : v) in >> x;
  return v;
}

// A word of free text (a change's source, a key=value) on a line of words: blanks, newlines and
// backslashes escaped.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\')
      out += "\\\\";
    else if (c == ' ')
      out += "\\s";
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else
      out += c;
  }
  return out.empty() ? "\\e" : out;
}

std::string unescaped(const std::string& word) {
  std::string out;
  for (std::size_t k = 0; k < word.size(); ++k) {
    if (word[k] != '\\' || k + 1 == word.size()) {
      out += word[k];
      continue;
    }
    const char c = word[++k];
    if (c == 's')
      out += ' ';
    else if (c == 'n')
      out += '\n';
    else if (c == 't')
      out += '\t';
    else if (c == '\\')
      out += '\\';
    // 'e': the empty word
  }
  return out;
}

} // namespace

std::vector<std::string> RunBook::overrides() const {
  std::vector<std::string> all;
  for (const RunChange& c : changes) all.insert(all.end(), c.set.begin(), c.set.end());
  // A key set again replaces what it was set to before, whatever came between (an override
  // assigns), so only its last setting is kept, in the order of the last settings: a run
  // changed at every few steps (a controller) loads its scenario with one override a key.
  const auto key = [](const std::string& x) { return x.substr(0, x.find('=')); };
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (auto x = all.rbegin(); x != all.rend(); ++x)
    if (seen.insert(key(*x)).second) out.push_back(*x);
  std::reverse(out.begin(), out.end());
  return out;
}

RunBook RunBook::of(const BuiltScenario& built) {
  RunBook book;
  book.tracked = built.tracked;
  book.groups = built.groups;
  for (const auto& [name, _] : built.groups) book.force_columns.push_back(name);
  book.fill = built.fill;
  book.bounds = built.bounds;
  book.settle_time = built.settle_time;
  book.collision_time = built.collision_time;
  return book;
}

std::string RunBook::encode() const {
  std::ostringstream o;
  o.precision(17);
  for (const auto& [f, b] : file_bytes) o << "file " << f << " " << b << "\n";
  o << "snapshots " << snapshots << "\nfreezes " << freezes << "\nlast_freeze " << last_freeze
    << "\nwall_seconds " << wall_seconds << "\nsettle_time " << settle_time << "\ncollision_time "
    << collision_time << "\nfill " << fill.lo.x << " " << fill.lo.y << " " << fill.hi.x << " "
    << fill.hi.y << "\nbounds " << bounds.lo.x << " " << bounds.lo.y << " " << bounds.hi.x << " "
    << bounds.hi.y << "\ntracked";
  for (const auto t : tracked) o << " " << t;
  o << "\nforce_columns";
  for (const std::string& name : force_columns) o << " " << name;
  write_numbers(o << "\nsnapshot_times ", snapshot_times);
  write_numbers(o << "\nfront_state ", front_state);
  write_numbers(o << "\ncontact_state ", contact_state);
  write_numbers(o << "\nledger_state ", ledger_state);
  o << "\n";
  if (!ended.empty()) o << "ended " << ended << "\n";
  o << "stage " << stage << " " << stage_start << " " << stage_start_time << "\nscenario_hash "
    << scenario_hash << "\nrun_id " << run_id << "\n";
  for (const RunChange& c : changes) {
    o << "change " << c.step << " " << c.time << " " << escaped(c.source) << " " << c.set.size();
    for (const std::string& x : c.set) o << " " << escaped(x);
    o << "\n";
  }
  for (const auto& [name, g] : groups) {
    o << "group " << name << " " << g.particles.size();
    for (const auto i : g.particles) o << " " << i;
    o << " " << g.segments.size();
    for (const auto i : g.segments) o << " " << i;
    o << "\n";
  }
  return o.str();
}

RunBook RunBook::decode(const std::string& text) {
  RunBook b;
  bool columns_given = false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    std::string key;
    l >> key;
    if (key == "file") {
      std::string f;
      std::uint64_t n = 0;
      l >> f >> n;
      b.file_bytes[f] = n;
    } else if (key == "snapshots")
      l >> b.snapshots;
    else if (key == "freezes")
      l >> b.freezes;
    else if (key == "last_freeze")
      l >> b.last_freeze;
    else if (key == "wall_seconds")
      l >> b.wall_seconds;
    else if (key == "ended")
      l >> b.ended;
    else if (key == "settle_time")
      l >> b.settle_time;
    else if (key == "collision_time")
      l >> b.collision_time;
    else if (key == "fill")
      l >> b.fill.lo.x >> b.fill.lo.y >> b.fill.hi.x >> b.fill.hi.y;
    else if (key == "bounds")
      l >> b.bounds.lo.x >> b.bounds.lo.y >> b.bounds.hi.x >> b.bounds.hi.y;
    else if (key == "stage") {
      l >> b.stage >> b.stage_start;
      if (!(l >> b.stage_start_time)) // a book of a talus whose timestep never changed
        b.stage_start_time = std::numeric_limits<double>::quiet_NaN();
    } else if (key == "scenario_hash")
      l >> b.scenario_hash;
    else if (key == "run_id")
      l >> b.run_id;
    else if (key == "change") {
      RunChange c;
      std::string word;
      std::size_t n = 0;
      l >> c.step >> c.time >> word >> n;
      c.source = unescaped(word);
      for (std::size_t k = 0; k < n && l >> word; ++k) c.set.push_back(unescaped(word));
      b.changes.push_back(std::move(c));
    } else if (key == "force_columns") {
      columns_given = true;
      for (std::string name; l >> name;) b.force_columns.push_back(name);
    } else if (key == "snapshot_times") {
      b.snapshot_times = read_numbers(l);
    } else if (key == "front_state")
      b.front_state = read_numbers(l);
    else if (key == "contact_state")
      b.contact_state = read_numbers(l);
    else if (key == "ledger_state")
      b.ledger_state = read_numbers(l);
    else if (key == "tracked") {
      for (std::uint32_t t; l >> t;) b.tracked.push_back(t);
    } else if (key == "group") {
      std::string name;
      std::size_t n = 0;
      l >> name >> n;
      DriverTargets& g = b.groups[name];
      g.particles.resize(n);
      for (auto& i : g.particles) l >> i;
      l >> n;
      g.segments.resize(n);
      for (auto& i : g.segments) l >> i;
    }
  }
  if (!columns_given) // a book of a talus whose groups never changed: they are its columns
    for (const auto& [name, _] : b.groups) b.force_columns.push_back(name);
  return b;
}

std::uint64_t new_run_id() {
  std::random_device device;
  const auto now = std::chrono::system_clock::now().time_since_epoch().count();
  std::uint64_t id = (std::uint64_t{device()} << 32) ^ device() ^ static_cast<std::uint64_t>(now);
  return id == 0 ? 1 : id;
}

std::string run_id_line(std::uint64_t id) {
  return fmt::format("# talus run {:016x}: this run's scenario, as it started\n", id);
}

std::uint64_t run_id_in(const std::string& scenario_text) {
  unsigned long long id = 0;
  return std::sscanf(scenario_text.c_str(), "# talus run %16llx:", &id) == 1 ? id : 0;
}

} // namespace talus::run
