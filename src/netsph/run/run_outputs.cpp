#include "netsph/run/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include <spdlog/spdlog.h>

#include "netsph/core/error.hpp"
#include "netsph/io/output_folder.hpp"

namespace netsph {

namespace {
std::vector<CsvColumn> series_columns(int dims) {
  const std::string per = dims == 2 ? "/m" : "";
  return {{"time", "s"},
          {"dt", "s"},
          {"step", ""},
          {"fluid_particles", ""},
          {"wall_particles", ""},
          {"buffer_particles", ""},
          {"lost_particles", ""},
          {"inflow_particles", ""},
          {"outflow_particles", ""},
          {"kinetic_energy", "J" + per},
          {"fluid_mass", "kg" + per},
          {"max_speed", "m/s"},
          {"min_density", "kg/m^3"},
          {"max_density", "kg/m^3"},
          {"dt_force_limit", "s"},
          {"dt_acoustic_limit", "s"},
          {"wall_time", "s"}};
}

std::vector<CsvColumn> with_force_columns(std::vector<CsvColumn> cols,
                                          const BodyForceRecorder& forces, const Simulation& sim) {
  for (auto& c : forces.series_columns()) cols.push_back(std::move(c));
  // Coupled nets: largest deflection along the normal and largest twine tension.
  for (const CoupledNet& net : sim.nets()) {
    cols.push_back({net.model.name + "_deflection", "m"});
    cols.push_back({net.model.name + "_max_tension", "N"});
  }
  return cols;
}
}  // namespace

namespace {
/// Whether the end of the run that wrote checkpoint c wrote, off their schedules, a series row
/// (which = 0) or a snapshot and the nets' shapes (which = 1): RunOutputs::write_final.
bool final_extra(const CheckpointData& c, int which) {
  const auto extra = c.f64.find("outputs.final_extra");
  return extra != c.f64.end() && extra->second.size() == 2 && extra->second[which] != 0;
}

/// The time up to which a restart keeps the rows of series.csv and bodies.csv: the checkpoint's,
/// or just before it when the run that wrote it ended with a row of its own there (an end or a
/// stop off the series schedule, RunOutputs::write_final), which the run continued past it
/// would not have written.
std::optional<double> resume_time(const CheckpointData* c) {
  if (!c) return {};
  const double t = c->real("sim.time");
  return final_extra(*c, 0) ? t * (1 - 2e-8) : t;  // CsvSeries keeps rows up to 1e-8 past it
}

/// Snapshots of the run before a restart that are gone from its folder (deleted to save room,
/// or a copy of the folder made without them). particles.xdmf goes on listing them, because the
/// snapshots after the restart are numbered on from them (SnapshotWriter), and ParaView then
/// fails on the series: the user hears of it now, not there.
void warn_missing_snapshots(const std::filesystem::path& dir, const std::string& entries) {
  std::istringstream in(entries);  // a line per snapshot: file, time, step, particles
  std::string file, first;
  double t;
  std::int64_t step;
  std::size_t n, listed = 0, missing = 0;
  while (in >> file >> t >> step >> n) {
    ++listed;
    std::error_code ec;
    if (std::filesystem::is_regular_file(dir / file, ec)) continue;
    if (missing++ == 0) first = file;
  }
  if (missing == 0) return;
  spdlog::warn(
      "{} of the {} snapshots written before the restart are missing from {} (the first: {}): "
      "particles.xdmf still lists them (the new snapshots are numbered on after them), so "
      "ParaView fails on it until they are put back; the remaining .h5 files open one by one",
      missing, listed, dir.string(), first);
}
}  // namespace

RunOutputs::RunOutputs(const Simulation& sim, std::filesystem::path dir, bool snapshots,
                       const CheckpointData* resume)
    : dir_(std::move(dir)),
      window_(force_window(sim.spec())),
      end_time_(sim.spec().simulation.end_time),
      forces_(sim, window_[0], window_[1]),
      nets_(sim, window_[0], window_[1]),
      probes_((create_output_folder(dir_, "output folder"), sim), dir_, window_[0], window_[1],
              resume_time(resume)),
      gauges_(sim, dir_, resume_time(resume)),
      series_(resume
                  ? CsvSeries(dir_ / "series.csv",
                              with_force_columns(series_columns(sim.model().dims), forces_, sim),
                              *resume_time(resume))
                  : CsvSeries(dir_ / "series.csv",
                              with_force_columns(series_columns(sim.model().dims), forces_, sim))) {
  for (const CoupledNet& net : sim.nets()) {
    net_vtk_.emplace_back(dir_ / (net.model.name + ".vtk.series"));
    net_xdmf_.emplace_back(dir_ / (net.model.name + ".xdmf"));
  }
  if (snapshots)
    snapshots_ = std::make_unique<SnapshotWriter>(dir_, "particles", resume != nullptr);
  if (!sim.bodies().empty()) {
    bodies_csv_ = resume ? std::make_unique<CsvSeries>(dir_ / "bodies.csv",
                                                       body_state_columns(sim.model().dims),
                                                       *resume_time(resume))
                         : std::make_unique<CsvSeries>(dir_ / "bodies.csv",
                                                       body_state_columns(sim.model().dims));
  }
  snapshot_schedule_ = {snapshot_interval(sim.spec()), sim.time()};
  series_schedule_ = {series_interval(sim.spec()), sim.time()};
  if (resume) restore_state(sim, *resume);
}

void RunOutputs::save_state(CheckpointData& c) const {
  c.f64["outputs.next"] = {snapshot_schedule_.next, series_schedule_.next,
                           static_cast<double>(last_snapshot_step_),
                           static_cast<double>(last_series_step_)};
  c.text["outputs.snapshots"] = snapshots_ ? snapshots_->entries_text() : "";
  c.f64["outputs.net_times"] = net_times_;
  c.f64["outputs.every"] = {snapshot_schedule_.every, series_schedule_.every};
  c.f64["outputs.final_extra"] = {final_row_ ? 1.0 : 0.0, final_shapes_ ? 1.0 : 0.0};
  c.f64["outputs.window"] = {window_[0], window_[1], end_time_};
  c.f64["outputs.forces"] = forces_.state();
  c.f64["outputs.nets"] = nets_.state();
  c.f64["outputs.probes"] = probes_.state();
}

void RunOutputs::restore_state(const Simulation& sim, const CheckpointData& c) {
  const std::vector<double>& next = c.reals("outputs.next");
  if (next.size() != 4) throw Error(c.source, "output state of another netsph version");
  snapshot_schedule_.next = next[0], series_schedule_.next = next[1];
  last_snapshot_step_ = static_cast<std::int64_t>(next[2]);
  last_series_step_ = static_cast<std::int64_t>(next[3]);
  // The averages go on only over the window they were summed over: the same window, or one
  // that starts where it did and ends later when the first run's window reached its end (a
  // longer run with output.force_window extended; the one step that ended the first run, just
  // past its end, is not in the sums). A restart that moves the window otherwise (a longer
  // end_time moves the default, the run's second half) starts the means afresh, so they cover
  // the new window from the restart on. Checkpoints that did not record the window continue.
  const auto saved = c.f64.find("outputs.window");
  bool same_window = true;
  if (saved != c.f64.end() && saved->second.size() == 3) {
    const double w0 = saved->second[0], w1 = saved->second[1], first_end = saved->second[2];
    same_window = (w0 == window_[0] && w1 == window_[1]) ||
                  (w0 == window_[0] && w1 >= first_end && window_[1] >= w1);
    if (!same_window && window_[0] < sim.time()) {
      spdlog::warn(
          "the averaging window moved from [{:.6g}, {:.6g}] s to [{:.6g}, {:.6g}] s on restart: "
          "the means of forces, nets and probes cover only [{:.6g}, {:.6g}] s, after the "
          "restart (set output.force_window to keep the first run's window)",
          w0, w1, window_[0], window_[1], sim.time(), window_[1]);
    }
  }
  if (same_window) {
    forces_.restore(c.reals("outputs.forces"));
    nets_.restore(c.reals("outputs.nets"));
  }
  probes_.restore(c.reals("outputs.probes"), same_window);
  // A snapshot (and the nets' shapes) that the end or stop of the first run wrote off the
  // snapshot schedule is not one the continued run would have written: dropped, and its
  // index written over by the next.
  const bool final_shapes = final_extra(c, 1);
  std::string entries = c.text_of("outputs.snapshots");  // a line per snapshot
  if (final_shapes && !entries.empty()) {
    const auto cut = entries.find_last_of('\n', entries.size() - 2);
    entries.erase(cut == std::string::npos ? 0 : cut + 1);
  }
  if (snapshots_) {
    warn_missing_snapshots(dir_, entries);
    snapshots_->resume(entries);
  }
  // A restart with a new output.snapshot_every or series_every goes on with the new interval at
  // once (issue 46: the first snapshot after it fell at the old schedule's next time). Its due
  // times are the new interval's multiples, as in a run given it from the start, from the first
  // after the last output written: the last snapshot listed, the checkpoint's time for series
  // rows (written up to it). One due at or before the restart's time is written at its first
  // step. Checkpoints that did not record the intervals are rescheduled alike.
  const auto saved_every = c.f64.find("outputs.every");
  const auto changed = [&](std::size_t k, const OutputSchedule& s) {
    return saved_every == c.f64.end() || saved_every->second.size() != 2 ||
           saved_every->second[k] != s.every;
  };
  const auto after = [](const OutputSchedule& s, double last) {
    return s.every > 0 ? (std::floor(schedule_time(last) / s.every) + 1) * s.every : s.next;
  };
  if (changed(0, snapshot_schedule_)) {
    double last_snapshot = -std::numeric_limits<double>::infinity();
    std::istringstream in(entries);
    std::string file;
    double t;
    std::int64_t step;
    std::size_t n;
    while (in >> file >> t >> step >> n) last_snapshot = t;
    if (std::isfinite(last_snapshot))
      snapshot_schedule_.next = after(snapshot_schedule_, last_snapshot);
  }
  if (changed(1, series_schedule_)) series_schedule_.next = after(series_schedule_, sim.time());
  // The nets' shapes written so far (net_<net>_<index>.vtk): their times, or in checkpoints
  // that did not record them those of the particle snapshots they went with.
  if (const auto saved_times = c.f64.find("outputs.net_times"); saved_times != c.f64.end()) {
    net_times_ = saved_times->second;
    if (final_shapes && !net_times_.empty()) net_times_.pop_back();
  } else if (snapshots_) {
    std::istringstream in(entries);
    std::string file;
    double t;
    std::int64_t step;
    std::size_t n;
    while (in >> file >> t >> step >> n) net_times_.push_back(t);
  }
  for (std::size_t k = 0; k < sim.nets().size(); ++k) {
    std::vector<std::pair<std::string, double>> list;
    for (std::size_t i = 0; i < net_times_.size(); ++i)
      list.emplace_back(net_shape_file(sim.nets()[k], i), net_times_[i]);
    net_vtk_[k].reset(std::move(list));
    net_xdmf_[k].resume(net_times_.size());
  }
}

void RunOutputs::write_snapshot(const Simulation& sim, OutputParticles& particles) {
  SnapshotPieces out =
      snapshots_->begin(sim.time(), sim.steps(), particles.count(ParticleSelection::Snapshot));
  const TaitEos& eos = sim.model().eos;
  std::vector<float> pressure;
  particles.pieces(ParticleSelection::Snapshot, [&](const ParticleSet& q) {
    pressure.resize(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) pressure[i] = eos.pressure(q.rho[i]);
    SnapshotFields f;
    f.position = q.pos;
    f.velocity = q.vel;
    f.density = q.rho;
    f.pressure = pressure;
    f.kind = {reinterpret_cast<const std::uint8_t*>(q.kind.data()), q.kind.size()};
    f.id = q.id;
    out.append(f);
  });
  out.finish();
  last_snapshot_step_ = sim.steps();
  write_net_shapes(sim);
}

std::string RunOutputs::net_shape_file(const CoupledNet& net, std::size_t index) {
  return "net_" + net.model.name + "_" + std::to_string(index) + ".vtk";
}

void RunOutputs::write_net_shapes(const Simulation& sim) {
  const auto& nets = sim.nets();
  if (nets.empty()) return;
  for (std::size_t n = 0; n < nets.size(); ++n) {
    const CoupledNet& net = nets[n];
    const std::string file = net_shape_file(net, net_times_.size());
    write_net_vtk(dir_ / file, net.model, net.initial);
    net_vtk_[n].add(file, sim.time());
    net_xdmf_[n].add(net.model, net.initial, sim.time());
  }
  net_times_.push_back(sim.time());
  last_snapshot_step_ = sim.steps();
}

void RunOutputs::write_net_tables(const Simulation& sim) {
  for (const CoupledNet& net : sim.nets()) {
    write_knots_csv(dir_ / ("knots_" + net.model.name + ".csv"), net.model, net.initial);
    write_profile_csv(dir_ / ("profile_" + net.model.name + ".csv"), net.model, net.initial);
  }
}

void RunOutputs::write_series_row(const Simulation& sim, OutputParticles& particles,
                                  double wall_s) {
  const GlobalMeasures g = particles.measure();
  const auto& d = sim.diagnostics();
  std::vector<double> row = {sim.time(),
                             sim.steps() > 0 ? sim.last_dt() : 0.0,
                             static_cast<double>(sim.steps()),
                             static_cast<double>(g.fluid),
                             static_cast<double>(g.walls),
                             static_cast<double>(g.buffer),
                             static_cast<double>(d.lost_total),
                             static_cast<double>(d.open.entered_fluid),
                             static_cast<double>(d.open.removed),
                             g.kinetic_energy,
                             g.fluid_mass,
                             g.max_speed,
                             g.min_density,
                             g.max_density,
                             d.dt_limits.force,
                             d.dt_limits.acoustic,
                             wall_s};
  forces_.append_series_values(sim, row);
  for (const CoupledNet& net : sim.nets()) {
    row.push_back(max_normal_deflection(net.model, net.initial));
    row.push_back(max_twine_tension(net.model));
  }
  series_.append(row);
  if (bodies_csv_) append_body_rows(sim, *bodies_csv_);
  last_series_step_ = sim.steps();
}

void RunOutputs::maybe_write(const Simulation& sim, OutputParticles& particles, double wall_s) {
  const double t = schedule_time(sim.time());
  // Without particle snapshots the nets' shapes still go out at the snapshot times.
  if ((snapshots_ || !sim.nets().empty()) && snapshot_schedule_.take(t)) {
    if (snapshots_) {
      write_snapshot(sim, particles);
    } else {
      write_net_shapes(sim);
    }
  }
  if (series_schedule_.take(t)) write_series_row(sim, particles, wall_s);
}

void RunOutputs::write_final(const Simulation& sim, OutputParticles& particles, double wall_s) {
  // What is written here is off the schedules: a checkpoint after it says so (final_row_,
  // final_shapes_), so that a restart drops it.
  if (last_snapshot_step_ != sim.steps()) {
    final_shapes_ = snapshots_ || !sim.nets().empty();
    if (snapshots_) {
      write_snapshot(sim, particles);
    } else {
      write_net_shapes(sim);
    }
  }
  if (last_series_step_ != sim.steps()) {
    write_series_row(sim, particles, wall_s);
    final_row_ = true;
  }
  write_net_tables(sim);
  probes_.write_means();
}

}  // namespace netsph
