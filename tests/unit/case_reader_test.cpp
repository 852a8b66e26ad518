// Case reader: every malformed file under tests/cases/bad must fail with the message (and
// line) its "# expect:" header names; the valid files under tests/cases/good must parse to
// the expected values, defaults included; --set overrides and their errors.
#include "netsph/case/case_reader.hpp"

#include <gtest/gtest.h>

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

namespace netsph {
namespace {

namespace fs = std::filesystem;

/// tests/cases. NETSPH_TEST_CASES_DIR should name it; when it does not exist (the macro is
/// built from the CMake folder the test is registered in), use the folder beside this file's.
fs::path cases_dir() {
  const fs::path configured = NETSPH_TEST_CASES_DIR;
  std::error_code ec;
  if (fs::is_directory(configured / "bad", ec)) return configured;
  return fs::path(__FILE__).parent_path().parent_path() / "cases";
}

const fs::path kCasesDir = cases_dir();

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

const std::string kMinimal = R"(
[simulation]
dp = 0.02
end_time = 1.0

[[fill]]
min = [0, 0, 0]
max = [1, 1, 1]
)";

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
    EXPECT_EQ(e.message(), "simulation.dp = -1: must be > 0 m");
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

TEST(SourceLocation, FormatsFileLineColumn) {
  EXPECT_EQ((SourceLocation{"a.toml", 3, 7}.str()), "a.toml:3:7");
  EXPECT_EQ((SourceLocation{"--set x=1", 0, 0}.str()), "--set x=1");
}

// ---- [[body]] -----------------------------------------------------------------------------

constexpr double kTol = 1e-12;

void expect_near(const Vec3d& actual, const Vec3d& expected, const std::string& what) {
  EXPECT_NEAR(actual.x, expected.x, kTol) << what;
  EXPECT_NEAR(actual.y, expected.y, kTol) << what;
  EXPECT_NEAR(actual.z, expected.z, kTol) << what;
}

void expect_unit(const Quat& q) {
  EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1.0, kTol);
}

const double kS = std::sqrt(0.5);

