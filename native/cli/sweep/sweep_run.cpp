// Running a sweep: the unfinished runs as child processes, a few at a time, with one progress
// line per run, the index rewritten after each, and a signal passed on to the runs so that each
// stops at a checkpoint and the sweep can be continued.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <map>
#include <thread>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>

#include "cli/run/run_folder.hpp"
#include "cli/sweep/sweep.hpp"
#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

volatile std::sig_atomic_t sweep_stop = 0;
void on_sweep_signal(int) {
  sweep_stop = 1;
}

void catch_signals() {
  struct sigaction a {};
  a.sa_handler = on_sweep_signal;
  sigemptyset(&a.sa_mask);
  a.sa_flags = 0;
  sigaction(SIGINT, &a, nullptr);
  sigaction(SIGTERM, &a, nullptr);
}

std::string describe(const SweepPlan& p, const SweepRun& r) {
  std::string text;
  for (std::size_t a = 0; a < p.axes.size(); ++a)
    text += (text.empty() ? "" : ", ") + p.axes[a].key + "=" + r.values[a];
  if (p.seeds > 1) text += (text.empty() ? "" : ", ") + fmt::format("seed {}", r.seed);
  return text;
}

// `talus run` (a run not started, or stopped before its first checkpoint) or `talus resume`.
pid_t launch(const fs::path& dir, const SweepRun& r) {
  const fs::path run = dir / r.name;
  const bool resume =
      fs::exists(run) && !never_checkpointed(run) &&
      (fs::exists(run / "checkpoint.bin") || fs::exists(run / "checkpoint.prev.bin"));
  const std::string exe = fs::read_symlink("/proc/self/exe").string();
  std::vector<std::string> args{exe};
  if (resume)
    args.insert(args.end(), {"resume", run.string()});
  else
    args.insert(args.end(),
                {"run", (dir / "scenarios" / (r.name + ".toml")).string(), "--out", run.string()});
  args.insert(args.end(), {"--threads", "1", "--quiet"});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = (dir / "logs" / (r.name + ".log")).string();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw InvalidArgument(std::string("talus sweep: fork: ") + std::strerror(errno));
  if (pid == 0) {
    // the run stops at a checkpoint when the sweep dies, however it dies (even by SIGKILL), so
    // that talus resume finds no run still going
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    // the sweep's handler, copied by fork, would swallow a signal passed on before the exec
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (::getppid() != parent || sweep_stop) ::_exit(130);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0 || ::dup2(fd, 1) < 0 || ::dup2(fd, 2) < 0) ::_exit(126);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

void start_folder(const fs::path& dir, const SweepPlan& plan) {
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InvalidArgument("--out '" + dir.string() + "' is a file, not a folder");
  if (is_sweep_folder(dir))
    throw InvalidArgument("'" + dir.string() +
                          "' holds a sweep already; continue it with: talus resume " +
                          dir.string() + " (or choose another folder with --out)");
  if (fs::exists(dir) && !fs::is_empty(dir))
    throw InvalidArgument("sweep folder '" + dir.string() +
                          "' exists and is not empty; choose another with --out");
  fs::create_directories(dir / "scenarios");
  fs::create_directories(dir / "logs");
  for (const SweepRun& r : plan.runs)
    write_file_atomically((dir / "scenarios" / (r.name + ".toml")).string(),
                          sweep_run_scenario(plan, r).toml);
  write_plan(dir, plan); // last: a folder with a plan has every run's scenario
}

struct Pool {
  const fs::path& dir;
  const SweepPlan& plan;
  const SweepOptions& o;
  std::vector<SweepResult> results;
  std::map<pid_t, std::size_t> running; // pid -> run index
  std::map<pid_t, std::chrono::steady_clock::time_point> started;
  std::size_t finished = 0;
  bool failed = false;

  void ended(pid_t pid, int status) {
    const std::size_t i = running.at(pid);
    running.erase(pid);
    // the process's whole time, its settling too (run.json's wall_seconds counts the steps only)
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started.at(pid)).count();
    started.erase(pid);
    const SweepRun& r = plan.runs[i];
    results[i] = read_result(dir, r);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    // a run stopped by the sweep's signal before it began is still to do, not failed
    const bool stopped_early =
        sweep_stop && results[i].status == "pending" && (code == 130 || code == 128 + SIGTERM);
    if (!stopped_early &&
        (results[i].status == "pending" || (code != 0 && code != 130 && code != 4))) {
      results[i].status = results[i].status == "pending" ? "failed" : results[i].status;
      results[i].texts["error"] = fmt::format("exit status {}; see logs/{}.log", code, r.name);
    }
    if (results[i].status == "finished") ++finished;
    if (results[i].status != "finished" && results[i].status != "interrupted" && !stopped_early)
      failed = true;
    write_index(dir, plan, results);
    if (o.quiet) return;
    report(i, seconds);
  }

  void report(std::size_t i, double seconds) const {
    const SweepRun& r = plan.runs[i];
    const SweepResult& x = results[i];
    std::string what = x.status;
    if (x.status == "finished")
      what += fmt::format(" at t = {:.4g} s in {:.3g} s", x.numbers.at("time"), seconds);
    if (x.numbers.count("rate"))
      what += fmt::format("; discharge {:.4g} +- {:.2g} grains/s", x.numbers.at("rate"),
                          x.numbers.at("rate_error"));
    else if (x.texts.count("why_no_rate"))
      what += "; discharge: " + x.texts.at("why_no_rate");
    if (x.texts.count("error")) what += " (" + x.texts.at("error") + ")";
    fmt::print("[{}/{}] {} ({}): {}\n", finished, plan.runs.size(), r.name, describe(plan, r),
               what);
    std::fflush(stdout);
  }

  // takes in the runs that ended, waiting a little when none has
  void reap() {
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid > 0) {
      if (running.count(pid)) ended(pid, status);
    } else if (pid == 0 || errno == EINTR) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    } else {
      throw InvalidArgument(std::string("talus sweep: waitpid: ") + std::strerror(errno));
    }
  }
};

} // namespace

