#pragma once
// Forces on rigid bodies as a run reports them:
//   series.csv  per force group (bodies sharing a `group` name): the fluid's force Fx Fy Fz [N]
//               and moment Mx My Mz [N m] about the group's reference point (the mean of its
//               bodies' centres at the start), and Cd = Fx / (0.5 rho0 U^2 A) when the case gives
//               U and A; in 2D forces and moments are per metre of depth [N/m], [N] (force_units);
//   bodies.csv  one row per body per series interval: centre, velocity, orientation, fluid
//               and contact force;
//   summary.json the time averages of the group values over the case's force window.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "netsph/io/csv_series.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph {

struct ForceGroup {
  std::string name;
  std::vector<std::size_t> bodies;
  Vec3d reference_point{};
  std::optional<double> reference_velocity, reference_area;
};

struct GroupLoad {
  Vec3d force{}, moment{};
  double cd = 0;  ///< 0 without reference values
};

/// The groups of a simulation's bodies, in order of first appearance.
std::vector<ForceGroup> force_groups(const Simulation& sim);

GroupLoad group_load(const Simulation& sim, const ForceGroup& g);

class BodyForceRecorder {
 public:
  BodyForceRecorder(const Simulation& sim, double window_start, double window_end);

  bool empty() const { return groups_.empty(); }
  /// Columns this recorder adds to series.csv, and their values now.
  std::vector<CsvColumn> series_columns() const;
  void append_series_values(const Simulation& sim, std::vector<double>& row) const;
  /// Adds the current loads, weighted by dt, when the step ended inside the window.
  void accumulate(const Simulation& sim);
  /// Window averages per group, for summary.json.
  nlohmann::json summary() const;
  /// The running sums, for a checkpoint and a restart.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  std::vector<ForceGroup> groups_;
  double t0_, t1_;
  int dims_;
  double weight_ = 0;
  std::vector<GroupLoad> sums_;
};

/// Columns and one row per body for bodies.csv.
/// Columns of bodies.csv; forces per metre of depth in 2D.
std::vector<CsvColumn> body_state_columns(int dims);

/// Units of body forces and moments: N and N m in 3D; per metre of depth in 2D (N/m, N).
struct ForceUnits {
  const char* force;
  const char* moment;
};
ForceUnits force_units(int dims);
void append_body_rows(const Simulation& sim, CsvSeries& csv);

}  // namespace netsph
