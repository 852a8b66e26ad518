#pragma once
// A standalone net run (a case with [[net]] tables and no fluid): the nets hang under gravity,
// their anchors and sinkers, loaded by the [current] through the screen or Morison model,
// until end_time. Outputs in the run folder: series.csv (per net: current force, anchor
// force, Cd on the outline area, largest deflection, largest tension), net_<name>_NNNN.vtk
// with <name>.vtk.series for ParaView, knots_<name>.csv and profile_<name>.csv at the end,
// summary.json (forces averaged over output.force_window). The engineer's quick answer:
// drag and deflection in seconds, without SPH.
#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "netsph/case/case_spec.hpp"

namespace netsph {

struct NetRunSummary {
  std::string name;
  Vec3d mean_force{};         ///< current force on the net over the window, N
  Vec3d mean_anchor_force{};  ///< N
  /// Along the current, on the outline area; NaN without a current (F / (0.5 rho U^2 A) is
  /// undefined at U = 0, and 0 would read as a measured value).
  double drag_coefficient = 0;
  double max_deflection = 0;  ///< along the normal, at the end, m
  int knots = 0, twines = 0;
};

struct NetRunReport {
  std::string status = "completed";  ///< completed | unstable | interrupted (as a coupled run)
  std::string message;
  std::vector<std::string> warnings;  ///< also in summary.json
  double sim_time = 0;
  long long substeps = 0;
  double wall_s = 0;
  std::array<double, 2> window{};
  std::vector<NetRunSummary> nets;
};

struct NetRunOptions {
  std::filesystem::path out_dir;
  bool progress = true;
  /// Asked after every series row; true ends the run there with status "interrupted", its
  /// outputs written as at the end (Ctrl-C in `netsph run`).
  std::function<bool()> stop;
};

NetRunReport run_standalone_nets(const CaseSpec& spec, const NetRunOptions& options);

}  // namespace netsph
