// Case reader: every malformed file under tests/cases/bad must fail with the message (and
// line) its "# expect:" header names; the valid files under tests/cases/good must parse to
// the expected values, defaults included. Bodies: case_reader_bodies_test.cpp; --set:
// case_overrides_test.cpp.
#include "netsph/case/case_reader.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/core/quaternion.hpp"

#include "case_test_files.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;
using case_test::kCasesDir;
using case_test::kMinimal;

// ---- malformed files ----------------------------------------------------------------------

struct BadCase {
  std::string expect;  ///< substring of what()
  int line = 0;        ///< expected line of where(); 0: not checked
};

/// Reads the "# expect: ..." and "# expect-line: N" header comments of a bad case file.
BadCase read_expectations(const fs::path& path) {
  BadCase c;
  std::ifstream in(path);
  std::string line;
  const std::string expect_tag = "# expect: ";
  const std::string line_tag = "# expect-line: ";
  while (std::getline(in, line) && line.starts_with("#")) {
    if (line.starts_with(expect_tag)) c.expect = line.substr(expect_tag.size());
    if (line.starts_with(line_tag)) c.line = std::stoi(line.substr(line_tag.size()));
  }
  return c;
}

std::vector<fs::path> bad_case_files() {
  std::vector<fs::path> files;
  std::error_code ec;  // a missing folder must not abort test discovery: the count test fails
  for (const auto& entry : fs::directory_iterator(kCasesDir / "bad", ec)) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class BadCaseFile : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadCaseFile, FailsWithExpectedMessageAndPosition) {
  const fs::path& path = GetParam();
  const BadCase expected = read_expectations(path);
  ASSERT_FALSE(expected.expect.empty()) << path << " has no '# expect:' header line";
  try {
    read_case_file(path);
    FAIL() << path << " was accepted; expected an error containing: " << expected.expect;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(expected.expect), std::string::npos)
        << "what():   " << e.what() << "\nexpected: " << expected.expect;
    const std::string file = path.string();
    EXPECT_TRUE(e.where().starts_with(file)) << "where() does not name the file: " << e.where();
    if (expected.line > 0) {
      const std::string position = file + ":" + std::to_string(expected.line) + ":";
      EXPECT_TRUE(e.where().starts_with(position))
          << "where(): " << e.where() << "\nexpected line " << expected.line;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CaseReader, BadCaseFile, ::testing::ValuesIn(bad_case_files()),
                         [](const ::testing::TestParamInfo<fs::path>& param_info) {
                           return param_info.param.stem().string();
                         });

TEST(CaseReaderBadCases, FolderHoldsEnoughCases) {
  EXPECT_GE(bad_case_files().size(), 100u);
}

// ---- valid files --------------------------------------------------------------------------

constexpr double kEps = 1e-12;

TEST(CaseReader, FullFileParsesEveryKey) {
  const fs::path path = kCasesDir / "good" / "full3d.toml";
  const CaseSpec spec = read_case_file(path);
  EXPECT_EQ(spec.source, path.string());

  const SimulationSpec& s = spec.simulation;
  EXPECT_EQ(s.name, "tank3d");
  EXPECT_EQ(s.dimensions, 3);
  EXPECT_DOUBLE_EQ(s.dp, 0.02);
  EXPECT_DOUBLE_EQ(s.h_over_dp, 2.0);
  EXPECT_EQ(s.kernel, KernelType::CubicSpline);
  EXPECT_DOUBLE_EQ(s.end_time, 1.5);
  EXPECT_DOUBLE_EQ(s.cfl, 0.25);
  EXPECT_DOUBLE_EQ(s.dt_min, 1e-7);
  EXPECT_DOUBLE_EQ(s.dt_max, 1e-3);

  const FluidSpec& f = spec.fluid;
  EXPECT_DOUBLE_EQ(f.density, 998.0);  // written as an integer
  EXPECT_DOUBLE_EQ(f.sound_speed, 35.0);
  EXPECT_DOUBLE_EQ(f.sound_speed_coef, 20.0);
  EXPECT_DOUBLE_EQ(f.gamma, 7.0);
  EXPECT_EQ(f.gravity, (Vec3d{0, 0, -9.81}));
  EXPECT_EQ(f.viscosity, ViscosityModel::Laminar);
  EXPECT_DOUBLE_EQ(f.kinematic_viscosity, 1e-6);
  EXPECT_DOUBLE_EQ(f.alpha, 0.01);  // default, unused by laminar
  EXPECT_EQ(f.density_diffusion, DensityDiffusion::Fourtakas);
  EXPECT_DOUBLE_EQ(f.delta, 0.2);
  EXPECT_EQ(f.shifting, ShiftingModel::None);  // default without open boundaries

  EXPECT_TRUE(spec.domain.given);
  EXPECT_EQ(spec.domain.min, (Vec3d{-0.2, -0.2, -0.2}));
  EXPECT_EQ(spec.domain.max, (Vec3d{2.2, 1.2, 1.5}));
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{false, false, false}));

  ASSERT_EQ(spec.fills.size(), 2u);
  EXPECT_EQ(spec.fills[0].box.min, (Vec3d{0, 0, 0}));
  EXPECT_EQ(spec.fills[0].box.max, (Vec3d{0.5, 1, 0.4}));
  EXPECT_EQ(spec.fills[0].velocity, (Vec3d{0.1, -0.2, 0}));
  ASSERT_TRUE(spec.fills[0].surface_z.has_value());
  EXPECT_DOUBLE_EQ(*spec.fills[0].surface_z, 0.4);
  EXPECT_EQ(spec.fills[0].where.str(), path.string() + ":25:1");
  EXPECT_EQ(spec.fills[1].velocity, (Vec3d{0, 0, 0}));
  EXPECT_FALSE(spec.fills[1].surface_z.has_value());
  EXPECT_EQ(spec.fills[1].where.line, 31);

  ASSERT_EQ(spec.walls.size(), 2u);
  const WallSpec& tank = spec.walls[0];
  EXPECT_EQ(tank.name, "tank");
  EXPECT_EQ(tank.box.max, (Vec3d{2, 1, 1.2}));
  EXPECT_EQ(tank.faces, (std::array<bool, 6>{true, true, true, true, true, false}));
  EXPECT_EQ(tank.layers, 4);
  EXPECT_EQ(tank.model, WallModel::Dbc);
  EXPECT_EQ(tank.slip, WallSlip::WallVelocity);  // default (unused by DBC)
  EXPECT_FALSE(tank.motion.moving());
  EXPECT_EQ(tank.where.line, 35);
  const WallSpec& post = spec.walls[1];
  EXPECT_EQ(post.name, "wall2");  // default: 1-based index
  EXPECT_EQ(post.faces, (std::array<bool, 6>{true, true, true, true, true, true}));
  EXPECT_EQ(post.layers, 4);  // default ceil(2 h_over_dp) at h_over_dp = 2
  EXPECT_EQ(post.model, WallModel::Dbc);
  EXPECT_TRUE(spec.inlets.empty());
  EXPECT_TRUE(spec.outlets.empty());

  EXPECT_FALSE(spec.output.snapshots);
  EXPECT_DOUBLE_EQ(spec.output.snapshot_every, 0.1);
  EXPECT_DOUBLE_EQ(spec.output.series_every, 0.01);
}