TEST(CaseReaderBodies, FileParsesEveryBodyKey) {
  const fs::path path = kCasesDir / "good" / "bodies3d.toml";
  const CaseSpec spec = read_case_file(path);
  ASSERT_EQ(spec.bodies.size(), 7u);

  const BodySpec& cyl = spec.bodies[0];  // defaults
  EXPECT_EQ(cyl.name, "body1");
  EXPECT_EQ(cyl.group, "body1");
  EXPECT_EQ(cyl.shape_name, "cylinder");
  EXPECT_EQ(cyl.shape, BodyShape::Cylinder);
  EXPECT_DOUBLE_EQ(cyl.diameter, 0.05);
  EXPECT_DOUBLE_EQ(cyl.length, 1.0);
  EXPECT_EQ(cyl.center, (Vec3d{1.0, 0.5, 0.3}));
  expect_near(rotate(cyl.orientation, {1, 0, 0}), {0, 1, 0}, "default cylinder axis");
  expect_unit(cyl.orientation);
  EXPECT_EQ(cyl.motion, BodyMotion::Fixed);
  EXPECT_EQ(cyl.model, WallModel::Mdbc);
  EXPECT_EQ(cyl.slip, WallSlip::WallVelocity);
  EXPECT_EQ(cyl.layers, 0);
  EXPECT_FALSE(cyl.velocity.moving());
  EXPECT_FALSE(cyl.mass.has_value());
  ASSERT_TRUE(cyl.reference_velocity.has_value());
  EXPECT_DOUBLE_EQ(*cyl.reference_velocity, 0.5);
  ASSERT_TRUE(cyl.reference_area.has_value());
  EXPECT_DOUBLE_EQ(*cyl.reference_area, 0.05);
  EXPECT_EQ(cyl.where.str(), path.string() + ":21:1");

  // normal [0, 0, 2] takes local x up (about -y, so local z goes to -x); the rotation about z
  // comes after it: x stays up, y goes to -x, z to -y.
  const BodySpec& knot1 = spec.bodies[1];
  EXPECT_EQ(knot1.name, "knot1");
  EXPECT_EQ(knot1.group, "net");
  EXPECT_EQ(knot1.shape_name, "plate");
  EXPECT_EQ(knot1.shape, BodyShape::Box);
  EXPECT_EQ(knot1.lengths, (Vec3d{0.004, 0.1, 0.2}));
  expect_near(rotate(knot1.orientation, {1, 0, 0}), {0, 0, 1}, "normal after rotation");
  expect_near(rotate(knot1.orientation, {0, 1, 0}), {-1, 0, 0}, "local y");
  expect_near(rotate(knot1.orientation, {0, 0, 1}), {0, -1, 0}, "local z");
  expect_unit(knot1.orientation);
  EXPECT_EQ(knot1.model, WallModel::Dbc);
  EXPECT_EQ(knot1.layers, -1);

  const BodySpec& knot2 = spec.bodies[2];  // antiparallel normal: half a turn about y
  EXPECT_EQ(knot2.group, "net");
  EXPECT_EQ(knot2.shape_name, "square_plate");
  EXPECT_EQ(knot2.shape, BodyShape::Box);
  EXPECT_EQ(knot2.lengths, (Vec3d{0.005, 0.15, 0.15}));
  expect_near(rotate(knot2.orientation, {1, 0, 0}), {-1, 0, 0}, "antiparallel normal");
  expect_near(rotate(knot2.orientation, {0, 1, 0}), {0, 1, 0}, "antiparallel: y kept");
  expect_unit(knot2.orientation);
  EXPECT_EQ(knot2.slip, WallSlip::NoSlip);
  EXPECT_EQ(knot2.layers, 4);

  const BodySpec& disc = spec.bodies[3];
  EXPECT_EQ(disc.shape_name, "circular_plate");
  EXPECT_EQ(disc.shape, BodyShape::Cylinder);
  EXPECT_DOUBLE_EQ(disc.diameter, 0.2);
  EXPECT_DOUBLE_EQ(disc.length, 0.01);
  expect_near(rotate(disc.orientation, {1, 0, 0}), {0, kS, kS}, "normalised normal");
  EXPECT_EQ(disc.motion, BodyMotion::Floating);
  EXPECT_DOUBLE_EQ(disc.density, 500);
  EXPECT_FALSE(disc.mass.has_value());
  EXPECT_EQ(disc.initial_velocity, (Vec3d{0.1, 0, 0}));

  const BodySpec& buoy = spec.bodies[4];
  EXPECT_EQ(buoy.group, "buoy");  // default: the name
  EXPECT_EQ(buoy.shape, BodyShape::Box);
  EXPECT_EQ(buoy.lengths, (Vec3d{0.2, 0.1, 0.05}));
  expect_near(rotate(buoy.orientation, {1, 0, 0}), {1, 0, 0}, "box x");
  expect_near(rotate(buoy.orientation, {0, 1, 0}), {0, std::cos(std::numbers::pi / 6), 0.5},
              "box y");
  EXPECT_EQ(buoy.motion, BodyMotion::Floating);
  EXPECT_DOUBLE_EQ(buoy.density, 0);
  ASSERT_TRUE(buoy.mass.has_value());
  EXPECT_DOUBLE_EQ(*buoy.mass, 2.0);
  EXPECT_EQ(buoy.initial_velocity, (Vec3d{0, 0, 0}));

  const BodySpec& sphere = spec.bodies[5];
  EXPECT_EQ(sphere.shape, BodyShape::Sphere);
  EXPECT_DOUBLE_EQ(sphere.diameter, 0.1);
  EXPECT_EQ(sphere.orientation.w, 1.0);
  EXPECT_EQ(sphere.motion, BodyMotion::Prescribed);
  EXPECT_EQ(sphere.velocity.times, (std::vector<double>{0}));
  EXPECT_EQ(sphere.velocity.velocities, (std::vector<Vec3d>{{0.2, 0, 0}}));

  const BodySpec& cross = spec.bodies[6];
  EXPECT_EQ(cross.shape, BodyShape::Cruciform);
  EXPECT_DOUBLE_EQ(cross.length, 0.1);
  EXPECT_DOUBLE_EQ(cross.diameter, 0.004);
  expect_near(rotate(cross.orientation, {1, 0, 0}), {kS, kS, 0}, "cruciform normal");
  EXPECT_EQ(cross.motion, BodyMotion::Prescribed);
  EXPECT_EQ(cross.velocity.times, (std::vector<double>{0, 1}));
  EXPECT_EQ(cross.velocity.velocities, (std::vector<Vec3d>{{0, 0, 0}, {0, 0, 0.1}}));
  EXPECT_NEAR(cross.velocity.at(0.5).z, 0.05, kEps);
  EXPECT_EQ(cross.slip, WallSlip::FreeSlip);
  EXPECT_EQ(cross.layers, 0);

  ASSERT_TRUE(spec.output.force_window.has_value());
  EXPECT_EQ(*spec.output.force_window, (std::array<double, 2>{1.0, 2.0}));
}

