#include "netsph/run/runner.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "netsph/io/atomic_file.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/io/progress.hpp"
#include "netsph/run/run_outputs.hpp"

namespace netsph {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_stop_signal{0};  // the signal that asked, 0 when none did

/// For a net whose sinker bar gave some of its reaction at the bar (no water downstream of a
/// share: solver/net_coupling.hpp), what a user should know; empty otherwise.
std::string sinker_reactions_at_bar_warning(const Simulation& sim, const CoupledNet& net) {
  if (net.reactions_at_bar == 0) return {};
  return fmt::format(
      "net '{}': no water {:.3g} m downstream of the sinker bar at {} ({} times, shares x "
      "stages): the bar's reaction went into the water at the bar, where it slows the flow its "
      "drag is sampled from (summary.json: nets[].sinker_reactions_at_bar)",
      net.model.name, net.reaction_offset,
      sim.bodies()[net.first_body + net.first_knot_reacting_at_bar].name, net.reactions_at_bar);
}

/// The warning above, once per net and run, when it first applies.
void warn_sinker_reactions_at_bar(const Simulation& sim, std::vector<char>& warned) {
  for (std::size_t n = 0; n < sim.nets().size(); ++n) {
    if (warned[n]) continue;
    const std::string w = sinker_reactions_at_bar_warning(sim, sim.nets()[n]);
    if (w.empty()) continue;
    spdlog::warn("t = {:.6g} s: {}", sim.time(), w);
    warned[n] = 1;
  }
}

std::vector<std::string> collect_warnings(const Simulation& sim) {
  std::vector<std::string> w = sim.scene().warnings;
  const auto& d = sim.diagnostics();
  if (d.lost_total > 0) {
    const std::string where = describe_lost(d.last_lost);
    w.push_back(fmt::format("{} particles left the domain and were removed{}", d.lost_total,
                            where.empty() ? "" : "; the last to leave: " + where));
  }
  for (const CoupledNet& net : sim.nets()) {
    std::string at_bar = sinker_reactions_at_bar_warning(sim, net);
    if (!at_bar.empty()) w.push_back(std::move(at_bar));
  }
  return w;
}

/// The means over output.force_window that nothing fed: a window shorter than one time step
/// (bodies, nets) or between two samples (probes, which sample every series_every or their own
/// `every`), or a probe that never had fluid in reach. Their keys are left out of summary.json;
/// without a word a script reading them would find nothing, and the log printed zeros. And a
/// point probe whose mean coverage is below 1/2 (mostly in a wall, a body or the air).
std::vector<std::string> window_warnings(const nlohmann::json& summary) {
  std::vector<std::string> w;
  const auto window = [](const nlohmann::json& j) {
    return fmt::format("[{:.6g}, {:.6g}] s", j["window_s"][0].get<double>(),
                       j["window_s"][1].get<double>());
  };
  // A run stopped (or unstable, or cut by --max-steps) before its window is another story
  // than a window too short to hold a step.
  const double ended = summary.value("time", nlohmann::json::object()).value("simulated_s", 0.0);
  const auto why = [&](const nlohmann::json& j) {
    if (ended < j["window_s"][0].get<double>())
      return fmt::format("the run ended at t = {:.6g} s, before output.force_window {}", ended,
                         window(j));
    return fmt::format("no time step fell in output.force_window {} (widen it)", window(j));
  };
  for (const auto& g : summary.value("bodies", nlohmann::json::array())) {
    if (g.value("averaged_over_s", 1.0) > 0) continue;
    w.push_back(fmt::format("force group '{}': {}, so its mean force is not measured",
                            g.value("group", std::string("?")), why(g)));
  }
  for (const auto& n : summary.value("nets", nlohmann::json::array())) {
    if (n.contains("mean_max_deflection_m")) continue;
    w.push_back(fmt::format("net '{}': {}, so its mean deflection and tension are not measured",
                            n.value("name", std::string("?")), why(n)));
  }
  for (const auto& p : summary.value("probes", nlohmann::json::array())) {
    if (p.contains("mean_coverage") && p["mean_coverage"].get<double>() < 0.5) {
      w.push_back(fmt::format(
          "probe '{}': mean coverage {:.3g} over output.force_window {}: the point lies mostly "
          "outside the fluid (in a wall, a body or the air), so its means are those of the few "
          "fluid particles at the edge of its kernel; move it into the water",
          p.value("name", std::string("?")), p["mean_coverage"].get<double>(), window(p)));
    }
    if (p.value("samples", 1) > 0) continue;
    if (ended < p["window_s"][0].get<double>()) {
      w.push_back(fmt::format("probe '{}': {}, so its means are empty",
                              p.value("name", std::string("?")), why(p)));
      continue;
    }
    w.push_back(
        fmt::format("probe '{}': no sample in output.force_window {}: the window lies "
                    "between two samples (every output.series_every, or the probe's "
                    "every) or no fluid came within reach; its means are empty",
                    p.value("name", std::string("?")), window(p)));
  }
  return w;
}

/// The last particles that left the domain, as summary.json lists them.
nlohmann::json lost_json(std::span<const StepDiagnostics::Lost> lost) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& l : lost) {
    j.push_back({{"id", l.id},
                 {"position_m", {l.pos.x, l.pos.y, l.pos.z}},
                 {"velocity_m_s", {l.vel.x, l.vel.y, l.vel.z}}});
  }
  return j;
}

