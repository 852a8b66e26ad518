#include "netsph/run/probes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "netsph/core/error.hpp"
#include "netsph/io/output_folder.hpp"

namespace netsph {

struct ProbeRecorder::Probe {
  ProbeSpec spec;
  std::vector<Vec3d> points;
  std::vector<ShepardValue> values;
  std::vector<ProbeAverage> sums;
  std::unique_ptr<CsvSeries> csv;
  OutputSchedule writes;  ///< the rows of <name>.csv
};

namespace {

std::vector<CsvColumn> probe_columns() {
  return {{"time", "s"}, {"point", ""}, {"x", "m"},    {"y", "m"},  {"z", "m"},
          {"ux", "m/s"}, {"uy", "m/s"}, {"uz", "m/s"}, {"p", "Pa"}, {"coverage", ""}};
}

}  // namespace

ProbeRecorder::ProbeRecorder(const Simulation& sim, const std::filesystem::path& dir,
                             double window_start, double window_end,
                             std::optional<double> resume_time)
    : dir_(dir / "probes"),
      t0_(window_start),
      t1_(window_end),
      sample_schedule_{series_interval(sim.spec()), sim.time()},
      inflow_(sim.spec().uniform_inflow()) {
  const CaseSpec& spec = sim.spec();
  if (spec.probes.empty()) return;
  create_output_folder(dir_, "probes");
  for (const ProbeSpec& ps : spec.probes) {
    auto pr = std::make_unique<Probe>();
    pr->spec = ps;
    pr->points = ps.sample_points();
    pr->values.resize(pr->points.size());
    pr->sums.resize(pr->points.size());
    pr->writes = {ps.every > 0 ? ps.every
                               : (ps.type == ProbeType::Point ? series_interval(spec)
                                                              : snapshot_interval(spec)),
                  sim.time()};
    pr->csv = resume_time ? std::make_unique<CsvSeries>(dir_ / (ps.name + ".csv"), probe_columns(),
                                                        *resume_time)
                          : std::make_unique<CsvSeries>(dir_ / (ps.name + ".csv"), probe_columns());
    probes_.push_back(std::move(pr));
  }
}

ProbeRecorder::~ProbeRecorder() = default;

void ProbeRecorder::after_step(const Simulation& sim, OutputParticles& particles) {
  if (probes_.empty()) return;
  const double t = schedule_time(sim.time());
  const bool sample = sample_schedule_.take(t);
  const bool in_window = sample && sim.time() >= t0_ && sim.time() <= t1_;
  for (auto& pr : probes_) {
    const bool write = pr->writes.take(t);
    if (!write && !in_window) continue;
    particles.sample(pr->points, pr->values);
    if (in_window) {
      for (std::size_t k = 0; k < pr->points.size(); ++k) {
        const ShepardValue& v = pr->values[k];
        if (!(v.coverage > 0)) continue;
        ProbeAverage& s = pr->sums[k];
        s.velocity += v.velocity;
        s.pressure += v.pressure;
        s.coverage += v.coverage;
        ++s.samples;
      }
    }
    if (write) {
      for (std::size_t k = 0; k < pr->points.size(); ++k) {
        const ShepardValue& v = pr->values[k];
        const Vec3d& x = pr->points[k];
        const bool seen = v.coverage > 0;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double row[] = {sim.time(),
                              static_cast<double>(k),
                              x.x,
                              x.y,
                              x.z,
                              seen ? v.velocity.x : nan,
                              seen ? v.velocity.y : nan,
                              seen ? v.velocity.z : nan,
                              seen ? v.pressure : nan,
                              v.coverage};
        pr->csv->append(row);
      }
    }
  }
}

const std::vector<Vec3d>& ProbeRecorder::points(std::size_t index) const {
  return probes_.at(index)->points;
}

std::vector<double> ProbeRecorder::state() const {
  std::vector<double> s{sample_schedule_.next};
  for (const auto& pr : probes_) {
    s.push_back(pr->writes.next);
    for (const ProbeAverage& a : pr->sums) {
      s.insert(s.end(), {a.velocity.x, a.velocity.y, a.velocity.z, a.pressure, a.coverage,
                         static_cast<double>(a.samples)});
    }
  }
  return s;
}

void ProbeRecorder::restore(const std::vector<double>& s, bool keep_means) {
  std::size_t need = 1;
  for (const auto& pr : probes_) need += 1 + 6 * pr->sums.size();
  if (s.size() != need) throw Error("checkpoint", "the probes differ");
  std::size_t i = 0;
  sample_schedule_.next = s[i++];
  for (auto& pr : probes_) {
    pr->writes.next = s[i++];
    for (ProbeAverage& a : pr->sums) {
      if (keep_means) {
        a.velocity = {s[i], s[i + 1], s[i + 2]};
        a.pressure = s[i + 3], a.coverage = s[i + 4], a.samples = static_cast<int>(s[i + 5]);
      }
      i += 6;
    }
  }
}

const std::vector<ProbeAverage>& ProbeRecorder::averages(std::size_t index) const {
  return probes_.at(index)->sums;
}

namespace {
ProbeAverage mean_of(const ProbeAverage& s) {
  ProbeAverage m = s;
  if (s.samples > 0) {
    const double inv = 1.0 / s.samples;
    m.velocity = s.velocity * inv;
    m.pressure = s.pressure * inv;
    m.coverage = s.coverage * inv;
  }
  return m;
}
}  // namespace

void ProbeRecorder::write_means() const {
  for (const auto& pr : probes_) {
    CsvSeries csv(dir_ / (pr->spec.name + "_mean.csv"), {{"point", ""},
                                                         {"s", "m"},
                                                         {"x", "m"},
                                                         {"y", "m"},
                                                         {"z", "m"},
                                                         {"ux", "m/s"},
                                                         {"uy", "m/s"},
                                                         {"uz", "m/s"},
                                                         {"speed", "m/s"},
                                                         {"p", "Pa"},
                                                         {"coverage", ""},
                                                         {"samples", ""}});
    for (std::size_t k = 0; k < pr->points.size(); ++k) {
      const ProbeAverage m = mean_of(pr->sums[k]);
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const bool seen = m.samples > 0;
      const Vec3d& x = pr->points[k];
      const double row[] = {static_cast<double>(k),
                            norm(x - pr->points.front()),
                            x.x,
                            x.y,
                            x.z,
                            seen ? m.velocity.x : nan,
                            seen ? m.velocity.y : nan,
                            seen ? m.velocity.z : nan,
                            seen ? norm(m.velocity) : nan,
                            seen ? m.pressure : nan,
                            m.coverage,
                            static_cast<double>(m.samples)};
      csv.append(row);
    }
  }
}

nlohmann::json ProbeRecorder::summary() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& pr : probes_) {
    nlohmann::json j;
    j["name"] = pr->spec.name;
    j["type"] = name_of(pr->spec.type);
    j["points"] = pr->points.size();
    j["file"] = "probes/" + pr->spec.name + ".csv";
    j["mean_file"] = "probes/" + pr->spec.name + "_mean.csv";
    j["window_s"] = {t0_, t1_};
    // The most samples any point took (a point counts a sample only with fluid in reach): the
    // first point of a line or plane may lie in a wall while the others measure.
    int samples = 0;
    for (const ProbeAverage& a : pr->sums) samples = std::max(samples, a.samples);
    j["samples"] = samples;
    if (pr->spec.type == ProbeType::Point && pr->sums.front().samples > 0) {
      const ProbeAverage m = mean_of(pr->sums.front());
      j["mean_velocity_m_s"] = {m.velocity.x, m.velocity.y, m.velocity.z};
      j["mean_pressure_Pa"] = m.pressure;
      // Below 1/2 the point lies mostly outside the fluid (in a wall, a body or the air): its
      // Shepard means are those of the few particles at the edge of its kernel (the run warns).
      j["mean_coverage"] = m.coverage;
      if (inflow_) j["velocity_reduction"] = 1 - m.velocity.x / *inflow_;
    }
    if (pr->spec.type != ProbeType::Point && inflow_) {
      // The slowest point that lies well inside the fluid (coverage >= 0.9: not beside a
      // body or a wall): how much the flow is slowed at most along the line or over the plane.
      double slowest = std::numeric_limits<double>::infinity();
      std::size_t where = 0;
      for (std::size_t k = 0; k < pr->sums.size(); ++k) {
        const ProbeAverage m = mean_of(pr->sums[k]);
        if (m.samples == 0 || m.coverage < 0.9 || m.velocity.x >= slowest) continue;
        slowest = m.velocity.x, where = k;
      }
      if (std::isfinite(slowest)) {
        const Vec3d& x = pr->points[where];
        j["largest_velocity_reduction"] = 1 - slowest / *inflow_;
        j["largest_reduction_at_m"] = {x.x, x.y, x.z};
      }
    }
    if (inflow_) j["reference_velocity_m_s"] = *inflow_;
    if (pr->spec.type == ProbeType::Plane) {
      // The plane's mean streamwise velocity over its points in the fluid (coverage >= 0.9):
      // behind a net, across its outline, the flow that reaches whatever lies downstream.
      double sum = 0;
      int n = 0;
      for (const ProbeAverage& a : pr->sums) {
        const ProbeAverage m = mean_of(a);
        if (m.samples == 0 || m.coverage < 0.9) continue;
        sum += m.velocity.x, ++n;
      }
      if (n > 0) {
        j["mean_ux_m_s"] = sum / n;
        if (inflow_) j["mean_velocity_reduction"] = 1 - sum / n / *inflow_;
      }
    }
    if (pr->spec.type == ProbeType::Line) {
      // The mean streamwise velocity along the line (null where no fluid was seen, or the
      // point lay beside a body or a wall: coverage below 0.9), for the validation's reading
      // of the paper's centreline figures.
      nlohmann::json x = nlohmann::json::array(), ux = nlohmann::json::array();
      for (std::size_t k = 0; k < pr->sums.size(); ++k) {
        const ProbeAverage m = mean_of(pr->sums[k]);
        x.push_back({pr->points[k].x, pr->points[k].y, pr->points[k].z});
        ux.push_back(m.samples > 0 && m.coverage >= 0.9 ? nlohmann::json(m.velocity.x)
                                                        : nlohmann::json(nullptr));
      }
      j["profile_points_m"] = x;
      j["profile_mean_ux_m_s"] = ux;
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace netsph