TEST(CaseReader, MinimalTwoDimensionalFileTakesDefaults) {
  const fs::path path = kCasesDir / "good" / "dambreak2d.toml";
  const CaseSpec spec = read_case_file(path);
  const SimulationSpec& s = spec.simulation;
  EXPECT_EQ(s.name, "dambreak2d");  // the file stem
  EXPECT_EQ(s.dimensions, 2);
  EXPECT_DOUBLE_EQ(s.h_over_dp, 1.5);
  EXPECT_EQ(s.kernel, KernelType::Wendland);
  EXPECT_DOUBLE_EQ(s.cfl, 0.2);
  EXPECT_DOUBLE_EQ(s.dt_min, 0);
  EXPECT_DOUBLE_EQ(s.dt_max, 0);

  const FluidSpec& f = spec.fluid;
  EXPECT_DOUBLE_EQ(f.density, 1000);
  EXPECT_DOUBLE_EQ(f.sound_speed, 0);  // 0: derived from sound_speed_coef
  EXPECT_DOUBLE_EQ(f.sound_speed_coef, 20);
  EXPECT_DOUBLE_EQ(f.gamma, 7);
  EXPECT_EQ(f.gravity, (Vec3d{0, 0, -9.81}));
  EXPECT_EQ(f.viscosity, ViscosityModel::Artificial);
  EXPECT_DOUBLE_EQ(f.alpha, 0.01);
  EXPECT_EQ(f.density_diffusion, DensityDiffusion::Molteni);
  EXPECT_DOUBLE_EQ(f.delta, 0.1);
  EXPECT_EQ(f.shifting, ShiftingModel::None);
  EXPECT_DOUBLE_EQ(f.shifting_coefficient, 2.0);
  EXPECT_DOUBLE_EQ(f.shifting_surface_threshold, 0);
  EXPECT_FALSE(spec.domain.given);
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{false, false, false}));

  ASSERT_EQ(spec.fills.size(), 1u);
  EXPECT_EQ(spec.fills[0].box.min, (Vec3d{0, 0, 0}));  // y is ignored in 2D and set to 0
  EXPECT_EQ(spec.fills[0].box.max, (Vec3d{0.6, 0, 0.6}));

  ASSERT_EQ(spec.walls.size(), 1u);
  // 2D default: the four x/z faces.
  EXPECT_EQ(spec.walls[0].faces, (std::array<bool, 6>{true, true, false, false, true, true}));
  EXPECT_EQ(spec.walls[0].layers, 3);
  EXPECT_EQ(spec.walls[0].model, WallModel::Mdbc);  // 3 layers cover 2h at h_over_dp = 1.5
  EXPECT_EQ(spec.walls[0].slip, WallSlip::WallVelocity);
  EXPECT_FALSE(spec.walls[0].motion.moving());
  EXPECT_TRUE(spec.inlets.empty());
  EXPECT_TRUE(spec.outlets.empty());

  EXPECT_TRUE(spec.output.snapshots);
  EXPECT_DOUBLE_EQ(spec.output.snapshot_every, 0);
  EXPECT_DOUBLE_EQ(spec.output.series_every, 0);
}