nlohmann::json summary_json(const Simulation& sim, const GlobalMeasures& g, const RunReport& r,
                            const RunOptions& opt, const RunOutputs& outputs, int processes) {
  const CaseSpec& s = sim.spec();
  nlohmann::json j;
  j["netsph_version"] = NETSPH_VERSION;
  j["case"] = {{"name", s.simulation.name}, {"source", s.source}, {"overrides", s.overrides}};
  j["status"] = r.status;
  if (!r.message.empty()) j["message"] = r.message;
  j["model"] = {{"dimensions", s.simulation.dimensions},
                {"dp_m", s.simulation.dp},
                {"h_m", sim.model().kernel.h},
                {"kernel", name_of(s.simulation.kernel)},
                {"sound_speed_m_s", sim.scene().sound_speed},
                {"density_diffusion", name_of(s.fluid.density_diffusion)},
                {"viscosity", name_of(s.fluid.viscosity)}};
  const auto& d = sim.diagnostics();
  j["particles"] = {{"fluid", g.fluid},
                    {"wall", g.walls},
                    {"buffer", g.buffer},
                    {"lost", d.lost_total},
                    {"last_lost", lost_json(d.last_lost)},
                    {"inflow", d.open.entered_fluid},
                    {"outflow", d.open.removed}};
  j["time"] = {{"simulated_s", r.sim_time},
               {"end_time_s", s.simulation.end_time},
               {"steps", r.steps},
               {"last_dt_s", sim.last_dt()}};
  j["performance"] = {{"wall_s", r.wall_s},
                      {"particle_steps_per_s", r.particle_steps_per_s},
                      {"bytes_per_particle", r.bytes_per_particle},
                      {"threads", omp_get_max_threads()},
                      {"processes", processes}};
  j["final_state"] = {{"kinetic_energy_J", g.kinetic_energy},
                      {"fluid_mass_kg", g.fluid_mass},
                      {"max_speed_m_s", g.max_speed},
                      {"min_density", g.min_density},
                      {"max_density", g.max_density}};
  j["outputs"] = {{"folder", std::filesystem::absolute(opt.out_dir).string()},
                  {"snapshots", r.snapshots},
                  {"xdmf", r.snapshots > 0 ? "particles.xdmf" : ""},
                  {"series", "series.csv"}};
  j["bodies"] = outputs.body_summary();
  j["nets"] = outputs.net_summary(sim);
  j["probes"] = outputs.probe_summary();
  j["gauges"] = outputs.gauge_summary();
  j["warnings"] = r.warnings;
  return j;
}

}  // namespace

