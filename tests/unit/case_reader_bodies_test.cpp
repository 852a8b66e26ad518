// Case reader, [[body]] tables: every key of a full file, defaults, orientation (normal,
// axis, rotation), the motion kinds' keys, and names and groups.
#include "netsph/case/case_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
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
using case_test::expect_near;
using case_test::kCasesDir;
using case_test::kMinimal;

constexpr double kTol = 1e-12;

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
  EXPECT_NEAR(cross.velocity.at(0.5).z, 0.05, kTol);
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
  EXPECT_NEAR(history.at(1.0).x, 0.5, kTol);
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

}  // namespace
}  // namespace netsph