TEST(CaseReader, OpenChannelFileParsesEveryOpenFlowKey) {
  const fs::path path = kCasesDir / "good" / "channel3d.toml";
  const CaseSpec spec = read_case_file(path);

  const FluidSpec& f = spec.fluid;
  EXPECT_EQ(f.shifting, ShiftingModel::Fickian);
  EXPECT_DOUBLE_EQ(f.shifting_coefficient, 1.5);
  EXPECT_DOUBLE_EQ(f.shifting_surface_threshold, 2.5);
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{false, true, false}));

  ASSERT_EQ(spec.walls.size(), 3u);
  const WallSpec& bed = spec.walls[0];
  EXPECT_EQ(bed.model, WallModel::Mdbc);  // default
  EXPECT_EQ(bed.slip, WallSlip::FreeSlip);
  EXPECT_EQ(bed.layers, 3);
  EXPECT_FALSE(bed.motion.moving());
  const WallSpec& gate = spec.walls[1];
  EXPECT_EQ(gate.model, WallModel::Mdbc);
  EXPECT_EQ(gate.slip, WallSlip::WallVelocity);
  ASSERT_TRUE(gate.motion.moving());
  EXPECT_EQ(gate.motion.times, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(gate.motion.velocities, (std::vector<Vec3d>{{0, 0, 0}, {0, 0, 0.2}, {0, 0, 0}}));
  EXPECT_NEAR(gate.motion.at(0.25).z, 0.1, kEps);
  const WallSpec& paddle = spec.walls[2];
  EXPECT_EQ(paddle.model, WallModel::Dbc);
  EXPECT_EQ(paddle.layers, 1);  // the mDBC layer rule does not apply to DBC
  EXPECT_EQ(paddle.motion.times, (std::vector<double>{0}));
  EXPECT_EQ(paddle.motion.velocities, (std::vector<Vec3d>{{0.1, 0, 0}}));

  ASSERT_EQ(spec.inlets.size(), 1u);
  const OpenBoundarySpec& in = spec.inlets[0];
  EXPECT_EQ(in.name, "upstream");
  EXPECT_EQ(in.face, kXMin);
  EXPECT_EQ(in.layers, 5);
  EXPECT_FALSE(in.velocity.has_value());
  EXPECT_EQ(in.profile_z, (std::vector<double>{0, 0.3}));
  EXPECT_EQ(in.profile_u, (std::vector<double>{0.3, 0.6}));
  EXPECT_EQ(in.density, BufferDensity::Hydrostatic);
  ASSERT_TRUE(in.surface_z.has_value());
  EXPECT_DOUBLE_EQ(*in.surface_z, 0.3);
  EXPECT_EQ(in.where.str(), path.string() + ":42:1");

  ASSERT_EQ(spec.outlets.size(), 1u);
  const OpenBoundarySpec& out = spec.outlets[0];
  EXPECT_EQ(out.name, "outlet1");  // defaults
  EXPECT_EQ(out.face, kXMax);
  EXPECT_EQ(out.layers, 4);
  ASSERT_TRUE(out.velocity.has_value());
  EXPECT_DOUBLE_EQ(*out.velocity, 0.45);
  EXPECT_TRUE(out.profile_z.empty());
  EXPECT_EQ(out.density, BufferDensity::Extrapolated);
  EXPECT_FALSE(out.surface_z.has_value());
}

