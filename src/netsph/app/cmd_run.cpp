#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "netsph/app/commands.hpp"
#include "netsph/app/logging.hpp"
#include "netsph/app/plots.hpp"
#include "netsph/app/run_results.hpp"
#include "netsph/app/scene_report.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"
#include "netsph/distributed/distributed_stepper.hpp"
#include "netsph/distributed/mpi_collectives.hpp"
#include "netsph/distributed/scene_parts.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/io/output_folder.hpp"
#include "netsph/run/runner.hpp"
#include "netsph/run/standalone_net_run.hpp"

namespace netsph::app {
namespace {

/// Logs what the snapshots will take and warns when the outputs (snapshots and checkpoint) are
/// more than the disk holds free: a run that fills the disk fails at its next write, hours in.
void warn_if_outputs_overfill(const Simulation& sim, OutputParticles& particles,
                              const std::filesystem::path& out) {
  const bool snapshots = sim.spec().output.snapshots;
  const SnapshotVolume v = snapshot_volume(sim, particles);
  if (snapshots) spdlog::info("{}", describe_snapshots(sim, v));
  if (snapshots && v.particles == 0 && sim.spec().output.snapshot_region) {
    spdlog::warn(
        "output.snapshot_region holds no particle at the start: the snapshots stay empty until "
        "particles move into it (check its min and max against the water and the walls)");
  }
  const double checkpoint = checkpoint_bytes(particles.count(ParticleSelection::All));
  warn_if_output_overfills((snapshots ? v.total() : 0) + checkpoint,
                           snapshots ? "snapshots and checkpoint" : "checkpoint", out);
}
extern "C" void on_interrupt(int signal) {
  request_stop(signal);
}

/// While it lives, Ctrl-C (SIGINT), SIGTERM (a scheduler ending the job) and SIGHUP (the
/// terminal or its ssh session closed) end the run after the current step, with its final
/// outputs and checkpoint, rather than kill it.
class StopOnSignals {
 public:
  StopOnSignals() {
    for (const int s : kSignals) std::signal(s, on_interrupt);
  }
  ~StopOnSignals() {
    for (const int s : kSignals) std::signal(s, SIG_DFL);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
};

/// The case a run folder's summary.json says its run ran (none without a readable one: a run
/// killed before its end writes none).
struct FolderCase {
  std::string name, source;
  std::vector<std::string> sets;  ///< its --set overrides
};
std::optional<FolderCase> case_of_run_folder(const std::filesystem::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) return std::nullopt;
  const nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
  if (s.is_discarded() || !s.is_object() || !s.contains("case")) return std::nullopt;
  const nlohmann::json& c = s["case"];
  if (!c.is_object() || !c.contains("name") || !c["name"].is_string() || !c.contains("source") ||
      !c["source"].is_string()) {
    return std::nullopt;
  }
  FolderCase f{c["name"].get<std::string>(), c["source"].get<std::string>(), {}};
  if (c.contains("overrides") && c["overrides"].is_array()) {
    for (const nlohmann::json& o : c["overrides"])
      if (o.is_string()) f.sets.push_back(o.get<std::string>());
  }
  return f;
}

/// With --overwrite, a new run into a folder that holds an earlier run replaces it: said, and
/// done whole at once. The earlier run's checkpoint.h5 and summary.json go now, so that a new
/// run stopped early never leaves the old checkpoint and summary beside its own series and
/// snapshots (a --restart would then continue the wrong run); its snapshots go when the
/// snapshot writer starts, series.csv and log.txt are written afresh.
void replace_earlier_run(const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  const fs::path summary = out / "summary.json", checkpoint = checkpoint_path(out);
  std::error_code ec;
  const std::optional<FolderCase> earlier = case_of_run_folder(out);
  const std::string what =
      earlier ? fmt::format("an earlier run of case '{}'", earlier->name) : "an earlier run";
  spdlog::warn(
      "{} holds {}: --overwrite: this run replaces it (its snapshots, series.csv, "
      "summary.json and checkpoint.h5)",
      out.string(), what);
  fs::remove(summary, ec);
  fs::remove(checkpoint, ec);
}
}  // namespace

/// A standalone net case: no particles, no backend; the knot-spring model in a current.
int run_net_only(const CaseSpec& spec, const std::filesystem::path& out, bool quiet) {
  spdlog::info("standalone net run (no fluid): {} net(s), output folder {}", spec.nets.size(),
               std::filesystem::absolute(out).string());
  NetRunOptions opt;
  opt.out_dir = out;
  opt.progress = !quiet;
  // Ctrl-C ends the run at its next series row with every output written, as an SPH run's.
  opt.stop = stop_requested;
  const NetRunReport r = [&] {
    const StopOnSignals stop_on_signals;
    return run_standalone_nets(spec, opt);
  }();
  for (const NetRunSummary& n : r.nets) {
    if (!std::isfinite(n.mean_force.x)) {
      spdlog::info("net '{}': {} knots, {} twines; largest deflection {:.4g} m", n.name, n.knots,
                   n.twines, n.max_deflection);
      continue;  // the means were not measured: r.warnings says why
    }
    spdlog::info(
        "net '{}': {} knots, {} twines; over {:.3g}-{:.3g} s: drag {:.4g} N "
        "(force [{:.4g}, {:.4g}, {:.4g}] N), {} on the outline, largest "
        "deflection {:.4g} m",
        n.name, n.knots, n.twines, r.window[0], r.window[1],
        norm(spec.current.velocity) > 0
            ? dot(n.mean_force, spec.current.velocity / norm(spec.current.velocity))
            : 0.0,
        n.mean_force.x, n.mean_force.y, n.mean_force.z,
        std::isfinite(n.drag_coefficient) ? fmt::format("Cd {:.4f}", n.drag_coefficient)
                                          : std::string("Cd undefined (no current)"),
        n.max_deflection);
  }
  spdlog::info(
      "{}: t = {:.6g} s, {} knot sub-steps, {:.2f} s wall; outputs: series.csv, "
      "summary.json, <net>.vtk.series, knots_<net>.csv, profile_<net>.csv",
      r.status, r.sim_time, r.substeps, r.wall_s);
  for (const std::string& w : r.warnings) spdlog::warn("{}", w);
  if (r.status == "unstable") {
    spdlog::error("the net became unstable: {}", r.message);
    return 3;
  }
  if (r.status == "interrupted") {
    spdlog::warn(
        "{}; the outputs hold the run up to there (a standalone run has no checkpoint: "
        "run it again to go further)",
        r.message);
    return 130;
  }
  return 0;
}

namespace {

/// The dotted key of a --set, without the blanks --set allows around its parts.
std::string override_key(const std::string& set) {
  std::string key;
  for (const char c : set.substr(0, set.find('=')))
    if (c != ' ' && c != '\t') key += c;
  return key;
}

/// A restart continues the checkpoint's particles, bodies and nets: a --set may change how long
/// and in what steps it runs, and what it writes, but not the model they were made with (a new
/// dp would step the old particles with another mass and kernel).
bool restart_may_set(const std::string& set) {
  const std::string key = override_key(set);
  for (const char* allowed : {"simulation.end_time", "simulation.cfl", "simulation.dt_min",
                              "simulation.dt_max", "simulation.max_lost_fraction"}) {
    if (key == allowed) return true;
  }
  return key.rfind("output.", 0) == 0;
}

void check_restart_override(const std::string& set) {
  if (restart_may_set(set)) return;
  const std::string key = override_key(set);
  throw Error("--set " + set,
              "a restart continues the checkpoint's particles, so it may change only the run's "
              "length and time stepping (simulation.end_time, cfl, dt_min, dt_max, "
              "max_lost_fraction) and its outputs ([output] keys); to change '" +
                  key + "', start a new run");
}

/// The case of a restart: as its checkpoint recorded it, with the new --set overrides after
/// the old ones (so that, e.g., simulation.end_time can be raised to run longer).
CaseSpec restart_case(const CheckpointData& c, const std::vector<std::string>& more,
                      std::vector<std::string>& overrides) {
  for (const std::string& set : more) check_restart_override(set);
  overrides = recorded_overrides(c);
  overrides.insert(overrides.end(), more.begin(), more.end());
  // A case file without simulation.name is named after the file's stem, as when it was read
  // first (read_case_file); a built-in case after its source.
  const std::string& source = c.text_of("case.source");
  const std::string name =
      source.rfind("builtin:", 0) == 0 ? source : std::filesystem::path(source).stem().string();
  return read_case_string(c.text_of("case.toml"), source, overrides, name);
}

/// A case and its --set overrides, for messages: "case 'name' (source, --set a=1 --set b=2)".
std::string describe_case(const std::string& name, const std::string& source,
                          const std::vector<std::string>& sets) {
  std::string text = "case '" + name + "' (" + source;
  for (const std::string& set : sets) text += " --set " + set;
  return text + ")";
}

/// A restart appends to the outputs of the folder it continues, so the folder's checkpoint.h5
/// must be the one its run wrote: one copied in from another run's folder would continue that
/// other run into this folder's series.csv, snapshots and summary. The folder's summary.json,
/// written at the end of every run and restart, names the case it ran; the checkpoint records
/// its own (`recorded`: the --set overrides it was run with). They must be the same case from
/// the same source, with the same overrides but for those one of them gained at a later
/// restart, which only a restart may set (a checkpoint of a restart killed before it wrote its
/// summary; the summary of a restart that failed before its first checkpoint). A folder without
/// a readable summary.json (a run killed before its end) cannot be checked: its checkpoint is
/// taken as its own.
void check_checkpoint_is_the_folders(const std::string& dir, const CaseSpec& spec,
                                     const std::vector<std::string>& recorded) {
  const std::optional<FolderCase> folder = case_of_run_folder(dir);
  if (!folder) return;
  const std::filesystem::path summary = std::filesystem::path(dir) / "summary.json";
  const std::string& name = folder->name;
  const std::string& source = folder->source;
  const std::vector<std::string>& sets = folder->sets;
  const std::size_t common = std::min(sets.size(), recorded.size());
  const std::vector<std::string>& longer = sets.size() > recorded.size() ? sets : recorded;
  const bool same_sets = std::equal(sets.begin(), sets.begin() + common, recorded.begin()) &&
                         std::all_of(longer.begin() + common, longer.end(), restart_may_set);
  if (name == spec.simulation.name && source == spec.source && same_sets) return;
  throw Error(
      "--restart",
      fmt::format("{} is not the checkpoint of the run in {}: it continues {}, but {} is of "
                  "{}; a restart would append the one run to the other's series.csv and "
                  "snapshots. Put back the checkpoint.h5 this folder's run wrote, or restart the "
                  "folder the checkpoint came from (if summary.json is left over from an earlier "
                  "run in this folder, move it aside)",
                  checkpoint_path(dir).string(), dir,
                  describe_case(spec.simulation.name, spec.source, recorded), summary.string(),
                  describe_case(name, source, sets)));
}

int exit_status(const RunReport& r) {
  if (r.status == "unstable") return 3;
  if (r.status == "output failed") return 1;
  if (r.status == "interrupted") return 130;
  return 0;
}

/// What a finished run tells its user; the exit status.
int report_run(const RunReport& r, const std::filesystem::path& out, bool plots) {
  for (const auto& w : r.warnings) spdlog::warn("{}", w);
  log_run_results(r.summary);
  spdlog::info(
      "{}: t = {:.6g} s in {} steps, {:.1f} s wall, {:.3g} particle-steps/s, {:.0f} B/particle",
      r.status, r.sim_time, r.steps, r.wall_s, r.particle_steps_per_s, r.bytes_per_particle);
  const bool gauges = !r.summary.value("gauges", nlohmann::json::array()).empty();
  if (r.snapshots > 0) {
    spdlog::info("outputs: {} snapshot(s) in {}/particles.xdmf, series.csv, {}summary.json",
                 r.snapshots, std::filesystem::absolute(out).string(),
                 gauges ? "gauges.csv, " : "");
  } else {
    spdlog::info("outputs: series.csv, {}summary.json in {} (no particle snapshots)",
                 gauges ? "gauges.csv, " : "", std::filesystem::absolute(out).string());
  }
  if (plots) make_plots(out);  // also after a failure: the plots show what went wrong
  if (r.checkpoint_time >= 0 && r.status != "completed") {
    spdlog::info("continue with: netsph run --restart {} (checkpoint at t = {:.6g} s)",
                 out.string(), r.checkpoint_time);
  }
  if (r.status == "unstable") {
    spdlog::error("the simulation became unstable: {}", r.message);
    spdlog::error("the outputs written up to that point, and a final snapshot, are in {}",
                  out.string());
  }
  if (r.status == "interrupted") spdlog::warn("{}", r.message);
  if (r.status == "output failed") {
    spdlog::error("the run's outputs could not be written: {}", r.message);
    spdlog::error("what was written before is kept in {}{}", out.string(),
                  r.checkpoint_time >= 0 ? " (with its last complete checkpoint)" : "");
  }
  return exit_status(r);
}

}  // namespace

int run_command(const RunArgs& args) {
  if (args.max_steps < 0) throw Error("--max-steps", "must be >= 0 (0: no limit)");
  // Under mpirun (more than one process) the run is distributed over the processes
  // (distributed/); netsph touches MPI only then.
  std::optional<MpiSession> mpi;
  std::optional<MpiCollectives> coll;
  if (launched_by_mpi()) {
    mpi.emplace();
    coll.emplace();
    if (coll->size() == 1) coll.reset();  // one process: the plain run
    if (coll && coll->rank() > 0) spdlog::set_level(spdlog::level::warn);  // process 0 reports
  }
  const bool reporting = !coll || coll->rank() == 0;
  const bool restart = args.restart_dir.has_value();
  // `--restart ""` (an unset shell variable, say) would otherwise start the default case.
  if (restart && args.restart_dir->empty()) {
    throw Error("--restart",
                "give a run folder: the folder of the run to continue (its -o, by default "
                "out/<case name>), which holds its checkpoint.h5");
  }
  const std::string restart_dir = args.restart_dir.value_or("");
  if (restart && !args.case_choice.path.empty()) {
    throw Error("--restart",
                "give either a case or --restart DIR: a restart reads its case from "
                "the checkpoint (add --set to change a key, e.g. the end time)");
  }
  if (restart && !args.out_dir.empty()) {
    throw Error("--restart",
                "a restart continues in the folder it restarts (" + restart_dir +
                    "): -o does not apply; copy the folder first to keep the original");
  }
  if (restart && args.overwrite) {
    throw Error("--overwrite",
                "a restart continues the run in its folder and replaces nothing: leave out "
                "--overwrite");
  }
  CheckpointData checkpoint, record;
  std::vector<std::string> overrides = args.case_choice.overrides;
  CaseSpec spec;
  if (restart) {
    // A process of a distributed run reads only the particles of its part of the case, once
    // the case (in the checkpoint) says where that lies; the outputs' view holds none.
    const std::filesystem::path file = checkpoint_path(restart_dir);
    checkpoint = coll ? read_checkpoint_file(file, Simulation::particle_rows(AxisRange::nothing()))
                      : read_checkpoint_file(file);
    if (!checkpoint.unchecked.empty()) spdlog::warn("{}: {}", file.string(), checkpoint.unchecked);
    spec = restart_case(checkpoint, args.case_choice.overrides, overrides);
    check_checkpoint_is_the_folders(restart_dir, spec, recorded_overrides(checkpoint));
    const double at = checkpoint.real("sim.time");
    if (run_has_ended(at, spec.simulation.end_time)) {
      throw Error("--restart",
                  fmt::format("the checkpoint in {} is at t = {:.6g} s, and the case ends at "
                              "simulation.end_time = {:.6g} s: nothing is left to run; give a "
                              "later end, e.g. --set simulation.end_time={:.3g}",
                              restart_dir, at, spec.simulation.end_time, 2 * at));
    }
    if (coll) {
      const AxisRange part = set_up_region(spec, coll->size(), coll->rank());
      checkpoint = read_checkpoint_file(file, Simulation::particle_rows(part));
    }
    record =
        case_record(checkpoint.text_of("case.toml"), checkpoint.text_of("case.source"), overrides);
  } else {
    spec = load_case(args.case_choice);
    const auto [text, source] = case_text(args.case_choice);
    record = case_record(text, source, overrides);
  }
  const std::string backend = resolve_backend(args.backend, static_cast<bool>(coll));
  const int threads = apply_threads(args.threads);
  const std::filesystem::path out = restart ? std::filesystem::path(restart_dir)
                                    : args.out_dir.empty()
                                        ? std::filesystem::path("out") / spec.simulation.name
                                        : std::filesystem::path(args.out_dir);
  // A run never destroys an earlier run's results unasked: without --overwrite they move aside
  // to <folder>.<n> (the first free n) and this run gets the folder afresh, so the same
  // command typed twice works and out/<name> always holds the latest run (docs/ARCHITECTURE.md).
  const std::string where = restart ? "--restart" : args.out_dir.empty() ? "output folder" : "-o";
  std::optional<std::filesystem::path> moved_to;
  std::optional<FolderCase> moved_case;
  if (reporting && !restart && !args.overwrite) {
    moved_case = case_of_run_folder(out);
    moved_to = move_earlier_run_aside(out, where);
  }
  const bool replace = reporting && !restart && args.overwrite && holds_earlier_run(out);
  // Every process alike, so that all stop together when the folder cannot be made.
  create_output_folder(out, where);
  if (reporting) log_also_to_file(out / "log.txt", restart);
  if (replace) replace_earlier_run(out);
  if (moved_to) {
    spdlog::warn(
        "{} held {}: moved to {} (nothing deleted; add --overwrite to replace an "
        "earlier run instead)",
        out.string(),
        moved_case ? fmt::format("an earlier run of case '{}'", moved_case->name)
                   : std::string("an earlier run's results"),
        moved_to->string());
  }

  spdlog::info("netsph {} run: case '{}' from {}", NETSPH_VERSION, spec.simulation.name,
               spec.source);
  if (coll && (spec.net_only() || step_backend(backend) != StepBackend::Cpu)) {
    throw Error("mpirun", spec.net_only()
                              ? "a standalone net case (no fluid) runs as one process"
                              : "a distributed run needs --backend cpu: the device-shaped step "
                                "(cuda, host-device) runs in one process (one GPU per process is "
                                "not supported yet)");
  }
  if (spec.net_only()) return run_net_only(spec, out, args.quiet);
  spdlog::info("backend {}, {} OpenMP threads{}, output folder {}", backend, threads,
               coll ? fmt::format(" in each of {} MPI processes", coll->size()) : "",
               std::filesystem::absolute(out).string());
  std::unique_ptr<Simulation> sim;
  std::unique_ptr<RunStepper> stepper;
  const auto built = std::chrono::steady_clock::now();
  if (coll) {
    check_case_fits_memory(spec, backend, &*coll);
    stepper = std::make_unique<DistributedStepper>(spec, *coll, restart ? &checkpoint : nullptr,
                                                   RebalancePolicy{args.rebalance_every});
  } else {
    check_case_fits_memory(spec, backend);
    sim = std::make_unique<Simulation>(spec, step_backend(backend));
    if (restart) sim->restore_state(checkpoint);
    stepper = std::make_unique<SingleStepper>(*sim);
  }
  // The report reads the particles' counts, from every process in a distributed run.
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count();
  if (const Simulation* view = stepper->view()) {
    log_scene(*view, stepper->particles(), setup_s);
    warn_if_outputs_overfill(*view, stepper->particles(), out);
    stepper->outputs_written();
  } else {
    stepper->serve_outputs();
  }
  if (restart) {
    spdlog::info("restarting from {} at t = {:.6g} s (step {}), to end_time = {:.6g} s",
                 checkpoint_path(out).string(), stepper->time(), stepper->steps(),
                 spec.simulation.end_time);
  }

  const StopOnSignals stop_on_signals;
  RunOptions opt;
  opt.out_dir = out;
  opt.progress = !args.quiet;
  opt.plain_progress = args.plain_progress;
  opt.max_steps = args.max_steps;
  opt.case_record = std::move(record);
  opt.resume = restart ? &checkpoint : nullptr;
  int status = 0;
  try {
    const RunReport r = run_stepped(*stepper, opt);
    status = reporting ? report_run(r, out, args.plots) : exit_status(r);
  } catch (const std::exception& e) {
    // One process's error (an output that cannot be written) would leave the others waiting
    // in their next collective step: end them all.
    if (!coll || coll->size() == 1) throw;
    spdlog::error("process {}: {}", coll->rank(), e.what());
    MpiSession::abort(2);
  }
  return status;
}

}  // namespace netsph::app

namespace netsph::app {

int plot_command(const std::string& run_dir, const std::string& shape_times) {
  if (!std::filesystem::exists(std::filesystem::path(run_dir) / "summary.json")) {
    throw Error(run_dir, "not a netsph run folder (no summary.json)");
  }
  return make_plots(run_dir, shape_times) ? 0 : 1;
}

}  // namespace netsph::app
