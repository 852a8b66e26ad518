#pragma once
// Wave gauges: the free-surface elevation above the still-water level at each [[gauge]],
// sampled over time into gauges.csv and summarised (zero up-crossing analysis,
// waves/wave_record.hpp) in summary.json.
//
// How a gauge finds the surface: the kernel's fluid volume sum ("coverage", sph/shepard.hpp)
// is sampled up a vertical line at (x, y), from the lowest fill's bottom to the domain's top
// (without [domain]: the highest fill's top plus twice the wave height), every dp/4. Inside
// the water the sum is 1; at a flat free surface exactly half the kernel lies in water, so it
// is 0.5 there. The surface is the highest point where the sum crosses 0.5, located by linear
// interpolation between samples (DualSPHysics' gauges use the same half-kernel rule on the
// mass sum). Spray above the surface does not count: a lone particle's own sum is about 0.25.
// A gauge that finds no water writes NaN.
//
// gauges.csv: time [s], then per gauge <name> [m] (the elevation), and with [waves]
// <name>_target [m] (waves/wave_train.hpp: the wave the paddle is meant to make at the gauge,
// without its evanescent modes). Sampled every output.gauge_every seconds (default: with
// [waves], a fortieth of the (peak) period or the series interval if shorter; without, the
// series interval).
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "netsph/io/csv_series.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/run/output_schedule.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/sph/free_surface.hpp"

namespace netsph {

/// The sampling interval of gauges.csv, s.
double gauge_interval(const CaseSpec& spec);

class GaugeRecorder {
 public:
  /// Creates gauges.csv (nothing without gauges); a restart (resume_time set) keeps the rows
  /// up to it, reads them back for the summary and continues the file.
  GaugeRecorder(const Simulation& sim, const std::filesystem::path& dir,
                std::optional<double> resume_time = {});
  bool empty() const { return gauges_.empty(); }
  /// Samples the gauges when their interval has come (always at t = 0).
  void after_step(const Simulation& sim, OutputParticles& particles);
  /// Per gauge: position, samples, and over the analysis window (the force window) the zero
  /// up-crossing waves' mean height and period, H1/3, mean and extreme crest and trough; with
  /// [waves], the same of the target signal and the ratios measured / target.
  nlohmann::json summary() const;

 private:
  struct Gauge {
    GaugeSpec spec;
    std::vector<Vec3d> points;  ///< up the vertical line
    std::vector<double> z;
    std::vector<double> eta, target;  ///< the record
  };
  std::filesystem::path file_;
  const CaseSpec* spec_ = nullptr;
  /// The still-water level the elevations are measured from: [waves]'s, else the highest
  /// fill's surface.
  double still_level_ = 0;
  std::vector<Gauge> gauges_;
  std::vector<double> times_;
  std::unique_ptr<CsvSeries> csv_;
  OutputSchedule schedule_;
  std::vector<Vec3d> all_points_;
  std::vector<ShepardValue> values_;
  std::vector<double> coverage_, row_;  ///< a sample's scratch, kept between samples
};

}  // namespace netsph
