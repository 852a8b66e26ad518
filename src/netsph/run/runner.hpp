#pragma once
// Runs a Simulation to its end time with outputs and progress, and turns every way a run can
// end (completed, unstable, interrupted by Ctrl-C) into a written summary.json and a report.
// Whatever happens, the snapshots and series rows written so far stay, and a last snapshot of
// the final state is added.
#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "netsph/run/run_stepper.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph {

struct RunOptions {
  std::filesystem::path out_dir = "out";
  bool progress = true;         ///< show progress on stderr
  bool plain_progress = false;  ///< periodic lines even on a terminal
  std::int64_t max_steps = 0;   ///< stop after this many steps (0: run to end_time)
  /// Goes into every checkpoint with the simulation's state: the case as run (texts
  /// "case.toml", "case.source", "case.overrides"), so that `netsph run --restart DIR` needs
  /// nothing else.
  CheckpointData case_record;
  /// A checkpoint the simulation was restored from: the outputs continue it.
  const CheckpointData* resume = nullptr;
};

/// The case as run, for RunOptions::case_record: its TOML text, where it came from (a file
/// or builtin:<name>) and the --set overrides, one per line.
CheckpointData case_record(const std::string& toml, const std::string& source,
                           const std::vector<std::string>& overrides);
/// The overrides a checkpoint's case record holds.
std::vector<std::string> recorded_overrides(const CheckpointData& checkpoint);

/// The checkpoint file of a run folder.
inline std::filesystem::path checkpoint_path(const std::filesystem::path& run_dir) {
  return run_dir / "checkpoint.h5";
}

struct RunReport {
  std::string status;   ///< "completed", "unstable", "interrupted", "step limit"
  std::string message;  ///< diagnosis when not completed
  std::int64_t steps = 0;
  double sim_time = 0;  ///< s
  double wall_s = 0;
  double particle_steps_per_s = 0;
  double bytes_per_particle = 0;
  int snapshots = 0;
  std::vector<std::string> warnings;
  nlohmann::json summary;       ///< what summary.json holds
  double checkpoint_time = -1;  ///< simulated time of the last checkpoint written, s (-1: none)
  bool ok() const { return status == "completed" || status == "step limit"; }
};

RunReport run_simulation(Simulation& sim, const RunOptions& options);
/// The same for any stepper (run/run_stepper.hpp): a distributed run's processes all call
/// it; the one holding the view writes the outputs and gets the whole report, the others a
/// report without summary.
RunReport run_stepped(RunStepper& stepper, const RunOptions& options);

/// Whether a run at time t has reached end_time (within the round-off of the summed steps):
/// the run loop's test, and a restart's.
inline bool run_has_ended(double t, double end_time) {
  return !(t < end_time * (1 - 1e-12));
}

/// Async-signal-safe: asks a running simulation to stop after the current step; `signal`, the
/// signal that asked (0: none), is named in the run's message.
void request_stop(int signal = 0);
bool stop_requested();
/// What asked the run to stop, for its message: "SIGHUP (its terminal or ssh session closed)".
std::string stop_cause();

}  // namespace netsph
