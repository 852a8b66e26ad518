#pragma once
// The netsph subcommands. Each returns the process exit code; errors are thrown as
// netsph::Error and printed by main().
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "netsph/case/case_spec.hpp"
#include "netsph/distributed/collectives.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph::app {

/// Where the case comes from: a path, "builtin:<name>", or empty for the default case.
struct CaseChoice {
  std::string path;
  std::vector<std::string> overrides;  ///< --set key=value
};

CaseSpec load_case(const CaseChoice& choice);
/// The TOML text a choice reads (the file's content or the built-in case's), and its source.
std::pair<std::string, std::string> case_text(const CaseChoice& choice);

struct RunArgs {
  CaseChoice case_choice;
  std::string out_dir;  ///< empty: out/<case name>
  std::string backend = "auto";
  int threads = 0;  ///< 0: OpenMP default
  std::int64_t max_steps = 0;
  bool plain_progress = false;
  bool quiet = false;
  bool plots = true;  ///< PNG plots at the end (when matplotlib is there)
  /// Replace an earlier run in the output folder instead of moving it aside to <folder>.<n>.
  bool overwrite = false;
  /// Continue the run in this folder from its checkpoint. Optional rather than empty when not
  /// given, so that `--restart ""` (an unset shell variable) is an error, not a new run.
  std::optional<std::string> restart_dir;
  /// Distributed runs: steps between checks of the slabs' balance (0: never cut again;
  /// RebalancePolicy).
  int rebalance_every = 20;
};
int run_command(const RunArgs& args);

/// `netsph plot DIR`: PNG plots of a run folder.
int plot_command(const std::string& run_dir, const std::string& shape_times);

struct CheckArgs {
  CaseChoice case_choice;
  int threads = 0;
  int sample_steps = 20;
  std::string backend = "auto";  ///< whose memory and speed the check reports
  std::string out_dir;           ///< where the run would write (empty: out/<case name>)
};
int check_command(const CheckArgs& args);

struct BenchArgs {
  std::vector<double> sizes{1e5, 2.4e5, 1e6};  ///< target particle counts
  int steps = 10;
  int threads = 0;
  std::string backend = "auto";
  std::string json_path;
  /// Also time the device step's phases (after the timed steps, over as many again).
  bool profile = false;
};
int bench_command(const BenchArgs& args);

struct NetArgs {
  CaseChoice case_choice;
  std::string out_dir;  ///< empty: out/<case name>
};
int net_command(const NetArgs& args);

struct ValidateArgs {
  bool quick = false;
  bool list = false;
  std::vector<std::string> only;  ///< entry names
  std::string out_dir = "out/validate";
  std::string json_path;
  int threads = 0;
  bool quiet = false;
  bool reuse = false;
};
int validate_command(const ValidateArgs& args);

/// Applies --threads (0 keeps the OpenMP default) and returns the thread count in use.
int apply_threads(int threads);

/// Checks --backend; returns the backend that will run: "cpu", "cuda" (throws when netsph was
/// built without CUDA or finds no usable device) or "host-device" (the CUDA backend's kernels
/// on the CPU, slow: for checking). "auto" is "cuda" where a CUDA device is usable and the run
/// is not `distributed` (under mpirun), else "cpu".
std::string resolve_backend(const std::string& requested, bool distributed = false);
/// The Simulation backend of a resolved name.
StepBackend step_backend(const std::string& resolved);
/// Refuses a case whose particles (estimated from its boxes, setup/memory_preflight.hpp)
/// cannot fit the memory available to one process, naming both; warns when it is close. With
/// `coll` (a distributed run; collective) each process's share, summed over the processes of
/// each machine (distributed/memory_share.hpp).
void check_case_fits_memory(const CaseSpec& spec, const std::string& backend,
                            Collectives* coll = nullptr);

}  // namespace netsph::app