int run_sweep(const fs::path& dir, const SweepPlan* new_plan, const SweepOptions& o) {
  if (new_plan) start_folder(dir, *new_plan);
  std::string holder;
  const int lock = take_lock(dir, holder);
  if (lock < 0)
    throw InvalidArgument("sweep folder '" + dir.string() + "' is in use by " +
                          (holder.empty() ? std::string("another process") : "process " + holder));
  const SweepPlan plan = new_plan ? *new_plan : read_plan(dir);
  Pool pool{dir, plan, o, {}, {}, {}, 0, false};
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    pool.results.push_back(read_result(dir, plan.runs[i]));
    const std::string& st = pool.results.back().status;
    if (st == "finished")
      ++pool.finished;
    else if (st == "pending" || st == "interrupted" || st == "stopped")
      todo.push_back(i);
  }
  write_index(dir, plan, pool.results);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned jobs = o.jobs ? o.jobs : cores;
  if (!o.quiet)
    fmt::print("talus sweep {}: {} runs ({} finished before), {} at a time; folder {}\n",
               plan.scenario, plan.runs.size(), pool.finished, jobs, dir.string());
  catch_signals();
  std::size_t next = 0;
  bool passed_on = false;
  while ((next < todo.size() && !sweep_stop) || !pool.running.empty()) {
    while (!sweep_stop && next < todo.size() && pool.running.size() < jobs) {
      const std::size_t i = todo[next++];
      const pid_t pid = launch(dir, plan.runs[i]);
      pool.running[pid] = i;
      pool.started[pid] = std::chrono::steady_clock::now();
    }
    if (sweep_stop && !passed_on) { // pass the signal on: each run stops at a checkpoint
      for (const auto& [pid, _] : pool.running) ::kill(pid, SIGTERM);
      passed_on = true;
    }
    pool.reap();
  }
  ::close(lock);
  if (sweep_stop) {
    fmt::print("sweep stopped: {} of {} runs finished; continue with: talus resume {}\n",
               pool.finished, plan.runs.size(), dir.string());
    return 130;
  }
  if (!o.quiet)
    fmt::print("sweep finished: {} of {} runs finished; index {}\n", pool.finished,
               plan.runs.size(), (dir / "index.csv").string());
  return pool.failed ? 1 : 0;
}

} // namespace talus::cli
