#pragma once
// What a coupled run reports of each net in summary.json: over the force window, the time
// averages of the largest deflection along the net's normal and of the largest twine tension,
// and at the end the deflection of the mid-width column (bottom to top). The net's fluid
// force and Cd are its force group's (run/body_forces.hpp).
#include <vector>

#include <nlohmann/json.hpp>

#include "netsph/solver/simulation.hpp"

namespace netsph {

class NetRecorder {
 public:
  NetRecorder(const Simulation& sim, double window_start, double window_end);
  /// Adds the present deflection, tension and sinker drag, weighted by dt, when the step ended
  /// inside the window.
  void accumulate(const Simulation& sim);
  /// One object per coupled net (an empty array without nets).
  nlohmann::json summary(const Simulation& sim) const;
  /// The running sums, for a checkpoint and a restart.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  double t0_, t1_;
  double weight_ = 0;
  std::vector<double> deflection_, tension_;  ///< dt-weighted sums per net
  std::vector<Vec3d> sinker_;                 ///< the sinker bar's modelled drag, the same
  double sinker_weight_ = 0;  ///< the time sinker_ covers (less than weight_ after a restart
                              ///< from a checkpoint older than it)
};

}  // namespace netsph
