#pragma once
// Velocity probes: the fluid sampled at the case's [[probe]] points, lines and planes with
// Shepard-corrected SPH interpolation (sph/shepard.hpp), as the paper's Figures 13, 19 and 24
// (centreline) and 17, 18, 22 and 23 (planes) show it. A run writes, per probe:
//   probes/<name>.csv       instantaneous values every probe.every seconds (default: the
//                           series interval for points, the snapshot interval for lines and
//                           planes): time, point, x, y, z, ux, uy, uz, p (gauge), coverage
//   probes/<name>_mean.csv  the time average over the force window, sampled every series
//                           interval: point, s (distance from the first point), x, y, z, ux,
//                           uy, uz, speed, p, coverage, samples
// Coverage is the kernel's fluid volume sum at the point (1 in the fluid; below ~0.5 the point
// lies in or next to a body or wall and its values stand for the fluid beside it).
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "netsph/io/csv_series.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/run/output_schedule.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/sph/shepard.hpp"

namespace netsph {

/// Time average of Shepard values at one point.
struct ProbeAverage {
  Vec3d velocity{};
  double pressure = 0;
  double coverage = 0;
  int samples = 0;  ///< samples in which the point saw fluid
};

class ProbeRecorder {
 public:
  /// Creates probes/<name>.csv for every probe of the case (nothing without probes); a
  /// restart (resume_time set) continues the files instead.
  ProbeRecorder(const Simulation& sim, const std::filesystem::path& dir, double window_start,
                double window_end, std::optional<double> resume_time = {});
  ~ProbeRecorder();

  bool empty() const { return probes_.empty(); }
  /// Samples the probes whose interval has come (always at t = 0) from `particles`
  /// (output_particles.hpp).
  void after_step(const Simulation& sim, OutputParticles& particles);
  /// Writes probes/<name>_mean.csv.
  void write_means() const;
  /// Per probe: type, points, files, samples averaged; point probes: the mean velocity; with a
  /// uniform inlet, the velocity reduction 1 - u_x / U (point probes) or the largest one along
  /// the line or over the plane; planes: the mean u_x over their points in the fluid (and its
  /// reduction); lines: the mean u_x at every point.
  nlohmann::json summary() const;

  /// The window averages of probe `index` (case order), one per point.
  const std::vector<ProbeAverage>& averages(std::size_t index) const;
  const std::vector<Vec3d>& points(std::size_t index) const;

  /// The running sums and next sampling times, for a checkpoint and a restart.
  std::vector<double> state() const;
  /// With keep_means false only the sampling schedule continues: the means start afresh (a
  /// restart whose averaging window moved).
  void restore(const std::vector<double>& state, bool keep_means = true);

 private:
  struct Probe;
  std::filesystem::path dir_;
  double t0_, t1_;
  OutputSchedule sample_schedule_;  ///< the samples of the means
  std::optional<double> inflow_;    ///< uniform inlet speed: velocity reductions refer to it
  std::vector<std::unique_ptr<Probe>> probes_;
};

}  // namespace netsph
