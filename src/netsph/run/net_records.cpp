#include "netsph/run/net_records.hpp"

#include "netsph/core/error.hpp"
#include "netsph/run/net_output.hpp"

namespace netsph {

NetRecorder::NetRecorder(const Simulation& sim, double window_start, double window_end)
    : t0_(window_start),
      t1_(window_end),
      deflection_(sim.nets().size(), 0.0),
      tension_(sim.nets().size(), 0.0),
      sinker_(sim.nets().size(), Vec3d{}) {}

void NetRecorder::accumulate(const Simulation& sim) {
  const double t = sim.time(), dt = sim.last_dt();
  if (sim.nets().empty() || t < t0_ || t > t1_ || !(dt > 0)) return;
  for (std::size_t n = 0; n < sim.nets().size(); ++n) {
    const CoupledNet& net = sim.nets()[n];
    deflection_[n] += max_normal_deflection(net.model, net.initial) * dt;
    tension_[n] += max_twine_tension(net.model) * dt;
    for (std::size_t k = 0; k < net.model.knots.size(); ++k)
      sinker_[n] += sim.bodies()[net.first_body + k].modelled_force * dt;
  }
  weight_ += dt;
  sinker_weight_ += dt;
}

std::vector<double> NetRecorder::state() const {
  std::vector<double> s = deflection_;
  s.insert(s.end(), tension_.begin(), tension_.end());
  s.push_back(weight_);
  for (const Vec3d& f : sinker_) s.insert(s.end(), {f.x, f.y, f.z});
  s.push_back(sinker_weight_);
  return s;
}

void NetRecorder::restore(const std::vector<double>& s) {
  const std::size_t n = deflection_.size();
  // Checkpoints written before the sinker's drag was modelled (2026-12-03) end at the weight:
  // the sinker's mean then covers the window from the restart on.
  const bool with_sinker = s.size() == 5 * n + 2;
  if (s.size() != 2 * n + 1 && !with_sinker) throw Error("checkpoint", "the nets differ");
  const auto at = [&](std::size_t i) { return s.begin() + static_cast<std::ptrdiff_t>(i); };
  deflection_.assign(at(0), at(n));
  tension_.assign(at(n), at(2 * n));
  weight_ = s[2 * n];
  for (std::size_t k = 0; k < n; ++k)
    sinker_[k] = with_sinker
                     ? Vec3d{s[2 * n + 1 + 3 * k], s[2 * n + 2 + 3 * k], s[2 * n + 3 + 3 * k]}
                     : Vec3d{};
  sinker_weight_ = with_sinker ? s.back() : 0.0;
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
      // Included in the net's force group (body_forces.cpp): how much of it is modelled.
      if (m.sinker_diameter > 0 && sinker_weight_ > 0) {
        const Vec3d f = sinker_[n] / sinker_weight_;
        j["mean_sinker_drag_N"] = {f.x, f.y, f.z};
      }
    }
    // Shares x stages whose reaction found no water downstream (over the run, restarts
    // included): a bar just before the outlet, a wall or a free surface.
    if (m.sinker_diameter > 0) j["sinker_reactions_at_bar"] = net.reactions_at_bar;
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
