#include "netsph/run/wave_gauges.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "netsph/waves/wave_record.hpp"

namespace netsph {

namespace {

/// The rows of a gauges.csv kept by a restart: the times and every gauge's columns.
void read_back(const std::filesystem::path& file, std::vector<double>& times,
               std::vector<std::vector<double>>& columns) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return;  // the header
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<double> values;
    while (std::getline(row, cell, ',')) {
      // NaN is written as "nan"; strtod reads it.
      values.push_back(std::strtod(cell.c_str(), nullptr));
    }
    if (values.size() != columns.size() + 1) continue;
    times.push_back(values[0]);
    for (std::size_t c = 0; c < columns.size(); ++c) columns[c].push_back(values[c + 1]);
  }
}

nlohmann::json record_json(const WaveRecordSummary& s) {
  // No complete wave: nothing to report (null, not zeros that read as a flat sea).
  if (s.waves.empty()) {
    return {{"waves", 0},
            {"mean_level_m", nullptr},
            {"mean_height_m", nullptr},
            {"mean_period_s", nullptr},
            {"h_third_m", nullptr},
            {"mean_crest_m", nullptr},
            {"mean_trough_m", nullptr},
            {"max_crest_m", nullptr},
            {"max_trough_m", nullptr}};
  }
  double max_crest = 0, max_trough = 0;
  for (const RecordWave& w : s.waves) {
    max_crest = std::max(max_crest, w.crest);
    max_trough = std::max(max_trough, w.trough);
  }
  return {{"waves", s.waves.size()},        {"mean_level_m", s.mean_level},
          {"mean_height_m", s.mean_height}, {"mean_period_s", s.mean_period},
          {"h_third_m", s.h_third},         {"mean_crest_m", s.mean_crest},
          {"mean_trough_m", s.mean_trough}, {"max_crest_m", max_crest},
          {"max_trough_m", max_trough}};
}

/// The record without its NaN samples (a gauge that found no water then).
WaveRecordSummary analyse(const std::vector<double>& t, const std::vector<double>& eta, double from,
                          double to) {
  std::vector<double> tt, ee;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from || t[k] > to || !std::isfinite(eta[k])) continue;
    tt.push_back(t[k]), ee.push_back(eta[k]);
  }
  return zero_upcrossing_waves(tt, ee);
}

}  // namespace

double gauge_interval(const CaseSpec& spec) {
  if (spec.output.gauge_every > 0) return spec.output.gauge_every;
  const double series = series_interval(spec);
  if (!spec.waves.given) return series;
  return std::min(series, spec.waves.reference_period() / 40);
}

GaugeRecorder::GaugeRecorder(const Simulation& sim, const std::filesystem::path& dir,
                             std::optional<double> resume_time)
    : file_(dir / "gauges.csv"), spec_(&sim.spec()) {
  const CaseSpec& spec = sim.spec();
  if (spec.gauges.empty()) return;
  if (spec.waves.given) {
    still_level_ = spec.waves.still_level;
  } else {
    still_level_ = -std::numeric_limits<double>::infinity();
    for (const FillSpec& f : spec.fills)
      still_level_ = std::max(still_level_, f.surface_z.value_or(f.box.max.z));
  }
  const double dz = spec.simulation.dp / 4;
  std::vector<CsvColumn> columns{{"time", "s"}};
  for (const GaugeSpec& g : spec.gauges) {
    Gauge gauge;
    gauge.spec = g;
    const auto n = static_cast<std::size_t>(std::ceil((g.z_max - g.z_min) / dz)) + 1;
    for (std::size_t k = 0; k < n; ++k) {
      const double z = std::min(g.z_min + static_cast<double>(k) * dz, g.z_max);
      gauge.z.push_back(z);
      gauge.points.push_back({g.x, g.y, z});
    }
    all_points_.insert(all_points_.end(), gauge.points.begin(), gauge.points.end());
    columns.push_back({g.name, "m"});
    if (spec.waves.given) columns.push_back({g.name + "_target", "m"});
    gauges_.push_back(std::move(gauge));
  }
  values_.resize(all_points_.size());
  schedule_ = {gauge_interval(spec), sim.time()};
  if (resume_time) {
    csv_ = std::make_unique<CsvSeries>(file_, columns, *resume_time);
    std::vector<std::vector<double>> back(columns.size() - 1);
    read_back(file_, times_, back);
    const std::size_t per = spec.waves.given ? 2 : 1;
    for (std::size_t g = 0; g < gauges_.size(); ++g) {
      gauges_[g].eta = back[per * g];
      if (per == 2) gauges_[g].target = back[per * g + 1];
    }
    // The row at the resume time is kept: the next is the first of the uninterrupted run's
    // times (whole intervals from 0) after it.
    if (!times_.empty()) {
      schedule_.next = 0;
      schedule_.take(schedule_time(times_.back()));
    }
  } else {
    csv_ = std::make_unique<CsvSeries>(file_, columns);
  }
}

void GaugeRecorder::after_step(const Simulation& sim, OutputParticles& particles) {
  if (gauges_.empty() || !schedule_.take(schedule_time(sim.time()))) return;
  particles.sample(all_points_, values_);
  const double t = sim.time();
  row_.assign(1, t);
  std::size_t offset = 0;
  for (Gauge& g : gauges_) {
    coverage_.resize(g.points.size());
    for (std::size_t k = 0; k < g.points.size(); ++k) coverage_[k] = values_[offset + k].coverage;
    offset += g.points.size();
    const double eta = surface_from_coverage(g.z, coverage_) - still_level_;
    g.eta.push_back(eta);
    row_.push_back(eta);
    if (spec_->waves.given) {
      const double target = spec_->waves.target_elevation(g.spec.x, t);
      g.target.push_back(target);
      row_.push_back(target);
    }
  }
  times_.push_back(t);
  csv_->append(row_);
}

nlohmann::json GaugeRecorder::summary() const {
  nlohmann::json out = nlohmann::json::array();
  const std::array<double, 2> window = force_window(*spec_);
  for (const Gauge& g : gauges_) {
    nlohmann::json j = {{"name", g.spec.name},  {"x_m", g.spec.x},
                        {"y_m", g.spec.y},      {"samples", times_.size()},
                        {"file", "gauges.csv"}, {"window_s", {window[0], window[1]}}};
    const WaveRecordSummary measured = analyse(times_, g.eta, window[0], window[1]);
    j["measured"] = record_json(measured);
    if (measured.waves.empty()) {
      const double last = times_.empty() ? 0.0 : times_.back();
      j["note"] =
          last < window[1]
              ? fmt::format("no complete wave in the window: the record ends at {:.6g} s", last)
              : std::string(
                    "no complete wave in the window (fewer than two "
                    "up-crossings, or no water at the gauge)");
    }
    if (spec_->waves.given) {
      const WaveRecordSummary target = analyse(times_, g.target, window[0], window[1]);
      j["target"] = record_json(target);
      if (target.mean_height > 0 && target.mean_period > 0 && !measured.waves.empty()) {
        j["height_ratio"] = measured.mean_height / target.mean_height;
        j["period_ratio"] = measured.mean_period / target.mean_period;
      }
    }
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace netsph
