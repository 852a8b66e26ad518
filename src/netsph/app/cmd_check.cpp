#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/app/scene_report.hpp"
#include "netsph/net/net_generator.hpp"
#include "netsph/run/output_schedule.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph::app {

namespace {

/// "12 min 05 s"; days or years past a day, so that end_time = 1e300 does not print a number
/// of minutes 300 digits long.
std::string wall_estimate(double seconds) {
  if (!std::isfinite(seconds)) return "forever";
  if (seconds < 86400) {
    return fmt::format("{:.0f} min {:02.0f} s", std::floor(seconds / 60), std::fmod(seconds, 60.0));
  }
  const double days = seconds / 86400;
  return days < 365 ? fmt::format("{:.3g} days", days) : fmt::format("{:.3g} years", days / 365.25);
}

}  // namespace

int check_command(const CheckArgs& args) {
  if (args.sample_steps < 1) throw Error("--sample-steps", "must be >= 1 (default 20)");
  const CaseSpec spec = load_case(args.case_choice);
  const int threads = apply_threads(args.threads);
  if (spec.net_only()) {
    // The nets are what a standalone case builds: their generator's rules (a whole number of
    // meshes a side, at most 10^4) are checked here too, not first by `net` or `run`.
    for (const NetSpec& net : spec.nets) generate_net(net, net_environment(spec));
    spdlog::info("case '{}' from {}: valid", spec.simulation.name, spec.source);
    spdlog::info(
        "standalone net case: {} net(s), no fluid; `netsph net` reports knots, twines "
        "and the knot sub-step, `netsph run` runs it",
        spec.nets.size());
    return 0;
  }
  spdlog::info("case '{}' from {}: valid", spec.simulation.name, spec.source);
  const std::string backend = resolve_backend(args.backend);
  check_case_fits_memory(spec, backend);
  const auto built = std::chrono::steady_clock::now();
  Simulation sim(spec, step_backend(backend));
  SimulationParticles particles(sim);
  log_scene(sim, particles,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count());

  // Before the sample steps: from t = 0, the whole run's snapshots.
  const SnapshotVolume snapshots = snapshot_volume(sim, particles);

  // A short timing sample: the first step also sizes every work array, so memory is known.
  const auto t0 = std::chrono::steady_clock::now();
  sim.step();
  const double dt0 = sim.last_dt();
  const auto lim = sim.diagnostics().dt_limits;
  int n = 1;
  double wall = 0;
  while (n < std::max(args.sample_steps, 2)) {
    sim.step();
    ++n;
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (wall > 20) break;  // enough to estimate
  }
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double per_step = wall / n;
  const double mean_dt = sim.time() / n;
  const double n_total = spec.simulation.end_time / mean_dt;
  const double np = static_cast<double>(sim.particles().size());

  spdlog::info("memory ({} backend): {:.0f} bytes/particle, {:.1f} MiB in all", backend,
               sim.bytes_per_particle(), sim.bytes_per_particle() * np / (1024.0 * 1024.0));
  spdlog::info(
      "initial dt = {:.3g} s (CFL {:g}; force limit {:.3g} s, acoustic-viscous limit {:.3g} s)",
      dt0, spec.simulation.cfl, lim.force, lim.acoustic);
  spdlog::info(
      "timing sample: {} steps in {:.2f} s on {} threads = {:.3g} particle-steps/s{}", n, wall,
      threads, np * n / wall,
      backend == "host-device" ? " (the CUDA kernels run on the CPU: not a GPU's speed)" : "");
  spdlog::info(
      "estimate for end_time = {:g} s: about {:.3g} steps, {}, {:.3g} h per simulated second (dt "
      "varies as the flow develops: take this as an order of magnitude)",
      spec.simulation.end_time, n_total, wall_estimate(n_total * per_step),
      per_step / mean_dt / 3600);
  if (spec.output.snapshots) spdlog::info("{}", describe_snapshots(sim, snapshots));
  spdlog::info("a series row every {:g} s", series_interval(spec));
  // The folder the run would write to: its free space against the outputs (issue 46).
  const std::filesystem::path out = args.out_dir.empty()
                                        ? std::filesystem::path("out") / spec.simulation.name
                                        : std::filesystem::path(args.out_dir);
  const double checkpoint = checkpoint_bytes(particles.count(ParticleSelection::All));
  warn_if_output_overfills((spec.output.snapshots ? snapshots.total() : 0) + checkpoint,
                           spec.output.snapshots ? "snapshots and checkpoint" : "checkpoint", out);
  return 0;
}

}  // namespace netsph::app
