// netsph command line: run, check, net, bench, cases. Errors become one line on stderr and a
// non-zero exit code: 1 for bad input, 3 for an unstable run, 130 for an interrupted one.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <csignal>

#include "netsph/app/commands.hpp"
#include "netsph/app/logging.hpp"
#include "netsph/case/builtin_cases.hpp"
#include "netsph/core/error.hpp"

namespace {

void add_case_options(CLI::App* cmd, netsph::app::CaseChoice& c) {
  cmd->add_option("case", c.path,
                  "case file (TOML), or builtin:<name>; default: the built-in default case");
  // One value per --set, so that a case after it (`check --set a=1 case.toml`) stays the case.
  cmd->add_option("--set", c.overrides,
                  "override a case key, e.g. --set simulation.dp=0.01 (repeatable; value in TOML "
                  "syntax)")
      ->allow_extra_args(false);
}

std::vector<double> parse_sizes(const std::string& text) {
  std::vector<double> sizes;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    try {
      std::size_t used = 0;
      sizes.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw netsph::Error("--sizes", "'" + item + "' is not a number; expected e.g. 1e5,2.4e5,1e6");
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace netsph::app;
  // A run outlives its readers: a closed pipe (`netsph run ... | head`, a plot script that
  // died) makes the write fail instead of killing the run (SIGPIPE), and a write past the file
  // size limit (`ulimit -f`) fails as a full disk does, with the previous checkpoint kept,
  // instead of killing it with a core dump (SIGXFSZ).
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"netsph: SPH for fluid flow through flexible aquaculture nets"};
  app.set_version_flag("--version", std::string("netsph ") + NETSPH_VERSION);
  app.require_subcommand(0, 1);
  app.fallthrough();
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "only warnings and errors");