void request_stop(int signal) {
  if (signal != 0) g_stop_signal.store(signal);
  g_stop.store(true);
}
bool stop_requested() {
  return g_stop.load();
}

std::string stop_cause() {
  switch (g_stop_signal.load()) {
    case SIGINT:
      return "Ctrl-C (SIGINT)";
    case SIGTERM:
      return "SIGTERM (the end of the job, or kill)";
    case SIGHUP:
      return "SIGHUP (its terminal or ssh session closed)";
    default:
      return "a stop request";  // another process's signal, in a distributed run
  }
}

CheckpointData case_record(const std::string& toml, const std::string& source,
                           const std::vector<std::string>& overrides) {
  CheckpointData c;
  c.text["case.toml"] = toml;
  c.text["case.source"] = source;
  std::string lines;
  for (const std::string& o : overrides) lines += o + "\n";
  c.text["case.overrides"] = lines;
  return c;
}

std::vector<std::string> recorded_overrides(const CheckpointData& checkpoint) {
  std::vector<std::string> out;
  std::istringstream in(checkpoint.text_of("case.overrides"));
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

RunReport run_simulation(Simulation& sim, const RunOptions& opt) {
  SingleStepper stepper(sim);
  return run_stepped(stepper, opt);
}

RunReport run_stepped(RunStepper& stepper, const RunOptions& opt) {
  // The process that holds the view writes the outputs (the only process, without MPI); the
  // others step and take part in the outputs' reads of the particles (write_outputs below).
  // Every decision that changes the course of the loop is the same on every process: the
  // time, step count and dt are global, and stop requests are combined.
  const CaseSpec& spec = stepper.spec();
  const double end = spec.simulation.end_time;
  const double start_time = stepper.time();
  stepper.refresh_view();
  const Simulation* view = stepper.view();
  std::optional<RunOutputs> outputs;
  if (view) outputs.emplace(*view, opt.out_dir, spec.output.snapshots, opt.resume);
  // The outputs of one point of the run. When they fail on the view's process, the others
  // stop with its message rather than wait for it in their next step.
  const auto write_outputs = [&stepper, view](const auto& write) {
    if (!view) return stepper.serve_outputs();
    try {
      write(stepper.particles());
    } catch (const std::exception& e) {
      stepper.outputs_failed(e.what());
      throw;
    }
    stepper.outputs_written();
  };
  // Checkpoints every checkpoint_every seconds of simulated time (default: a tenth of the
  // run) and at the end, so that a run that dies loses at most that much.
  const double checkpoint_every =
      spec.output.checkpoint_every > 0 ? spec.output.checkpoint_every : end / 10;
  double next_checkpoint = stepper.time() + checkpoint_every;
  double checkpoint_time = -1;
  const auto write_checkpoint = [&](OutputParticles& particles) {
    CheckpointData c = opt.case_record;
    view->save_global_state(c);
    outputs->save_state(c);
    // The particles' arrays from each process in turn, in blocks of rows.
    write_checkpoint_file(checkpoint_path(opt.out_dir), c, [&particles](const auto& add) {
      particles.pieces(ParticleSelection::All, [&add](const ParticleSet& piece) {
        Simulation::particle_state_blocks(piece, add);
      });
    });
    checkpoint_time = view->time();
  };
  const bool show_progress = opt.progress && view;
  ProgressReporter progress(end, stderr, opt.plain_progress);

  const auto t0 = std::chrono::steady_clock::now();
  auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  RunReport r;
  double particle_steps = 0;
  bool warned_lost = false;
  std::vector<char> warned_at_bar(view ? view->nets().size() : 0, 0);
  if (!opt.resume) write_outputs([&](OutputParticles& p) { outputs->maybe_write(*view, p, 0.0); });
  try {
    while (!run_has_ended(stepper.time(), end)) {
      if (opt.max_steps > 0 && stepper.steps() >= opt.max_steps) {
        r.status = "step limit";
        break;
      }
      if (stepper.any(stop_requested())) {
        r.status = "interrupted";
        r.message = fmt::format("stopped by {} at t = {:.6g} s (step {})", stop_cause(),
                                stepper.time(), stepper.steps());
        break;
      }
      particle_steps += static_cast<double>(stepper.particle_count());
      stepper.step();
      const bool checkpoint_due =
          stepper.time() >= next_checkpoint * (1 - 1e-12) && !run_has_ended(stepper.time(), end);
      stepper.refresh_view();
      // An output that fails (a full disk, a quota, a file size limit) stops the run at this
      // step: on one process the run then ends as below, with its final outputs tried, the
      // status "output failed" in summary.json and a non-zero exit; a distributed run's
      // processes all stop with its message (write_outputs).
      try {
        write_outputs([&](OutputParticles& p) {
          outputs->after_step(*view, p);
          if (view->diagnostics().lost_total > 0 && !warned_lost) {
            // Where the first ones went tells a leak through a wall (just outside it) from a
            // domain drawn too small (anywhere on its faces, moving with the flow).
            const std::string where = describe_lost(view->diagnostics().last_lost);
            spdlog::warn(
                "t = {:.6g} s: particles are leaving the domain and are removed (reported in "
                "series.csv, lost_particles){}; enlarge [domain] if they should stay",
                view->time(), where.empty() ? "" : ", first " + where);
            warned_lost = true;
          }
          warn_sinker_reactions_at_bar(*view, warned_at_bar);
          outputs->maybe_write(*view, p, wall());
          if (checkpoint_due) write_checkpoint(p);
        });
      } catch (const Error& e) {
        if (stepper.processes() > 1) throw;
        r.status = "output failed";
        r.message = e.what();
        spdlog::error("t = {:.6g} s: {}: the run stops here", stepper.time(), e.what());
        break;
      }
      if (checkpoint_due) {
        while (next_checkpoint <= stepper.time() * (1 + 1e-12)) next_checkpoint += checkpoint_every;
      }
      if (show_progress) progress.update(stepper.time(), stepper.steps(), stepper.particle_count());
    }
    if (r.status.empty()) r.status = "completed";
  } catch (const SimulationUnstable& e) {
    r.status = "unstable";
    r.message = e.what();
  }
  if (show_progress) progress.finish(stepper.time(), stepper.steps(), stepper.particle_count());

  r.wall_s = wall();
  r.steps = stepper.steps();
  r.sim_time = stepper.time();
  r.particle_steps_per_s = r.wall_s > 0 ? particle_steps / r.wall_s : 0;
  r.bytes_per_particle = stepper.bytes_per_particle();
  stepper.refresh_view();
  stepper.finish();
  GlobalMeasures final_state;
  write_outputs([&](OutputParticles& p) {
    r.warnings = collect_warnings(*view);
    try {
      outputs->write_final(*view, p, r.wall_s);
      // The state of an unstable run is broken: its last good checkpoint stays.
      if (r.status != "unstable") write_checkpoint(p);
    } catch (const Error& e) {
      // The final checkpoint or outputs are part of the run's results: a run without them has
      // not completed (it said "completed" and exited 0 with no checkpoint), and its earlier
      // checkpoint is where a restart goes on from.
      r.warnings.push_back(std::string("final output failed: ") + e.what());
      if (r.status != "unstable" && r.status != "output failed") {
        r.status = "output failed";
        r.message = std::string("final output failed: ") + e.what();
      }
    }
    final_state = p.measure();
  });
  if (!view) return r;
  r.checkpoint_time = checkpoint_time;
  r.snapshots = outputs->snapshots_written();
  r.summary = summary_json(*view, final_state, r, opt, *outputs, stepper.processes());
  for (std::string& w : window_warnings(r.summary)) {
    r.summary["warnings"].push_back(w);
    r.warnings.push_back(std::move(w));
  }
  if (opt.resume) r.summary["time"]["restarted_from_s"] = start_time;
  write_file_atomic(opt.out_dir / "summary.json", r.summary.dump(2) + "\n");
  return r;
}

}  // namespace netsph
