// A piston wavemaker makes the wave it is asked for: the 2D flume of
// cases/waves/regular_piston2d.toml (depth 0.5 m, kh = 1.5, H = 0.06 m, H/L = 0.029) run at a
// coarse resolution, dp = 0.02 m (3 particles per wave height), until five periods after the
// ramp's front has passed the gauge one wavelength from the paddle. The gauge's zero
// up-crossing waves over the last three periods must have:
//   - the paddle's period within 1%: a linear wavemaker forces the period; the gauge, sampled
//     every T/40 with crossings interpolated linearly, locates a crossing to (2 pi/40)^2/8 of a
//     sample interval (1e-4 T), so 1% leaves room for the wave's own nonlinearity only;
//   - the target height (first-order wavemaker theory) within 15%: at this resolution the
//     kernel spans the whole wave height and the viscosity damps the wave; docs/VALIDATION.md
//     measures the loss at three resolutions (6.4% at one wavelength at this dp, 4.9% at
//     dp/2), and 15% asserts that the wave is made, not how finely it is resolved;
//   - a mean level within 5% of H of the still water: the fluid's mass stays in the flume.
// `netsph validate --only waves_regular` measures the same at dp = 20 and 10 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "case_runs.hpp"
#include "netsph/run/runner.hpp"

namespace netsph {
namespace {

TEST(WaveFlume, PistonMakesTheTargetWaveOneWavelengthDownTheFlume) {
  const CaseSpec spec = test::load_case(
      "waves/regular_piston2d.toml", {"simulation.dp=0.02", "simulation.end_time=8.6",
                                      "output.force_window=[4.9, 8.6]", "output.snapshots=false"});
  Simulation sim(spec);
  RunOptions opt;
  opt.out_dir = std::filesystem::temp_directory_path() / "netsph_wave_flume_test";
  opt.progress = false;
  std::filesystem::remove_all(opt.out_dir);
  const RunReport report = run_simulation(sim, opt);
  ASSERT_EQ(report.status, "completed") << report.message;
  std::ifstream in(opt.out_dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  const nlohmann::json* gauge = nullptr;
  for (const auto& g : summary.at("gauges"))
    if (g.at("name") == "one_L") gauge = &g;
  ASSERT_NE(gauge, nullptr);
  const nlohmann::json& measured = gauge->at("measured");
  const nlohmann::json& target = gauge->at("target");
  ASSERT_GE(measured.at("waves").get<int>(), 2);
  const double height = measured.at("mean_height_m"), period = measured.at("mean_period_s");
  std::printf("one_L: H = %.4f m (target %.4f), T = %.4f s (target %.4f), mean level %.2e m\n",
              height, target.at("mean_height_m").get<double>(), period,
              target.at("mean_period_s").get<double>(), measured.at("mean_level_m").get<double>());
  EXPECT_NEAR(period, spec.waves.period, 0.01 * spec.waves.period);
  EXPECT_NEAR(height, spec.waves.height, 0.15 * spec.waves.height);
  EXPECT_NEAR(gauge->at("height_ratio").get<double>(),
              height / target.at("mean_height_m").get<double>(), 1e-12);
  EXPECT_LT(std::fabs(measured.at("mean_level_m").get<double>()), 0.05 * spec.waves.height);
  // gauges.csv holds a row per gauge interval with every gauge and its target.
  std::ifstream csv(opt.out_dir / "gauges.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "time [s],half_L [m],half_L_target [m],one_L [m],one_L_target [m],one_and_half_L "
            "[m],one_and_half_L_target [m],refl_1 [m],refl_1_target [m],refl_2 [m],refl_2_target "
            "[m],refl_3 [m],refl_3_target [m]");
}

}  // namespace
}  // namespace netsph