TEST(CaseReader, ModelsMayBeBareStrings) {
  const CaseSpec spec = read_case_string(
      kMinimal + "[fluid]\nviscosity = \"laminar\"\ndensity_diffusion = \"none\"\n", "test");
  EXPECT_EQ(spec.fluid.viscosity, ViscosityModel::Laminar);
  EXPECT_DOUBLE_EQ(spec.fluid.kinematic_viscosity, 1e-6);
  EXPECT_EQ(spec.fluid.density_diffusion, DensityDiffusion::None);
}

/// kMinimal with a [domain] around the fill, so that open boundaries can be added.
const std::string kWithDomain = kMinimal + R"(
[domain]
min = [0, 0, 0]
max = [2, 1, 1]
)";

TEST(CaseReader, ShiftingDefaultsToFickianWithOpenBoundaries) {
  EXPECT_EQ(read_case_string(kWithDomain, "closed").fluid.shifting, ShiftingModel::None);
  const std::string inlet = "[[inlet]]\nface = \"xmin\"\nvelocity = 0.5\n";
  EXPECT_EQ(read_case_string(kWithDomain + inlet, "inlet").fluid.shifting, ShiftingModel::Fickian);
  const std::string outlet = "[[outlet]]\nface = \"xmax\"\n";
  const CaseSpec with_outlet = read_case_string(kWithDomain + outlet, "outlet");
  EXPECT_EQ(with_outlet.fluid.shifting, ShiftingModel::Fickian);
  EXPECT_DOUBLE_EQ(with_outlet.fluid.shifting_coefficient, 2.0);
  EXPECT_DOUBLE_EQ(with_outlet.fluid.shifting_surface_threshold, 0);
  // An explicit choice wins over the default, either way.
  EXPECT_EQ(read_case_string(kWithDomain + "[fluid]\nshifting = \"none\"\n" + inlet, "off")
                .fluid.shifting,
            ShiftingModel::None);
  EXPECT_EQ(
      read_case_string(kWithDomain + "[fluid]\nshifting = \"fickian\"\n", "on").fluid.shifting,
      ShiftingModel::Fickian);
}

TEST(CaseReader, ShiftingTableWithoutModelMeansFickian) {
  const CaseSpec spec =
      read_case_string(kMinimal + "[fluid]\nshifting = { coefficient = 10 }\n", "table");
  EXPECT_EQ(spec.fluid.shifting, ShiftingModel::Fickian);
  EXPECT_DOUBLE_EQ(spec.fluid.shifting_coefficient, 10);
  EXPECT_DOUBLE_EQ(spec.fluid.shifting_surface_threshold, 0);
}

TEST(CaseReader, OpenBoundaryDefaultsAndUniformInletVelocity) {
  const CaseSpec spec = read_case_string(kWithDomain + R"(
[[inlet]]
face = "xmin"
velocity = 0.5

[[inlet]]
face = "ymin"
velocity = 0.25

[[outlet]]
face = "xmax"
)",
                                         "open");
  ASSERT_EQ(spec.inlets.size(), 2u);
  EXPECT_EQ(spec.inlets[0].name, "inlet1");
  EXPECT_EQ(spec.inlets[1].name, "inlet2");
  EXPECT_EQ(spec.inlets[1].face, kYMin);
  EXPECT_EQ(spec.inlets[0].layers, 4);
  ASSERT_TRUE(spec.inlets[0].velocity.has_value());
  EXPECT_DOUBLE_EQ(*spec.inlets[0].velocity, 0.5);
  EXPECT_TRUE(spec.inlets[0].profile_z.empty());
  EXPECT_EQ(spec.inlets[0].density, BufferDensity::Extrapolated);
  EXPECT_FALSE(spec.inlets[0].surface_z.has_value());
  ASSERT_EQ(spec.outlets.size(), 1u);
  EXPECT_EQ(spec.outlets[0].name, "outlet1");
  EXPECT_FALSE(spec.outlets[0].velocity.has_value());  // extrapolated
}

