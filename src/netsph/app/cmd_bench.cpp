// `netsph bench`: the fixed benchmark case (cases/dambreak3d.toml, docs/PERFORMANCE.md) at a
// few particle counts, reported as full symplectic particle-steps per second over all
// particles (walls included) and bytes per particle.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "netsph/app/commands.hpp"
#include "netsph/core/error.hpp"
#include "netsph/io/atomic_file.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph::app {
namespace {

constexpr double kReferenceDp = 0.0075;

CaseSpec bench_case(double dp) {
  CaseChoice c;
  c.path = "builtin:dambreak3d";
  c.overrides = {fmt::format("simulation.dp={:.9g}", dp)};
  return load_case(c);
}

struct BenchRow {
  double target = 0, dp = 0;
  std::size_t particles = 0;
  int steps = 0;
  double wall_s = 0, rate = 0, bytes = 0;
  std::optional<DevicePhaseTimes> phases;
  double profiled_wall_s = 0;
};

/// Wall seconds of `steps` more steps of `sim`. On the device each step ends with reductions
/// copied back to the host, so the clock sees finished work.
double timed_steps(Simulation& sim, int steps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) sim.step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Times `steps` more steps of `sim` with the device step's phase profile on.
void profile_phases(Simulation& sim, int steps, BenchRow& row) {
  sim.set_device_profiling(true);
  row.profiled_wall_s = timed_steps(sim, steps);
  row.phases = sim.device_phase_times();
  sim.set_device_profiling(false);
}

void print_phases(const BenchRow& row) {
  const DevicePhaseTimes& t = *row.phases;
  fmt::print("    phases over {} profiled steps ({:.3f} s; timed phases {:.3f} s):\n", row.steps,
             row.profiled_wall_s, t.total());
  fmt::print("    {:<16} {:>12} {:>7} {:>12}\n", "phase", "ms/step", "share", "calls/step");
  for (std::size_t k = 0; k < kDevicePhaseNames.size(); ++k) {
    if (t.calls[k] == 0) continue;
    fmt::print("    {:<16} {:>12.3f} {:>6.1f}% {:>12.1f}\n", kDevicePhaseNames[k],
               1e3 * t.seconds[k] / row.steps, 100 * t.seconds[k] / t.total(),
               static_cast<double>(t.calls[k]) / row.steps);
  }
}

}  // namespace

int bench_command(const BenchArgs& args) {
  const std::string backend = resolve_backend(args.backend);
  const int threads = apply_threads(args.threads);
  if (args.steps < 1) throw Error("--steps", "must be >= 1");
  if (args.profile && backend == "cpu")
    throw Error("--profile",
                "the phase profile is of the device step (--backend cuda or "
                "host-device); profile the CPU step with perf (docs/PERFORMANCE.md)");
  // Particle count at the reference dp, to pick dp for each requested size (N ~ dp^-3).
  const double n_ref = static_cast<double>(Simulation(bench_case(kReferenceDp)).particles().size());
  const auto dp_for = [n_ref](double target) { return kReferenceDp * std::cbrt(n_ref / target); };
  // Every size and the output file are checked before the first run, which may take minutes.
  for (double target : args.sizes) {
    if (!(target >= 1000)) throw Error("--sizes", "particle counts must be >= 1000");
    if (!std::isfinite(target)) throw Error("--sizes", "particle counts must be finite");
    try {
      check_case_fits_memory(bench_case(dp_for(target)), backend);
    } catch (const Error& e) {
      // The memory check speaks of the case: say first that the size is what does not fit.
      throw Error("--sizes",
                  fmt::format("{:.3g} particles do not fit this machine: {}", target, e.message()));
    }
  }
  if (!args.json_path.empty()) {
    const std::filesystem::path folder = std::filesystem::absolute(args.json_path).parent_path();
    if (!std::filesystem::is_directory(folder))
      throw Error("--json", "the folder " + folder.string() + " does not exist");
    if (std::filesystem::is_directory(args.json_path))
      throw Error("--json", args.json_path + " is a folder; give a file name");
  }
  spdlog::info(
      "bench: 3D dam break (cases/dambreak3d.toml), backend {}, {} threads, {} steps "
      "after one warm-up step",
      backend, threads, args.steps);
  fmt::print("{:>12} {:>10} {:>7} {:>9} {:>18} {:>14}\n", "particles", "dp [m]", "steps",
             "wall [s]", "particle-steps/s", "bytes/particle");
  std::vector<BenchRow> rows;
  for (double target : args.sizes) {
    BenchRow row;
    row.target = target;
    row.dp = dp_for(target);
    Simulation sim(bench_case(row.dp), step_backend(backend));
    sim.step();  // warm-up: sizes every array, first sort
    row.wall_s = timed_steps(sim, args.steps);
    row.particles = sim.particle_count();
    row.bytes = sim.bytes_per_particle();
    row.steps = args.steps;
    row.rate = static_cast<double>(row.particles) * args.steps / row.wall_s;
    fmt::print("{:>12} {:>10.5f} {:>7} {:>9.2f} {:>18.3e} {:>14.0f}\n", row.particles, row.dp,
               row.steps, row.wall_s, row.rate, row.bytes);
    if (args.profile) {
      profile_phases(sim, args.steps, row);
      print_phases(row);
    }
    std::fflush(stdout);
    rows.push_back(row);
  }
  if (!args.json_path.empty()) {
    nlohmann::json j;
    j["case"] = "dambreak3d";
    j["backend"] = backend;
    j["threads"] = threads;
    for (const auto& r : rows) {
      nlohmann::json run{{"particles", r.particles},
                         {"dp_m", r.dp},
                         {"steps", r.steps},
                         {"wall_s", r.wall_s},
                         {"particle_steps_per_s", r.rate},
                         {"bytes_per_particle", r.bytes}};
      if (r.phases) {
        run["profiled_wall_s"] = r.profiled_wall_s;
        for (std::size_t k = 0; k < kDevicePhaseNames.size(); ++k) {
          run["phases"][std::string(kDevicePhaseNames[k])] = {
              {"ms_per_step", 1e3 * r.phases->seconds[k] / r.steps},
              {"calls_per_step", static_cast<double>(r.phases->calls[k]) / r.steps}};
        }
      }
      j["runs"].push_back(run);
    }
    write_file_atomic(args.json_path, j.dump(2) + "\n");
  }
  return 0;
}

}  // namespace netsph::app