TEST(CaseReaderBodies, TwoDimensionalBodiesStayInThePlane) {
  const CaseSpec spec = read_case_file(kCasesDir / "good" / "bodies2d.toml");
  ASSERT_EQ(spec.bodies.size(), 3u);
  const BodySpec& cyl = spec.bodies[0];
  EXPECT_EQ(cyl.center, (Vec3d{0.5, 0, 0.2}));  // y ignored
  expect_near(rotate(cyl.orientation, {1, 0, 0}), {0, 1, 0}, "2D cylinder axis");
  EXPECT_DOUBLE_EQ(*cyl.reference_area, 0.05);

  // normal [1, 0, 1] then 45 degrees about +y (x towards -z): back to the identity.
  const BodySpec& plate = spec.bodies[1];
  expect_near(rotate(plate.orientation, {1, 0, 0}), {1, 0, 0}, "plate normal");
  expect_near(rotate(plate.orientation, {0, 0, 1}), {0, 0, 1}, "plate local z");
  EXPECT_NEAR(plate.orientation.x, 0, kTol);  // only turns about y in 2D
  EXPECT_NEAR(plate.orientation.z, 0, kTol);

  const BodySpec& box = spec.bodies[2];
  EXPECT_EQ(box.motion, BodyMotion::Floating);
  EXPECT_DOUBLE_EQ(*box.mass, 1.5);
  EXPECT_EQ(box.initial_velocity, (Vec3d{0.1, 0, -0.1}));
  EXPECT_FALSE(spec.output.force_window.has_value());
}

/// kMinimal with one [[body]] made of `keys`.
CaseSpec read_body(const std::string& keys) {
  return read_case_string(kMinimal + "[[body]]\ncenter = [0.5, 0.5, 0.5]\n" + keys, "body");
}

TEST(CaseReaderBodies, MinimalBodyTakesDefaults) {
  const CaseSpec spec = read_body("shape = \"sphere\"\ndiameter = 0.1\n");
  ASSERT_EQ(spec.bodies.size(), 1u);
  const BodySpec& b = spec.bodies[0];
  EXPECT_EQ(b.name, "body1");
  EXPECT_EQ(b.group, "body1");
  EXPECT_EQ(b.shape_name, "sphere");
  EXPECT_EQ(b.motion, BodyMotion::Fixed);
  EXPECT_EQ(b.model, WallModel::Mdbc);
  EXPECT_EQ(b.slip, WallSlip::WallVelocity);
  EXPECT_EQ(b.layers, 0);
  EXPECT_DOUBLE_EQ(b.density, 0);
  EXPECT_FALSE(b.mass.has_value());
  EXPECT_FALSE(b.velocity.moving());
  EXPECT_FALSE(b.reference_velocity.has_value());
  EXPECT_FALSE(b.reference_area.has_value());
  EXPECT_EQ(b.orientation.w, 1.0);
  EXPECT_EQ(b.where.str(), "body:9:1");
  EXPECT_FALSE(spec.output.force_window.has_value());
  EXPECT_TRUE(read_case_string(kMinimal, "none").bodies.empty());
}

TEST(CaseReaderBodies, NormalIsLocalXForEveryDirection) {
  const std::vector<Vec3d> normals = {{1, 0, 0},
                                      {-1, 0, 0},
                                      {0, 1, 0},
                                      {0, -1, 0},
                                      {0, 0, 1},
                                      {0, 0, -1},
                                      {1, 2, 3},
                                      {-3, 0.5, -0.2},
                                      {-1, 1e-9, 0},
                                      {-1, 0, -1e-15},
                                      {-1, -1e-13, 1e-14},
                                      {1e-300, 0, 0},
                                      {1e300, 1e300, 1e300}};
  for (const Vec3d& n : normals) {
    std::ostringstream text;
    text.precision(17);
    text << "shape = \"circular_plate\"\ndiameter = 0.1\nthickness = 0.01\nnormal = [" << n.x
         << ", " << n.y << ", " << n.z << "]\n";
    const Quat q = read_body(text.str()).bodies[0].orientation;
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    const Vec3d unit = (n / largest) / norm(n / largest);
    expect_near(rotate(q, {1, 0, 0}), unit, text.str());
    expect_unit(q);
  }
}