TEST(CaseReader, TwoDimensionalOpenChannel) {
  const CaseSpec spec = read_case_string(R"(
[simulation]
dimensions = 2
dp = 0.01
h_over_dp = 2.0
end_time = 1

[domain]
min = [0, 0, 0]
max = [1, 0, 0.5]
periodic = []

[[fill]]
min = [0, 0, 0]
max = [1, 0, 0.2]

[[wall]]
min = [0, 0, 0]
max = [1, 0, 0.5]
faces = ["zmin"]
layers = 4

[[inlet]]
face = "xmin"
profile = { z = [0, 0.1, 0.2], u = [0, 0.4, 0.5] }

[[outlet]]
face = "xmax"
layers = 4
)",
                                         "channel2d");
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{false, false, false}));  // [] = none
  EXPECT_EQ(spec.walls[0].model, WallModel::Mdbc);
  EXPECT_EQ(spec.walls[0].layers, 4);  // 4 dp = 2h at h_over_dp = 2
  EXPECT_EQ(spec.inlets[0].profile_u, (std::vector<double>{0, 0.4, 0.5}));
  EXPECT_EQ(spec.fluid.shifting, ShiftingModel::Fickian);
}

TEST(CaseReader, PeriodicAxesIn2DAreXAndZ) {
  const CaseSpec spec = read_case_string(R"(
[simulation]
dimensions = 2
dp = 0.02
end_time = 1

[domain]
min = [0, 0, 0]
max = [2, 0, 1]
periodic = ["z", "x"]

[[fill]]
min = [0, 0, 0]
max = [1, 0, 0.5]
)",
                                         "periodic2d");
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{true, false, true}));
}

// A flume's walls along a periodic axis: a period of whole dp passes, to the few digits a user
// copies from the error's suggestion; a wall shorter than the period, or a period of fractional
// dp with no wall spanning it, is not checked (tests/cases/bad has the error itself).
TEST(CaseReader, WallsAcrossAPeriodNeedAWholeNumberOfDp) {
  const auto flume = [](const std::string& dp, const std::string& wall_max_x) {
    return "[simulation]\ndp = " + dp +
           "\nend_time = 1\n[domain]\nmin = [-0.3, -0.33, -0.5]\nmax = [0.5, 0.33, 0.1]\n"
           "periodic = [\"x\"]\n[[fill]]\nmin = [-0.3, -0.225, -0.4]\nmax = [0.5, 0.225, 0.0]\n"
           "[[wall]]\nmin = [-0.3, -0.225, -0.4]\nmax = [" +
           wall_max_x + ", 0.225, 0.0]\nfaces = [\"ymin\", \"ymax\", \"zmin\", \"zmax\"]\n";
  };
  EXPECT_NO_THROW(read_case_string(flume("0.0125", "0.5"), "64dp"));
  EXPECT_NO_THROW(read_case_string(flume("0.00601504", "0.5"), "133dp"));  // 0.8 / 133
  EXPECT_NO_THROW(read_case_string(flume("0.006", "0.4"), "short"));
  EXPECT_THROW(read_case_string(flume("0.006", "0.5"), "fractional"), Error);
  try {
    read_case_string(flume("0.0075", "0.5"), "crowded");
    FAIL() << "a period of 106.7 dp was accepted";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("0.667 dp apart instead of 1"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("such as 0.00747663551 m (107 spacings) or 0.00754716981 m (106)"),
              std::string::npos)
        << e.message();
  }
}

TEST(CaseReader, WallVelocityIsAConstantMotion) {
  const CaseSpec spec = read_case_string(kMinimal +
                                             "[[wall]]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"
                                             "velocity = [0.5, 0, -0.1]\n",
                                         "moving");
  const VelocityHistory& m = spec.walls[0].motion;
  ASSERT_TRUE(m.moving());
  EXPECT_EQ(m.times, (std::vector<double>{0}));
  EXPECT_EQ(m.at(3.0), (Vec3d{0.5, 0, -0.1}));
}

TEST(CaseReader, MdbcLayerRuleFollowsTheSmoothingLength) {
  const std::string sim =
      "[simulation]\ndp = 0.02\nend_time = 1\nh_over_dp = 2\n"
      "[[fill]]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"
      "[[wall]]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n";
  EXPECT_EQ(read_case_string(sim + "layers = 4\n", "four").walls[0].layers, 4);
  EXPECT_EQ(read_case_string(sim + "layers = 1\nmodel = \"dbc\"\n", "dbc").walls[0].layers, 1);
  try {
    read_case_string(sim + "layers = 3\n", "three");
    FAIL() << "3 mDBC layers at h_over_dp = 2 were accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "three:11:10");
    EXPECT_NE(e.message().find("kernel support 2h = 0.08 m (4 dp at h_over_dp = 2)"),
              std::string::npos)
        << e.message();
  }
}