  RunArgs run;
  auto* run_cmd =
      app.add_subcommand("run", "run a case (the built-in default case without a file)");
  add_case_options(run_cmd, run.case_choice);
  run_cmd->add_option("-o,--output", run.out_dir, "output folder (default: out/<case name>)");
  run_cmd
      ->add_option("--backend", run.backend,
                   "auto (cuda where a GPU is usable, else cpu), cpu, cuda, or host-device (the "
                   "CUDA kernels on the CPU: slow, for checking)")
      ->capture_default_str();
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (0: all cores)")
      ->capture_default_str();
  run_cmd->add_option("--max-steps", run.max_steps, "stop after this many steps (0: no limit)");
  run_cmd->add_flag("--plain-progress", run.plain_progress,
                    "progress as periodic lines, not a bar");
  run_cmd->add_flag("--overwrite", run.overwrite,
                    "replace an earlier run's results in the output folder (without it they are "
                    "moved aside to <folder>.1, .2, ...)");
  run_cmd->add_option("--restart", run.restart_dir,
                      "continue the run in this output folder from its checkpoint.h5");
  run_cmd
      ->add_option("--rebalance-every", run.rebalance_every,
                   "under mpirun: steps between checks of the processes' balance; the slabs are "
                   "cut again when the busiest process's own work exceeds the mean by 10% (0: "
                   "keep the slabs cut at the start)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  bool no_plots = false;
  run_cmd->add_flag("--no-plots", no_plots, "do not write PNG plots at the end");

  std::string plot_dir;
  auto* plot_cmd =
      app.add_subcommand("plot", "write PNG plots of a run folder into DIR/plots (matplotlib)");
  plot_cmd->add_option("DIR", plot_dir, "the run's output folder")->required();
  std::string shape_times;
  plot_cmd->add_option("--times", shape_times,
                       "draw the nets' shapes at these times, s (e.g. 0.5,1,2.5; default: five "
                       "moments spread over the run)");

  CheckArgs check;
  auto* check_cmd = app.add_subcommand(
      "check",
      "validate a case; print particle counts, memory, initial dt and a run-time estimate");
  add_case_options(check_cmd, check.case_choice);
  check_cmd->add_option("--threads", check.threads, "OpenMP threads (0: all cores)");
  check_cmd->add_option("-o,--output", check.out_dir,
                        "the folder the run would write to, whose free space is checked against "
                        "the run's outputs (default: out/<case name>)");
  check_cmd->add_option("--sample-steps", check.sample_steps, "steps timed for the estimate")
      ->capture_default_str();
  check_cmd
      ->add_option("--backend", check.backend,
                   "the backend whose memory and speed to report: auto, cpu, cuda, or "
                   "host-device (the CUDA step's memory, measured without a GPU)")
      ->capture_default_str();

  BenchArgs bench;
  std::string sizes = "1e5,2.4e5,1e6";
  auto* bench_cmd = app.add_subcommand(
      "bench", "benchmark the 3D dam break: particle-steps per second and bytes per particle");
  bench_cmd->add_option("--sizes", sizes, "comma-separated particle counts")->capture_default_str();
  bench_cmd->add_option("--steps", bench.steps, "timed steps per size")->capture_default_str();
  bench_cmd->add_option("--threads", bench.threads, "OpenMP threads (0: all cores)");
  bench_cmd
      ->add_option("--backend", bench.backend,
                   "auto (cuda where a GPU is usable, else cpu), cpu, cuda or host-device")
      ->capture_default_str();
  bench_cmd->add_option("--json", bench.json_path, "also write the results to this JSON file");
  bench_cmd->add_flag("--profile", bench.profile,
                      "device backends: then time the step's phases over as many steps again "
                      "(each phase waits for the device, so this run is a little slower)");

  NetArgs net;
  auto* net_cmd = app.add_subcommand(
      "net",
      "report the generated nets of a case (knots, twines, knot size, solidity, mass) "
      "and write them for ParaView");
  add_case_options(net_cmd, net.case_choice);
  net_cmd->add_option("-o,--output", net.out_dir, "output folder (default: out/<case name>)");

  ValidateArgs validate;
  auto* validate_cmd = app.add_subcommand(
      "validate",
      "run the paper's validation cases (reduced) and compare with its data and experiments");
  validate_cmd->add_flag("--quick", validate.quick,
                         "only the entries that run in a few minutes (the CI subset)");
  validate_cmd->add_option("--only", validate.only, "entries to run (see --list)")->delimiter(',');
  validate_cmd->add_flag("--list", validate.list, "list the entries with their run times");
  validate_cmd->add_option("-o,--output", validate.out_dir, "folder for the runs and the table")
      ->capture_default_str();
  validate_cmd->add_option("--json", validate.json_path, "also write the table to this JSON file");
  validate_cmd->add_option("--threads", validate.threads, "OpenMP threads (0: all cores)");
  validate_cmd->add_flag("--reuse", validate.reuse,
                         "keep the runs already completed in the output folder (same built-in "
                         "case and overrides) instead of running them again, and continue "
                         "the ones that stopped part-way from their checkpoints");

  auto* cases_cmd = app.add_subcommand("cases", "list the built-in cases");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  log_to_console(quiet);
  run.quiet = quiet;
  run.plots = !no_plots;
  try {
    if (*cases_cmd) {
      for (const auto& c : netsph::builtin_cases()) fmt::print("builtin:{}\n", c.name);
      return 0;
    }
    if (*check_cmd) return check_command(check);
    if (*plot_cmd) return plot_command(plot_dir, shape_times);
    if (*net_cmd) return net_command(net);
    if (*validate_cmd) {
      validate.quiet = quiet;
      return validate_command(validate);
    }
    if (*bench_cmd) {
      bench.sizes = parse_sizes(sizes);
      return bench_command(bench);
    }
    return run_command(run);  // `netsph` alone runs the default case too
  } catch (const netsph::Error& e) {
    spdlog::error("{}", e.what());
    return 1;
  } catch (const std::exception& e) {
    spdlog::error("internal error: {}", e.what());
    return 2;
  }
}
