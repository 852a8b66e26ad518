// Case reader, --set overrides: replacing, creating and indexing keys, and the errors of bad
// values and malformed options.
#include "netsph/case/case_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/core/quaternion.hpp"

#include "case_test_files.hpp"

namespace netsph {
namespace {

using case_test::expect_near;
using case_test::kCasesDir;

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
  EXPECT_EQ(e.message(), "simulation.dp = -1: must be in [1e-06, 1000] m");

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
  // A negative or oversized index is named as not an index (it suggested "wall.0.-1").
  for (const std::string option : {"wall.-1.layers=2", "wall.99999999999999999999.layers=2"}) {
    const std::string m = error_with({option}).message();
    EXPECT_NE(m.find("is not an index; the entries of wall are numbered from 0"), std::string::npos)
        << m;
    EXPECT_EQ(m.find("e.g. wall.0."), std::string::npos) << m;
  }
  // An indexed value of a key the case does not have: full3d.toml has no structure_gravity. The
  // message must not send the user to set keys of an entry (which then fails as out of range).
  const Error absent = error_with({"fluid.structure_gravity.2=-1"});
  EXPECT_NE(absent.message().find("the case has no fluid.structure_gravity"), std::string::npos)
      << absent.message();
  EXPECT_NE(absent.message().find("fluid.structure_gravity=[...]"), std::string::npos);
  // Present as an array of values: set it whole.
  EXPECT_NE(error_with({"fluid.gravity.2=-1"}).message().find("set it as a whole"),
            std::string::npos);
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