TEST(CaseReader, ArraysOfInlineTablesCountAsArraysOfTables) {
  const CaseSpec spec = read_case_string(
      "fill = [{ min = [0, 0, 0], max = [1, 1, 1] }]\n[simulation]\ndp = 0.02\nend_time = 1\n",
      "inline");
  ASSERT_EQ(spec.fills.size(), 1u);
  EXPECT_EQ(spec.fills[0].box.max, (Vec3d{1, 1, 1}));
}

TEST(CaseReader, SourceNameOfAStringAppearsInErrorsAndAsDefaultName) {
  EXPECT_EQ(read_case_string(kMinimal, "builtin:test").simulation.name, "builtin:test");
  EXPECT_EQ(read_case_string(kMinimal, "builtin:test").source, "builtin:test");
  try {
    read_case_string("[simulation]\ndp = -1\nend_time = 1\n", "builtin:test");
    FAIL() << "dp = -1 was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "builtin:test:2:6");
    EXPECT_EQ(e.message(), "simulation.dp = -1: must be in [1e-06, 1000] m");
  }
  try {
    read_case_string("[simulation\n", "builtin:broken");
    FAIL() << "syntax error was accepted";
  } catch (const Error& e) {
    EXPECT_TRUE(e.where().starts_with("builtin:broken:1:")) << e.where();
    EXPECT_NE(e.message().find("TOML syntax error"), std::string::npos) << e.message();
  }
}

TEST(CaseReader, UnknownKeyIsReportedBeforeTheMissingKeyItHides) {
  try {
    read_case_string("[simulation]\ndp = 0.02\nend_tme = 1\n", "typo");
    FAIL() << "end_tme was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "typo:3:1");
    EXPECT_NE(e.message().find("unknown key 'end_tme' in [simulation] (did you mean 'end_time'?)"),
              std::string::npos)
        << e.message();
  }
}

TEST(CaseReader, UnreadableFileIsNamed) {
  const fs::path path = kCasesDir / "good" / "does_not_exist.toml";
  try {
    read_case_file(path);
    FAIL() << "a missing file was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), path.string());
    EXPECT_NE(e.message().find("cannot read the file"), std::string::npos) << e.message();
  }
  EXPECT_THROW(read_case_file(kCasesDir / "good"), Error);  // a directory
}

// /dev/zero was read until std::bad_alloc, with no file named (issue 46).
TEST(CaseReader, DeviceOrPipeIsRefusedByName) {
  for (const char* device : {"/dev/zero", "/dev/null", "/dev/urandom"}) {
    if (!fs::exists(device)) continue;
    try {
      read_case_file(device);
      FAIL() << device << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.where(), device);
      EXPECT_NE(e.message().find("not a regular file"), std::string::npos) << e.message();
    }
  }
  const fs::path fifo =
      fs::temp_directory_path() / ("netsph_case_fifo_" + std::to_string(::getpid()));
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    read_case_file(fifo);  // must not wait for a writer
    ADD_FAILURE() << "a FIFO was accepted";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("not a regular file"), std::string::npos) << e.message();
  }
  fs::remove(fifo);
}

TEST(CaseReader, FileLargerThanTheLimitIsRefusedByName) {
  const fs::path big =
      fs::temp_directory_path() / ("netsph_case_big_" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(big, std::ios::binary);
    out << kMinimal;
    out << std::string(kMaxCaseFileBytes, '#');  // a comment: valid TOML, only too long
  }
  try {
    read_case_file(big);
    ADD_FAILURE() << "a file of " << fs::file_size(big) << " bytes was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), big.string());
    EXPECT_NE(e.message().find("larger than 4 MiB"), std::string::npos) << e.message();
  }
  fs::resize_file(big, std::string_view(kMinimal).size());
  EXPECT_NO_THROW(read_case_file(big));
  fs::remove(big);
}

TEST(SourceLocation, FormatsFileLineColumn) {
  EXPECT_EQ((SourceLocation{"a.toml", 3, 7}.str()), "a.toml:3:7");
  EXPECT_EQ((SourceLocation{"--set x=1", 0, 0}.str()), "--set x=1");
}

}  // namespace
}  // namespace netsph
