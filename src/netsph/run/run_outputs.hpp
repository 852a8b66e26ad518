#pragma once
// The files a run writes into its output folder:
//   particles.xdmf + snapshots/*.h5   fluid and boundary particles (ParaView)
//   series.csv                        global quantities over time, one row per series interval
//   bodies.csv                        rigid bodies' states and forces (run/body_forces.hpp)
//   <net>.xdmf, <net>.vtk.series + net_<net>_NNNN.vtk, knots_<net>.csv, profile_<net>.csv
//                                     coupled nets
//   probes/<name>.csv, probes/<name>_mean.csv   velocity probes (run/probes.hpp)
//   gauges.csv                        wave gauges' surface elevations (run/wave_gauges.hpp)
//   summary.json                      the run as a whole (rewritten atomically, also on failure)
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "netsph/io/csv_series.hpp"
#include "netsph/io/snapshot_writer.hpp"
#include "netsph/run/body_forces.hpp"
#include "netsph/run/net_output.hpp"
#include "netsph/run/net_records.hpp"
#include "netsph/run/net_xdmf.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/run/output_schedule.hpp"
#include "netsph/run/probes.hpp"
#include "netsph/run/wave_gauges.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph {

class RunOutputs {
 public:
  /// `resume`: a checkpoint to continue from (restart), or null for a new run. A restart keeps
  /// the outputs written up to the checkpoint and drops what the run wrote after it.
  RunOutputs(const Simulation& sim, std::filesystem::path dir, bool snapshots,
             const CheckpointData* resume = nullptr);

  // `sim` gives the run's time, bodies and nets; `particles` what the outputs read of its
  // particles (output_particles.hpp).

  /// Writes a snapshot and/or a series row when their interval has come (always at t = 0).
  void maybe_write(const Simulation& sim, OutputParticles& particles, double wall_s);
  /// Writes the final snapshot and series row unless this exact step was written already.
  void write_final(const Simulation& sim, OutputParticles& particles, double wall_s);
  /// Called after every step: time averages of body forces, probe samples.
  void after_step(const Simulation& sim, OutputParticles& particles) {
    forces_.accumulate(sim);
    nets_.accumulate(sim);
    probes_.after_step(sim, particles);
    gauges_.after_step(sim, particles);
  }
  /// Body force averages for summary.json (an empty array without bodies).
  nlohmann::json body_summary() const { return forces_.summary(); }
  /// Coupled nets for summary.json (an empty array without nets).
  nlohmann::json net_summary(const Simulation& sim) const { return nets_.summary(sim); }
  /// Probes for summary.json (an empty array without probes).
  nlohmann::json probe_summary() const { return probes_.summary(); }
  const ProbeRecorder& probes() const { return probes_; }
  /// Wave gauges for summary.json (an empty array without gauges).
  nlohmann::json gauge_summary() const { return gauges_.summary(); }

  /// The outputs' state (intervals, snapshot list, running averages), for a checkpoint.
  void save_state(CheckpointData& c) const;

  int snapshots_written() const { return snapshots_ ? snapshots_->count() : 0; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  void write_snapshot(const Simulation& sim, OutputParticles& particles);
  /// The nets' shapes now (net_<net>_<index>.vtk, <net>.vtk.series, <net>.xdmf): with every
  /// particle snapshot, or at the snapshot times when snapshots are off.
  void write_net_shapes(const Simulation& sim);
  /// The nets' knot and profile tables, at the end.
  void write_net_tables(const Simulation& sim);
  static std::string net_shape_file(const CoupledNet& net, std::size_t index);
  void write_series_row(const Simulation& sim, OutputParticles& particles, double wall_s);
  void restore_state(const Simulation& sim, const CheckpointData& c);

  std::filesystem::path dir_;
  std::array<double, 2> window_;  ///< the averaging window (force_window), before its users
  double end_time_;               ///< the run's end, s (a restart compares windows with it)
  std::unique_ptr<SnapshotWriter> snapshots_;
  BodyForceRecorder forces_;  // before series_: it adds series columns
  NetRecorder nets_;
  ProbeRecorder probes_;
  GaugeRecorder gauges_;
  CsvSeries series_;
  std::unique_ptr<CsvSeries> bodies_csv_;
  std::vector<NetVtkSeries> net_vtk_;  // one per coupled net
  std::vector<NetXdmfSeries> net_xdmf_;
  OutputSchedule snapshot_schedule_, series_schedule_;
  std::int64_t last_snapshot_step_ = -1, last_series_step_ = -1;  ///< snapshot: or net shapes
  std::vector<double> net_times_;  ///< the times of the nets' shapes written
  /// write_final wrote a series row / a snapshot or net shapes off their schedules.
  bool final_row_ = false, final_shapes_ = false;
};

}  // namespace netsph
