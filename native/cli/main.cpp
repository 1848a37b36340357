// talus: discrete element simulation of granular media (command line).
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "cli/commands.hpp"
#include "talus/error.hpp"

int main(int argc, char** argv) {
  // A file size limit or a full disk must fail a write (and be reported), not kill the process.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"talus: discrete element simulation of granular media (2D soft disks)", "talus"};
  app.set_version_flag("--version", std::string("talus ") + TALUS_VERSION);
  app.require_subcommand(1);
  talus::cli::add_run_command(app);
  talus::cli::add_resume_command(app);
  talus::cli::add_sweep_command(app);
  talus::cli::add_scenarios_command(app);
  talus::cli::add_convert_command(app);
  talus::cli::add_export_command(app);
  talus::cli::add_demo_command(app);
  talus::cli::add_bench_command(app);
  talus::cli::add_checkpoint_command(app);
  talus::cli::add_picture_commands(app);
  talus::cli::add_analyze_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const talus::InvalidArgument& e) {
    fmt::print(stderr, "talus: error: {}\n", e.what());
    return 2;
  } catch (const talus::InstabilityError& e) {
    fmt::print(stderr, "talus: the run went unstable: {}\n", e.what());
    return 3;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "talus: error: out of memory: this process could not get the memory it "
                       "asked for (a limit such as ulimit -v, or other processes' use); fewer "
                       "particles, or more memory\n");
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "talus: error: {}\n", e.what());
    return 1;
  }
  return talus::cli::exit_status();
}