TEST(CaseReaderBodies, CylinderAxisAndRotationCompose) {
  const BodySpec along_z =
      read_body("shape = \"cylinder\"\ndiameter = 0.1\nlength = 0.5\naxis = [0, 0, -3]\n")
          .bodies[0];
  expect_near(rotate(along_z.orientation, {1, 0, 0}), {0, 0, -1}, "cylinder axis");
  // The rotation turns the aligned body about a world axis: the axis [0, 1, 0] turned by 90
  // degrees about x points along z.
  const BodySpec turned = read_body(
                              "shape = \"cylinder\"\ndiameter = 0.1\nlength = 0.5\n"
                              "rotation = { axis = [2, 0, 0], angle = 90 }\n")
                              .bodies[0];
  expect_near(rotate(turned.orientation, {1, 0, 0}), {0, 0, 1}, "rotated cylinder axis");
  // A sphere may be turned too (a floating body's initial attitude).
  const BodySpec sphere =
      read_body(
          "shape = \"sphere\"\ndiameter = 0.1\nrotation = { axis = [0, 0, 1], angle = -90 }\n")
          .bodies[0];
  expect_near(rotate(sphere.orientation, {1, 0, 0}), {0, -1, 0}, "rotated sphere");
}

TEST(CaseReaderBodies, FloatingTakesDensityOrMass) {
  const BodySpec by_density =
      read_body("shape = \"sphere\"\ndiameter = 0.1\nmotion = \"floating\"\ndensity = 800\n")
          .bodies[0];
  EXPECT_DOUBLE_EQ(by_density.density, 800);
  EXPECT_FALSE(by_density.mass.has_value());
  const BodySpec by_mass =
      read_body("shape = \"sphere\"\ndiameter = 0.1\nmotion = \"floating\"\nmass = 0.3\n")
          .bodies[0];
  EXPECT_DOUBLE_EQ(by_mass.density, 0);
  ASSERT_TRUE(by_mass.mass.has_value());
  EXPECT_DOUBLE_EQ(*by_mass.mass, 0.3);
}

