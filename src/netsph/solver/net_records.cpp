#include "netsph/solver/net_records.hpp"

#include "netsph/core/error.hpp"
#include "netsph/net/net_output.hpp"

namespace netsph {

NetRecorder::NetRecorder(const Simulation& sim, double window_start, double window_end)
    : t0_(window_start),
      t1_(window_end),
      deflection_(sim.nets().size(), 0.0),
      tension_(sim.nets().size(), 0.0) {}

void NetRecorder::accumulate(const Simulation& sim) {
  const double t = sim.time(), dt = sim.last_dt();
  if (sim.nets().empty() || t < t0_ || t > t1_ || !(dt > 0)) return;
  for (std::size_t n = 0; n < sim.nets().size(); ++n) {
    const CoupledNet& net = sim.nets()[n];
    deflection_[n] += max_normal_deflection(net.model, net.initial) * dt;
    tension_[n] += max_twine_tension(net.model) * dt;
  }
  weight_ += dt;
}

std::vector<double> NetRecorder::state() const {
  std::vector<double> s = deflection_;
  s.insert(s.end(), tension_.begin(), tension_.end());
  s.push_back(weight_);
  return s;
}

void NetRecorder::restore(const std::vector<double>& s) {
  const std::size_t n = deflection_.size();
  if (s.size() != 2 * n + 1) throw Error("checkpoint", "the nets differ");
  deflection_.assign(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n));
  tension_.assign(s.begin() + static_cast<std::ptrdiff_t>(n), s.end() - 1);
  weight_ = s.back();
}

nlohmann::json NetRecorder::summary(const Simulation& sim) const {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t n = 0; n < sim.nets().size(); ++n) {
    const CoupledNet& net = sim.nets()[n];
    const NetModel& m = net.model;
    nlohmann::json j;
    j["name"] = m.name;
    j["knots"] = m.knots.size();
    j["twines"] = m.twines.size();
    j["outline_area_m2"] = m.width * m.height;
    j["numerical_solidity"] = m.numerical_solidity;
    j["window_s"] = {t0_, t1_};
    if (weight_ > 0) {
      j["mean_max_deflection_m"] = deflection_[n] / weight_;
      j["mean_max_tension_N"] = tension_[n] / weight_;
    }
    j["final_max_deflection_m"] = max_normal_deflection(m, net.initial);
    // The bottom knot of the middle column: how far the net's lower edge has swung.
    const int column = m.columns / 2;
    const std::size_t bottom = static_cast<std::size_t>(m.index(0, column));
    const Vec3d d = m.knots[bottom].position - net.initial[bottom];
    j["final_bottom_displacement_m"] = {d.x, d.y, d.z};
    out.push_back(j);
  }
  return out;
}

}  // namespace netsph
