#include "netsph/run/standalone_net_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "netsph/io/atomic_file.hpp"
#include "netsph/io/csv_series.hpp"
#include "netsph/io/output_folder.hpp"
#include "netsph/net/current_loads.hpp"
#include "netsph/net/knot_spring_solver.hpp"
#include "netsph/net/net_generator.hpp"
#include "netsph/run/net_output.hpp"
#include "netsph/run/output_schedule.hpp"
#include "netsph/run/runner.hpp"

namespace netsph {
namespace {

struct NetState {
  NetModel model;
  std::unique_ptr<KnotSpringSolver> solver;
  std::vector<Vec3d> initial;
  std::unique_ptr<NetVtkSeries> vtk;
  Vec3d force_sum{}, anchor_sum{};
  int window_samples = 0;
  /// Over the window: the least and largest force along the flow (waves: its range).
  double force_min = std::numeric_limits<double>::infinity();
  double force_max = -std::numeric_limits<double>::infinity();
  NetWater water;              ///< the water at the net, sampled once per load step
  bool wet_in_window = false;  ///< a knot was in the water at a row in the window
};

Vec3d current_force(const NetModel& net, const CurrentLoadParameters& p, const NetWater& water) {
  std::vector<Vec3d> f(net.knots.size());
  add_current_loads(net, p, f, &water);
  Vec3d sum{};
  for (const Vec3d& v : f) sum += v;
  return sum;
}

bool finite(const NetModel& net) {
  for (const NetKnot& k : net.knots) {
    if (!std::isfinite(k.position.x) || !std::isfinite(k.position.y) ||
        !std::isfinite(k.position.z) || !std::isfinite(k.velocity.x) ||
        !std::isfinite(k.velocity.y) || !std::isfinite(k.velocity.z)) {
      return false;
    }
  }
  return true;
}

}  // namespace

NetRunReport run_standalone_nets(const CaseSpec& spec, const NetRunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  create_output_folder(options.out_dir, "output folder");
  NetRunReport report;
  const double end_time = spec.simulation.end_time;
  const double snapshot_every = snapshot_interval(spec);
  const double series_every = series_interval(spec);
  report.window = force_window(spec);

  CurrentLoadParameters loads;
  if (spec.current.given || spec.waves.given) {
    // Waves without a [current] load the net with the [current] table's default model.
    loads.velocity = spec.current.velocity;
    loads.model = spec.current.model;
    loads.screen = spec.current.screen;
    loads.normal_drag = spec.current.normal_drag;
    loads.tangential_drag = spec.current.tangential_drag;
  } else {
    loads.model = NetLoadModel::None;
  }
  if (spec.waves.given) loads.waves = &spec.waves;
  loads.water_density = spec.fluid.density;
  loads.kinematic_viscosity = spec.fluid.kinematic_viscosity;
  const double speed = norm(loads.velocity);
  // Waves travel in +x: their forces are reported along x when there is no current.
  const Vec3d flow = speed > 0 ? loads.velocity / speed : Vec3d{1, 0, 0};
  // The loads change with the waves: the knots advance in steps of at most a hundredth of
  // the shortest component's period, each with the loads at its middle.
  double load_step = std::numeric_limits<double>::infinity();
  if (spec.waves.given) {
    for (const RegularWave& c : spec.waves.train.components)
      load_step = std::min(load_step, 2 * M_PI / c.omega / 100);
  }

  const NetEnvironment env = net_environment(spec);
  std::vector<NetState> nets;
  nets.reserve(spec.nets.size());
  std::vector<CsvColumn> columns = {{"time", "s"}, {"substeps", ""}};
  for (const NetSpec& ns : spec.nets) {
    NetState st;
    st.model = generate_net(ns, env);
    for (const NetKnot& k : st.model.knots) st.initial.push_back(k.position);
    st.vtk = std::make_unique<NetVtkSeries>(options.out_dir / (ns.name + ".vtk.series"));
    nets.push_back(std::move(st));
    nets.back().solver = std::make_unique<KnotSpringSolver>(nets.back().model);
    for (const char* c : {"Fx", "Fy", "Fz"}) columns.push_back({ns.name + "_" + c, "N"});
    for (const char* c : {"anchor_Fx", "anchor_Fy", "anchor_Fz"}) {
      columns.push_back({ns.name + "_" + c, "N"});
    }
    columns.push_back({ns.name + "_Cd", ""});
    columns.push_back({ns.name + "_deflection", "m"});
    columns.push_back({ns.name + "_max_tension", "N"});
  }
  CsvSeries series(options.out_dir / "series.csv", columns);

  // The water at each net is sampled at the start of each load step (with waves, a sum over
  // every component at every knot) and serves every knot sub-step of it.
  auto sample_water = [&] {
    for (NetState& st : nets) sample_net_water(st.model, loads, st.water);
  };
  // Each net's loads with that net's water.
  auto loads_of = [&](const NetState& st) {
    return [&](const NetModel& net, std::vector<Vec3d>& f) {
      add_current_loads(net, loads, f, &st.water);
    };
  };
  int snapshot = 0;
  auto write_snapshot = [&](double t) {
    for (NetState& st : nets) {
      const std::string file = fmt::format("net_{}_{:04d}.vtk", st.model.name, snapshot);
      write_net_vtk(options.out_dir / file, st.model, st.initial);
      st.vtk->add(file, t);
    }
    ++snapshot;
  };
  auto write_row = [&](double t, long long substeps) {
    std::vector<double> row = {t, static_cast<double>(substeps)};
    loads.time = t;
    sample_water();
    for (NetState& st : nets) {
      const Vec3d f = current_force(st.model, loads, st.water);
      const Vec3d anchor = st.solver->anchor_force(loads_of(st));
      const double q = 0.5 * loads.water_density * speed * speed * st.model.width * st.model.height;
      row.insert(row.end(),
                 {f.x, f.y, f.z, anchor.x, anchor.y, anchor.z, q > 0 ? dot(f, flow) / q : 0.0,
                  max_normal_deflection(st.model, st.initial), st.solver->max_tension()});
      if (t >= report.window[0] - 1e-12 && t <= report.window[1] + 1e-12) {
        st.force_sum += f;
        st.anchor_sum += anchor;
        ++st.window_samples;
        st.force_min = std::min(st.force_min, dot(f, flow));
        for (const std::uint8_t wet : st.water.knot_wet) st.wet_in_window |= wet != 0;
        st.force_max = std::max(st.force_max, dot(f, flow));
      }
    }
    series.append(row);
  };

  double t = 0;
  write_snapshot(0);
  write_row(0, 0);
  double next_snapshot = snapshot_every;
  int last_percent = -1;
  const long long rows = static_cast<long long>(std::ceil(end_time / series_every - 1e-9));
  for (long long i = 1; i <= rows; ++i) {
    const double t_next = std::min(end_time, static_cast<double>(i) * series_every);
    const int pieces = std::isfinite(load_step)
                           ? std::max(1, static_cast<int>(std::ceil((t_next - t) / load_step)))
                           : 1;
    const double piece = (t_next - t) / pieces;
    for (int k = 0; k < pieces; ++k) {
      loads.time = t + (k + 0.5) * piece;
      sample_water();
      for (NetState& st : nets) report.substeps += st.solver->advance(piece, loads_of(st));
    }
    t = t_next;
    bool ok = true;
    for (const NetState& st : nets) ok = ok && finite(st.model);
    if (!ok) {
      report.status = "unstable";
      report.message = fmt::format(
          "a knot's position or velocity became NaN or infinite at t = {:.6g} s; outputs up to "
          "the previous row are kept",
          t);
      break;
    }
    write_row(t, report.substeps);
    const bool stop = options.stop && options.stop();
    if (t >= next_snapshot - 1e-12 || i == rows || stop) {
      write_snapshot(t);
      next_snapshot += snapshot_every;
    }
    if (stop) {
      report.status = "interrupted";
      report.message = fmt::format("stopped by {} at t = {:.6g} s", stop_cause(), t);
      break;
    }
    const int percent = static_cast<int>(100 * t / end_time);
    if (options.progress && percent / 10 != last_percent / 10) {
      // fputs, which a closed stdout (netsph run ... | head) fails quietly; fmt::print throws.
      std::fputs(fmt::format("t = {:.3f} / {:.3f} s ({}%)\n", t, end_time, percent).c_str(),
                 stdout);
      last_percent = percent;
    }
  }
  report.sim_time = t;

  // The layout of a coupled run's summary.json (run/runner.cpp) where the two have the same
  // things to say, so that one script reads both.
  nlohmann::json j;
  j["netsph_version"] = NETSPH_VERSION;
  j["case"] = {
      {"name", spec.simulation.name}, {"source", spec.source}, {"overrides", spec.overrides}};
  j["mode"] = "standalone net";
  j["status"] = report.status;
  if (!report.message.empty()) j["message"] = report.message;
  j["current"] = {{"velocity_m_s", {loads.velocity.x, loads.velocity.y, loads.velocity.z}},
                  {"model", name_of(loads.model)}};
  if (spec.waves.given) {
    const WaveSpec& w = spec.waves;
    j["waves"] = {{"type", name_of(w.kind)},
                  {"height_m", w.reference_height()},
                  {"period_s", w.reference_period()},
                  {"depth_m", w.depth},
                  {"wavelength_m", w.reference_wavelength()},
                  {"theory", name_of(w.theory)}};
  }
  j["force_window_s"] = {report.window[0], report.window[1]};
  j["nets"] = nlohmann::json::array();
  for (NetState& st : nets) {
    write_knots_csv(options.out_dir / ("knots_" + st.model.name + ".csv"), st.model, st.initial);
    write_profile_csv(options.out_dir / ("profile_" + st.model.name + ".csv"), st.model,
                      st.initial);
    NetRunSummary s;
    s.name = st.model.name;
    s.knots = static_cast<int>(st.model.knots.size());
    s.twines = static_cast<int>(st.model.twines.size());
    // No series row in the force window (narrower than series_every, or a run stopped before
    // it): the means are not measured, and NaN (null in summary.json) says so where 0 N read
    // as a measured drag.
    const double nan = std::nan("");
    s.mean_force = s.mean_anchor_force = Vec3d(nan, nan, nan);
    if (st.window_samples > 0) {
      s.mean_force = st.force_sum / static_cast<double>(st.window_samples);
      s.mean_anchor_force = st.anchor_sum / static_cast<double>(st.window_samples);
    }
    const double q = 0.5 * loads.water_density * speed * speed * st.model.width * st.model.height;
    s.drag_coefficient = q > 0 ? dot(s.mean_force, flow) / q : nan;
    s.max_deflection = max_normal_deflection(st.model, st.initial);
    report.nets.push_back(s);
    if (spec.waves.given && st.window_samples > 0 && !st.wet_in_window) {
      report.warnings.push_back(fmt::format(
          "net '{}': no knot was in the water during the force window (the waves' still level "
          "is z = {:.4g} m): its forces are those of the sinker bar at most",
          s.name, spec.waves.still_level));
    }
    if (spec.waves.given && spec.waves.train.front_speed > 0) {
      const WaveSpec& w = spec.waves;
      const double distance = std::max(0.0, st.model.center.x - w.paddle_x);
      const double full = distance / w.train.front_speed + w.ramp;
      if (full > report.window[0]) {
        report.warnings.push_back(fmt::format(
            "net '{}': the waves reach their full height there at t = {:.4g} s (their ramp, "
            "{:.4g} s, from origin_x = {:.4g} m at the group velocity {:.4g} m/s), after the "
            "force window starts ({:.4g} s): its force range includes the ramp; start the "
            "window later or lengthen the run",
            s.name, full, w.ramp, w.paddle_x, w.train.front_speed, report.window[0]));
      }
    }
    if (st.window_samples == 0) {
      report.warnings.push_back(fmt::format(
          "net '{}': {}, so its mean force and Cd are not measured (null)", s.name,
          t < report.window[0]
              ? fmt::format("the run ended at t = {:.6g} s, before output.force_window [{:.6g}, "
                            "{:.6g}] s",
                            t, report.window[0], report.window[1])
              : fmt::format("no series row (every {:.6g} s) fell in output.force_window [{:.6g}, "
                            "{:.6g}] s: widen the window or lower output.series_every",
                            series_every, report.window[0], report.window[1])));
    }
    j["nets"].push_back({{"name", s.name},
                         {"knots", s.knots},
                         {"twines", s.twines},
                         {"mean_force_N", {s.mean_force.x, s.mean_force.y, s.mean_force.z}},
                         {"mean_anchor_force_N",
                          {s.mean_anchor_force.x, s.mean_anchor_force.y, s.mean_anchor_force.z}},
                         {"drag_N", dot(s.mean_force, flow)},
                         {"force_range_N", st.window_samples > 0
                                               ? nlohmann::json::array({st.force_min, st.force_max})
                                               : nlohmann::json(nullptr)},
                         {"Cd_outline", s.drag_coefficient},
                         {"max_deflection_m", s.max_deflection},
                         {"window_samples", st.window_samples}});
  }
  report.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  j["time"] = {{"simulated_s", t}, {"end_time_s", end_time}, {"knot_substeps", report.substeps}};
  j["performance"] = {{"wall_s", report.wall_s}};
  j["outputs"] = {{"folder", std::filesystem::absolute(options.out_dir).string()},
                  {"series", "series.csv"}};
  j["warnings"] = report.warnings;
  write_file_atomic(options.out_dir / "summary.json", j.dump(2) + "\n");
  return report;
}

}  // namespace netsph