TEST(CaseReaderBodies, PrescribedTakesConstantVelocityOrHistory) {
  const std::string head = "shape = \"sphere\"\ndiameter = 0.1\nmotion = \"prescribed\"\n";
  const VelocityHistory constant =
      read_body(head + "velocity = [0.5, 0, -0.1]\n").bodies[0].velocity;
  EXPECT_EQ(constant.times, (std::vector<double>{0}));
  EXPECT_EQ(constant.at(7.0), (Vec3d{0.5, 0, -0.1}));
  const VelocityHistory history =
      read_body(head +
                "motion_history = { times = [0.5, 1.5], velocities = [[0, 0, 0], [1, 0, "
                "0]] }\n")
          .bodies[0]
          .velocity;
  EXPECT_EQ(history.times, (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(history.at(0), (Vec3d{0, 0, 0}));
  EXPECT_NEAR(history.at(1.0).x, 0.5, kEps);
  EXPECT_EQ(history.at(9), (Vec3d{1, 0, 0}));
}

TEST(CaseReaderBodies, ForceWindowMayCoverTheWholeRun) {
  const CaseSpec spec = read_case_string(kMinimal + "[output]\nforce_window = [0, 1]\n", "fw");
  EXPECT_EQ(*spec.output.force_window, (std::array<double, 2>{0, 1}));
}

TEST(CaseReaderBodies, BodyNamesMayRepeatAsGroupsButNotAsNames) {
  const CaseSpec spec = read_case_string(kMinimal + R"(
[[body]]
name = "a"
group = "b"
shape = "sphere"
diameter = 0.1
center = [0.2, 0.5, 0.5]

[[body]]
name = "b"
shape = "sphere"
diameter = 0.1
center = [0.8, 0.5, 0.5]
)",
                                         "groups");
  EXPECT_EQ(spec.bodies[0].group, "b");
  EXPECT_EQ(spec.bodies[1].group, "b");
}

// ---- --set overrides ----------------------------------------------------------------------

CaseSpec read_with(const std::vector<std::string>& overrides) {
  return read_case_file(kCasesDir / "good" / "full3d.toml", overrides);
}

/// The error read_with(overrides) throws; fails the test when there is none.
Error error_with(const std::vector<std::string>& overrides) {
  try {
    read_with(overrides);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "overrides were accepted: " << ::testing::PrintToString(overrides);
  return Error("", "");
}

TEST(CaseOverrides, ReplaceNumberArrayStringAndInlineTable) {
  const CaseSpec spec = read_with({"simulation.dp=0.01", "fluid.gravity=[0,0,-1]",
                                   "simulation.kernel=wendland", "simulation.name = renamed",
                                   "fluid.viscosity={model=\"artificial\", alpha=0.05}"});
  EXPECT_DOUBLE_EQ(spec.simulation.dp, 0.01);
  EXPECT_EQ(spec.fluid.gravity, (Vec3d{0, 0, -1}));
  EXPECT_EQ(spec.simulation.kernel, KernelType::Wendland);  // bare word: taken as a string
  EXPECT_EQ(spec.simulation.name, "renamed");
  EXPECT_EQ(spec.fluid.viscosity, ViscosityModel::Artificial);
  EXPECT_DOUBLE_EQ(spec.fluid.alpha, 0.05);
}

TEST(CaseOverrides, NumericSegmentIndexesArrayOfTablesFromZero) {
  const CaseSpec spec = read_with({"wall.1.layers=7", "fill.0.velocity=[1, 0, 0]"});
  EXPECT_EQ(spec.walls[0].layers, 4);
  EXPECT_EQ(spec.walls[1].layers, 7);
  EXPECT_EQ(spec.fills[0].velocity, (Vec3d{1, 0, 0}));
}

TEST(CaseOverrides, CreateKeysTablesAndEntries) {
  const CaseSpec spec = read_case_file(kCasesDir / "good" / "dambreak2d.toml",
                                       {"output.snapshot_every=0.25", "fluid.sound_speed=30",
                                        "fill.1.min=[1, 0, 0]", "fill.1.max=[1.2, 0, 0.2]"});
  EXPECT_DOUBLE_EQ(spec.output.snapshot_every, 0.25);
  EXPECT_DOUBLE_EQ(spec.fluid.sound_speed, 30);
  ASSERT_EQ(spec.fills.size(), 2u);
  EXPECT_EQ(spec.fills[1].box.max, (Vec3d{1.2, 0, 0.2}));
  EXPECT_EQ(spec.fills[1].where.str(), "--set fill.1.min=[1, 0, 0]");
}

TEST(CaseOverrides, AlternativeKeysReplaceEachOther) {
  // full3d.toml gives sound_speed = 35: overriding the coefficient replaces it, and back.
  const CaseSpec a = read_with({"fluid.sound_speed_coef=15"});
  EXPECT_DOUBLE_EQ(a.fluid.sound_speed, 0);
  EXPECT_DOUBLE_EQ(a.fluid.sound_speed_coef, 15);
  const CaseSpec b = read_with({"fluid.sound_speed_coef=15", "fluid.sound_speed=40"});
  EXPECT_DOUBLE_EQ(b.fluid.sound_speed, 40);
}

TEST(CaseOverrides, BadValueErrorNamesTheOption) {
  const Error e = error_with({"simulation.dp=-1"});
  EXPECT_EQ(e.where(), "--set simulation.dp=-1");
  EXPECT_EQ(e.message(), "simulation.dp = -1: must be > 0 m");

  const Error typo = error_with({"fluid.densty=1000"});
  EXPECT_EQ(typo.where(), "--set fluid.densty=1000");
  EXPECT_NE(typo.message().find("(did you mean 'density'?)"), std::string::npos) << typo.message();

  const Error word = error_with({"simulation.kernel=gauss"});
  EXPECT_EQ(word.where(), "--set simulation.kernel=gauss");
  EXPECT_NE(word.message().find("simulation.kernel = \"gauss\": must be one of"), std::string::npos)
      << word.message();

  const Error broken = error_with({"fluid.gravity=[0, 0"});
  EXPECT_EQ(broken.where(), "--set fluid.gravity=[0, 0");
  EXPECT_NE(broken.message().find("is not valid TOML"), std::string::npos) << broken.message();
}

TEST(CaseOverrides, SetNewBoundaryKeys) {
  const CaseSpec spec = read_with({"domain.periodic=[\"y\"]", "fluid.shifting=fickian",
                                   "wall.0.layers=4", "wall.0.model=mdbc", "wall.0.slip=free_slip",
                                   "outlet.0.face=xmax", "outlet.0.velocity=0.2"});
  EXPECT_EQ(spec.domain.periodic, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(spec.fluid.shifting, ShiftingModel::Fickian);
  EXPECT_EQ(spec.walls[0].model, WallModel::Mdbc);
  EXPECT_EQ(spec.walls[0].slip, WallSlip::FreeSlip);
  ASSERT_EQ(spec.outlets.size(), 1u);
  EXPECT_EQ(spec.outlets[0].where.str(), "--set outlet.0.face=xmax");
  EXPECT_DOUBLE_EQ(*spec.outlets[0].velocity, 0.2);

  const Error e = error_with({"inlet.0.face=xmin"});
  EXPECT_EQ(e.where(), "--set inlet.0.face=xmin");
  EXPECT_NE(e.message().find("inlet[1] needs an inflow velocity"), std::string::npos)
      << e.message();
}

TEST(CaseOverrides, MalformedOptionsPointAtSet) {
  for (const std::string& option :
       {std::string("simulation.dp"), std::string("=0.01"), std::string("simulation..dp=1"),
        std::string("wall.5.layers=2"), std::string("wall.layers=2"),
        std::string("simulation.dp.x=1"), std::string("wall.0=1")}) {
    const Error e = error_with({option});
    EXPECT_EQ(e.where(), "--set") << option << " -> " << e.what();
    EXPECT_NE(e.message().find(option), std::string::npos) << e.message();
  }
  EXPECT_NE(error_with({"wall.5.layers=2"}).message().find("out of range"), std::string::npos);
}

TEST(CaseOverrides, BodyKeys) {
  const CaseSpec spec =
      read_case_file(kCasesDir / "good" / "bodies3d.toml",
                     {"body.0.layers=2", "body.1.rotation={axis=[0,0,1], angle=0}",
                      "body.5.motion_history={times=[0, 1], velocities=[[0,0,0],[1,0,0]]}",
                      "output.force_window=[0.5, 1.5]", "body.7.shape=sphere",
                      "body.7.diameter=0.1", "body.7.center=[0.5, 0.5, 0.5]"});
  EXPECT_EQ(spec.bodies[0].layers, 2);
  expect_near(rotate(spec.bodies[1].orientation, {1, 0, 0}), {0, 0, 1}, "no extra rotation");
  expect_near(rotate(spec.bodies[1].orientation, {0, 0, 1}), {-1, 0, 0}, "no extra rotation");
  // motion_history replaces the constant velocity of body 6.
  EXPECT_EQ(spec.bodies[5].velocity.times, (std::vector<double>{0, 1}));
  EXPECT_EQ(*spec.output.force_window, (std::array<double, 2>{0.5, 1.5}));
  ASSERT_EQ(spec.bodies.size(), 8u);
  EXPECT_EQ(spec.bodies[7].name, "body8");
  EXPECT_EQ(spec.bodies[7].where.str(), "--set body.7.shape=sphere");

  // A constant velocity replaces body 7's motion_history, and leaves its `motion` alone
  // (the wall's velocity/motion pair must not touch a body).
  const CaseSpec v =
      read_case_file(kCasesDir / "good" / "bodies3d.toml", {"body.6.velocity=[0.3, 0, 0]"});
  EXPECT_EQ(v.bodies[6].motion, BodyMotion::Prescribed);
  EXPECT_EQ(v.bodies[6].velocity.velocities, (std::vector<Vec3d>{{0.3, 0, 0}}));

  try {
    read_case_file(kCasesDir / "good" / "bodies3d.toml", {"body.0.shape=box"});
    FAIL() << "a box with a diameter was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.message(),
              "body[1].diameter = 0.05: is not a parameter of shape \"box\" (diameter is a "
              "parameter of \"circular_plate\", \"cylinder\" and \"sphere\"); shape \"box\" "
              "takes size");
  }
}

}  // namespace
}  // namespace netsph
