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

#include <nlohmann/json.hpp>

#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"
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

// ---- waves ------------------------------------------------------------------------------

namespace waves {

/// A rigid 0.1 m net (the Bi 2014 netting) at mid-depth in 2 m of water, alone (screen model
/// S2, which does not depend on the Reynolds number), under `overrides`.
CaseSpec small_rigid_net(const std::vector<std::string>& overrides) {
  constexpr std::string_view kCase = R"(
[simulation]
dimensions = 3
end_time = 1.0

[current]
velocity = [0.0, 0.0, 0.0]
model = "screen"
screen = "S2"

[[net]]
name = "small"
center = [0.0, 0.2, -1.0]
width = 0.1
height = 0.1
twine_length = 0.020
twine_diameter = 0.0026
knot_layout = "inset"
equivalent_knot = "full"
material = "polyethylene"
rigid = true
)";
  return read_case_string(kCase, "small_rigid_net", overrides);
}

}  // namespace waves

// Quasi-steady check of the waves' kinematics at the net: a rigid net small beside the
// wavelength (0.1 m in L = 16 m, kh = 0.77) feels at the crest's passage the drag of a
// current equal to the orbital velocity there, u = (H/2) sigma cosh k(z+h) / sinh kh (linear
// theory), and the opposite drag under the trough. Bounds: over the net's 0.1 m height u
// varies by k tanh(k (z+h)) 0.05 m = 0.7% either side of its centre, which the mean over the
// knots cancels to second order; the series samples T/400 apart catch the peak of u^2 to
// (2 pi / 400)^2 = 2.5e-4. So the peak drag within 1% of the steady one, the trough's the same
// with the sign changed, and the mean over whole periods zero within 1% of the peak.
TEST(StandaloneNet, RigidNetInWavesFeelsTheSteadyDragOfItsOrbitalVelocity) {
  const std::vector<std::string> wave_keys = {
      "current.velocity=[0.0, 0.0, 0.0]",
      "waves={type=\"regular\", height=0.2, period=4.0, "
      "depth=2.0, still_water_level=0.0, ramp=4.0}",
      "simulation.end_time=16.0", "output.force_window=[8.0, 16.0]", "output.series_every=0.01"};
  const CaseSpec in_waves = waves::small_rigid_net(wave_keys);
  ASSERT_TRUE(in_waves.waves.standalone);
  const RegularWave& w = in_waves.waves.train.components.at(0);
  const double kh = w.k * w.depth;
  const double u_max = 0.5 * w.height * w.omega * std::cosh(w.k * (-1.0 + w.depth)) / std::sinh(kh);
  const auto dir = std::filesystem::temp_directory_path() / "netsph_standalone_net_waves";
  std::filesystem::remove_all(dir);
  NetRunOptions opt;
  opt.progress = false;
  opt.out_dir = dir / "waves";
  const NetRunReport wavy = run_standalone_nets(in_waves, opt);
  ASSERT_EQ(wavy.status, "completed");
  const CaseSpec steady_spec =
      waves::small_rigid_net({"current.velocity=[" + std::to_string(u_max) + ", 0.0, 0.0]",
                              "simulation.end_time=0.2", "output.force_window=[0.1, 0.2]"});
  opt.out_dir = dir / "steady";
  const NetRunReport steady = run_standalone_nets(steady_spec, opt);
  ASSERT_EQ(steady.status, "completed");
  const double f_steady = steady.nets.at(0).mean_force.x;
  std::ifstream in(dir / "waves" / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  const double f_min = s["nets"][0]["force_range_N"][0], f_max = s["nets"][0]["force_range_N"][1];
  const double f_mean = s["nets"][0]["mean_force_N"][0];
  std::printf(
      "kh = %.3f, u_max = %.4f m/s: steady drag %.5f N; in waves %.5f .. %.5f N, mean %.2e N\n", kh,
      u_max, f_steady, f_min, f_max, f_mean);
  ASSERT_GT(f_steady, 0.0);
  EXPECT_NEAR(f_max / f_steady, 1.0, 0.01);
  EXPECT_NEAR(-f_min / f_steady, 1.0, 0.01);
  EXPECT_LT(std::fabs(f_mean), 0.01 * f_max);
}

// A standalone [waves] table needs the water's depth and level (there is no fill), and has no
// paddle; in a flume case the same keys are an error (the fill gives them).
TEST(StandaloneNet, WavesTableOfAStandaloneCaseTakesItsWaterFromItsKeys) {
  EXPECT_THROW(waves::small_rigid_net({"waves={height=0.1, period=2.0, still_water_level=0.0}"}),
               Error);
  try {
    waves::small_rigid_net(
        {"waves={height=0.1, period=2.0, depth=2.0, still_water_level=0.0, wavemaker=\"p\"}"});
    FAIL() << "a wavemaker was accepted in a standalone case";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("has no wavemaker"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace netsph
