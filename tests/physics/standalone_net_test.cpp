// The standalone Bi et al. (2014) net (cases/net_bi2014_standalone.toml: 0.3 m, 15 x 15
// meshes, top fixed, sinker) in a current, loaded by the screen model: the drag within 20% of
// the experiment (Shi et al. 2024, Table 3: 0.567 N at 0.17 m/s, 0.918 N at 0.226 m/s), the
// net in equilibrium (anchor force balances the loads), the deflection written out and
// growing with the current.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "netsph/case/case_reader.hpp"
#include "netsph/run/standalone_net_run.hpp"

namespace netsph {
namespace {

NetRunReport run_bi_net(double speed, const std::filesystem::path& out) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/net_bi2014_standalone.toml",
                     {"current.velocity=[" + std::to_string(speed) + ", 0, 0]",
                      "simulation.end_time=4.0", "output.force_window=[3.5, 4.0]"});
  NetRunOptions opt;
  opt.out_dir = out;
  opt.progress = false;
  return run_standalone_nets(spec, opt);
}

TEST(StandaloneNet, BiNetDragWithinTwentyPercentOfTheExperiment) {
  const auto dir = std::filesystem::temp_directory_path() / "netsph_standalone_net_test";
  std::filesystem::remove_all(dir);
  const NetRunReport slow = run_bi_net(0.17, dir / "u017");
  const NetRunReport fast = run_bi_net(0.226, dir / "u0226");
  ASSERT_EQ(slow.status, "completed");
  ASSERT_EQ(fast.status, "completed");
  const NetRunSummary& a = slow.nets.at(0);
  const NetRunSummary& b = fast.nets.at(0);
  std::printf("U = 0.17 m/s: drag %.4f N (experiment 0.567), deflection %.4f m\n", a.mean_force.x,
              a.max_deflection);
  std::printf("U = 0.226 m/s: drag %.4f N (experiment 0.918), deflection %.4f m\n", b.mean_force.x,
              b.max_deflection);
  EXPECT_NEAR(a.mean_force.x / 0.567, 1.0, 0.20);
  EXPECT_NEAR(b.mean_force.x / 0.918, 1.0, 0.20);
  // Equilibrium: the anchors carry the drag.
  EXPECT_NEAR(a.mean_anchor_force.x / a.mean_force.x, 1.0, 0.01);
  EXPECT_NEAR(b.mean_anchor_force.x / b.mean_force.x, 1.0, 0.01);
  // A faster current pushes the net further; the net deflects by centimetres, not metres.
  EXPECT_GT(b.max_deflection, a.max_deflection);
  EXPECT_GT(a.max_deflection, 0.01);
  EXPECT_LT(b.max_deflection, 0.3);
  // The deflection profile and the ParaView series are written.
  std::ifstream profile(dir / "u0226" / "profile_bi2014.csv");
  std::string header, line;
  ASSERT_TRUE(std::getline(profile, header));
  int rows = 0;
  while (std::getline(profile, line)) ++rows;
  EXPECT_EQ(rows, 15);
  EXPECT_TRUE(std::filesystem::exists(dir / "u0226" / "bi2014.vtk.series"));
}

// Asked to stop (Ctrl-C in `netsph run`), the run ends at that series row with every output of
// a finished run: before, the signal killed it with no summary, knots or profile.
TEST(StandaloneNet, AStoppedRunEndsAtItsRowWithEveryOutput) {
  const auto dir = std::filesystem::temp_directory_path() / "netsph_standalone_net_stop_test";
  std::filesystem::remove_all(dir);
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/net_bi2014_standalone.toml", {});
  NetRunOptions opt;
  opt.out_dir = dir;
  opt.progress = false;
  int rows = 0;
  opt.stop = [&rows] { return ++rows == 3; };
  const NetRunReport r = run_standalone_nets(spec, opt);
  EXPECT_EQ(r.status, "interrupted");
  EXPECT_LT(r.sim_time, spec.simulation.end_time / 10);
  EXPECT_GT(r.sim_time, 0.0);
  for (const char* file : {"summary.json", "knots_bi2014.csv", "profile_bi2014.csv", "series.csv",
                           "bi2014.vtk.series"})
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
}

// No current: Cd = F / (0.5 rho U^2 A) is undefined, not 0.
TEST(StandaloneNet, CdWithoutACurrentIsUndefined) {
  const auto dir = std::filesystem::temp_directory_path() / "netsph_standalone_net_still_test";
  std::filesystem::remove_all(dir);
  const CaseSpec spec = read_case_file(
      std::string(NETSPH_CASES_DIR) + "/net_bi2014_standalone.toml",
      {"current.velocity=[0, 0, 0]", "simulation.end_time=0.5", "output.force_window=[0, 0.5]"});
  NetRunOptions opt;
  opt.out_dir = dir;
  opt.progress = false;
  const NetRunReport r = run_standalone_nets(spec, opt);
  ASSERT_EQ(r.status, "completed");
  EXPECT_TRUE(std::isnan(r.nets.at(0).drag_coefficient));
}

// A force window between two series rows averages nothing: the means are NaN, not 0 N.
TEST(StandaloneNet, AForceWindowWithoutASampleMeasuresNothing) {
  const auto dir = std::filesystem::temp_directory_path() / "netsph_standalone_net_window_test";
  std::filesystem::remove_all(dir);
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/net_bi2014_standalone.toml",
                     {"simulation.end_time=0.5", "output.force_window=[0.301, 0.305]"});
  NetRunOptions opt;
  opt.out_dir = dir;
  opt.progress = false;
  const NetRunReport r = run_standalone_nets(spec, opt);
  ASSERT_EQ(r.status, "completed");
  EXPECT_TRUE(std::isnan(r.nets.at(0).mean_force.x));
  EXPECT_TRUE(std::isnan(r.nets.at(0).drag_coefficient));
  EXPECT_GT(r.nets.at(0).max_deflection, 0.0);  // measured at the end, window or not
}

}  // namespace
}  // namespace netsph
