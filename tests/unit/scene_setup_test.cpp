// The set-up of a case's particles (setup/scene.cpp, setup/scene_bodies.cpp): the fluid
// removed where fills overlap and inside bodies, against brute force, and the spatial bins
// (geometry/box_bins.hpp) that keep the body test from being O(particles x bodies).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "netsph/case/case_reader.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/core/error.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/core/quaternion.hpp"
#include "netsph/geometry/box_bins.hpp"
#include "netsph/geometry/box_lattice.hpp"
#include "netsph/geometry/shapes.hpp"
#include "netsph/setup/mach_check.hpp"
#include "netsph/setup/memory_preflight.hpp"
#include "netsph/setup/scene.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "scene_cases.hpp"

namespace netsph {
namespace {

TEST(BoxBins, CandidatesHoldEveryBoxThatContainsThePoint) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Aabb> boxes;
  for (int k = 0; k < 300; ++k) {
    // Mostly small boxes and a few long bars, as a net's knots and its edge bars.
    const Vec3d c{u(rng), u(rng), 0.2 * u(rng)};
    Vec3d half{0.01 + 0.03 * u(rng), 0.01 + 0.03 * u(rng), 0.005 + 0.01 * u(rng)};
    if (k % 50 == 0) half.x = 0.5;
    boxes.push_back({c - half, c + half});
  }
  const BoxBins bins(boxes);
  std::size_t inside = 0, tested = 0;
  for (int s = 0; s < 200000; ++s) {
    const Vec3d x{1.2 * u(rng) - 0.1, 1.2 * u(rng) - 0.1, 0.3 * u(rng) - 0.05};
    const auto cand = bins.candidates(x);
    ASSERT_TRUE(std::is_sorted(cand.begin(), cand.end()));
    tested += cand.size();
    for (std::uint32_t k = 0; k < boxes.size(); ++k) {
      if (!boxes[k].contains(x)) continue;
      ++inside;
      ASSERT_TRUE(std::binary_search(cand.begin(), cand.end(), k))
          << "box " << k << " contains (" << x.x << ", " << x.y << ", " << x.z
          << ") but is not among the point's candidates";
    }
  }
  std::printf("points in boxes: %zu; candidates tested per point: %.2f of %zu boxes\n", inside,
              static_cast<double>(tested) / 200000, boxes.size());
  EXPECT_GT(inside, 1000u);
  // The point of the bins: a point meets a few boxes, not all of them.
  EXPECT_LT(static_cast<double>(tested) / 200000, 10.0);
  EXPECT_TRUE(bins.candidates({5, 5, 5}).empty());
}

using test::fluid_cube;

TEST(SceneSetup, OverlappingFillsKeepTheFirstAndARemovedParticleRemovesNothing) {
  // test::shifted_fill_copies says which particles stay.
  const double dp = 0.04;
  const CaseSpec spec = test::shifted_fill_copies(dp);
  const Scene scene = build_scene(spec);
  const std::size_t per_fill = 10 * 10 * 10, column = 10 * 10;
  EXPECT_EQ(scene.particles.count(ParticleKind::Fluid), per_fill + column);
  EXPECT_EQ(scene.removed_overlaps, 2 * per_fill - column);
}

TEST(SceneSetup, OverlapsAreRemovedAsByTestingEveryEarlierParticle) {
  // Fills shifted by random fractions of dp on every axis, and by exactly dp/2 and a round-off
  // either side of it (a particle halfway between two cells of the search grid), in 3D and
  // 2D: the particles kept are those a test of every pair, in creation order, keeps.
  const double dp = 0.05;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (const int dims : {3, 2}) {
    CaseSpec spec = fluid_cube(dp);
    spec.simulation.dimensions = dims;
    if (dims == 2) spec.fills[0].box.min.y = spec.fills[0].box.max.y = 0;
    const FillSpec base = spec.fills[0];
    std::vector<Vec3d> shifts = {{0.5 * dp, 0, 0},
                                 {0, 0, 0.5 * dp * (1 + 1e-13)},
                                 {0.5 * dp * (1 - 1e-13), 0.5 * dp, 0.5 * dp}};
    for (int k = 0; k < 6; ++k) shifts.push_back({u(rng) * dp, u(rng) * dp, u(rng) * dp});
    for (Vec3d shift : shifts) {
      if (dims == 2) shift.y = 0;
      FillSpec f = base;
      f.box = {base.box.min + shift, base.box.max + shift};
      spec.fills.push_back(f);
    }
    // Every fill's particles alone, in creation order, then the greedy test of every pair.
    std::vector<Vec3d> kept;
    std::size_t created = 0;
    for (const FillSpec& f : spec.fills) {
      CaseSpec one = spec;
      one.fills = {f};
      for (const Vec3d& x : build_scene(one).particles.pos) {
        ++created;
        const bool overlaps = std::any_of(kept.begin(), kept.end(), [&](const Vec3d& y) {
          return norm2(x - y) < 0.25 * dp * dp;
        });
        if (!overlaps) kept.push_back(x);
      }
    }
    const Scene scene = build_scene(spec);
    const auto& pos = scene.particles.pos;
    ASSERT_EQ(pos.size(), kept.size()) << dims << "D";
    EXPECT_EQ(scene.removed_overlaps, created - kept.size());
    std::vector<Vec3d> built(pos.begin(), pos.end());
    const auto by_xyz = [](const Vec3d& a, const Vec3d& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::sort(built.begin(), built.end(), by_xyz);
    std::sort(kept.begin(), kept.end(), by_xyz);
    EXPECT_TRUE(built == kept) << dims << "D";
    std::printf("%dD: %zu created, %zu kept\n", dims, created, kept.size());
  }
}

TEST(SceneSetup, FluidInsideBodiesIsRemovedAsByTestingEveryBody) {
  // Forty boxes of random sizes and orientations in a fluid cube; the fluid kept must be what a
  // test of every particle against every body keeps (inside, or within dp/2 of the surface).
  const double dp = 0.01;
  CaseSpec spec = fluid_cube(dp);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 40; ++k) {
    BodySpec b;
    b.name = "box" + std::to_string(k);
    b.lengths = {0.02 + 0.06 * u(rng), 0.02 + 0.06 * u(rng), 0.02 + 0.02 * u(rng)};
    if (k % 10 == 0) b.lengths.x = 0.3;  // bars
    b.center = {0.05 + 0.3 * u(rng), 0.05 + 0.3 * u(rng), 0.05 + 0.3 * u(rng)};
    b.orientation = normalized(Quat{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
    b.layers = 2;
    spec.bodies.push_back(b);
  }
  const Scene scene = build_scene(spec);
  ASSERT_EQ(scene.bodies.size(), spec.bodies.size());
  const auto removed_by_some_body = [&](const Vec3d& x) {
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
      const Shape s = Shape::box(spec.bodies[k].lengths);
      const RigidBody& body = scene.bodies[k];
      const Vec3d local = rotate_inverse(body.state.q, x - body.state.com);
      if (s.inside(local) || s.depth(local) < 0.5 * dp * (1 - 1e-6)) return true;
    }
    return false;
  };
  std::size_t expected_removed = 0;
  for (const Vec3d& x : fill_box({spec.fills[0].box.min, spec.fills[0].box.max, 3}, dp))
    expected_removed += removed_by_some_body(x);
  std::printf("fluid removed inside 40 bodies: %zu (brute force %zu)\n", scene.removed_in_bodies,
              expected_removed);
  EXPECT_GT(expected_removed, 1000u);
  EXPECT_EQ(scene.removed_in_bodies, expected_removed);
  const ParticleSet& p = scene.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == ParticleKind::Fluid) {
      ASSERT_FALSE(removed_by_some_body(p.pos[i])) << i;
    }
  }
}

// A floating body's mass and inertia are those of the body as the case gives it: in 2D of its
// section by the plane, a disc for a cylinder across it (was a length x diameter rectangle:
// 100 kg/m for a 15.7 kg/m cylinder, which then sank at half the water's density), and for a
// body thinner than 2 dp not those of the thickened shape its particles resolve (a 4 mm plate
// turned like one ten times heavier).
constexpr const char* kFloatingBodies2D = R"(
[simulation]
dimensions = 2
dp = 0.02
end_time = 1.0
[domain]
min = [0.0, 0.0, 0.0]
max = [2.0, 0.0, 1.0]
[[fill]]
min = [0.0, 0.0, 0.0]
max = [2.0, 0.0, 0.8]
[[body]]
shape = "cylinder"
diameter = 0.2
length = 3.0
center = [0.5, 0.0, 0.4]
motion = "floating"
density = 500.0
[[body]]
shape = "plate"
thickness = 0.004
width = 0.3
height = 0.3
center = [1.2, 0.0, 0.4]
motion = "floating"
mass = 4.0
)";

TEST(SceneSetup, FloatingBodiesTakeTheMassAndInertiaOfTheBodyAsGiven) {
  const Scene scene = build_scene(read_case_string(kFloatingBodies2D, "floating_bodies", {}));
  ASSERT_EQ(scene.bodies.size(), 2u);
  const double pi = 3.14159265358979323846, r = 0.1;
  const RigidInertia& cylinder = scene.bodies[0].inertia;
  EXPECT_NEAR(cylinder.mass, 500 * pi * r * r, 1e-9);  // kg/m, whatever its length
  EXPECT_NEAR(cylinder.principal.y, cylinder.mass * r * r / 2, 1e-12);
  // The 4 mm plate is resolved two particles (0.04 m) thick; its mass is the given 4 kg/m and
  // its moment about y that of a 0.004 x 0.3 m section of that mass.
  const RigidInertia& plate = scene.bodies[1].inertia;
  EXPECT_NEAR(plate.mass, 4.0, 1e-12);
  EXPECT_NEAR(plate.principal.y, 4.0 * (0.004 * 0.004 + 0.3 * 0.3) / 12, 1e-12);
}

TEST(SceneSetup, FluidUnderABodyAcrossPeriodicEndsIsRemovedAtEveryImage) {
  // Periodic in x and z: boxes across one end, across two (a corner, three images) and inside;
  // the fluid kept must be what a test against each body's nearest image keeps, and the bodies'
  // particles are wrapped into the domain, their centres left where the case put them.
  const double dp = 0.01;
  CaseSpec spec = fluid_cube(dp);
  spec.domain = {true, {0, 0, 0}, {0.4, 0.4, 0.4}, {true, false, true}};
  const Vec3d period{0.4, 0, 0.4};
  const Vec3d centres[] = {{0.39, 0.2, 0.2}, {0.01, 0.15, 0.38}, {0.2, 0.2, 0.2}};
  for (int k = 0; k < 3; ++k) {
    BodySpec b;
    b.name = "box" + std::to_string(k);
    b.lengths = {0.08, 0.06, 0.1};
    b.center = centres[k];
    b.orientation = normalized(Quat{1, 0.2 * k, 0.1, -0.3});
    b.layers = 2;
    spec.bodies.push_back(b);
  }
  const Scene scene = build_scene(spec);
  const auto removed_by_some_body = [&](const Vec3d& x) {
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
      const Shape s = Shape::box(spec.bodies[k].lengths);
      const RigidBody& body = scene.bodies[k];
      const Vec3d local =
          rotate_inverse(body.state.q, nearest_image_offset(x - body.state.com, period));
      if (s.inside(local) || s.depth(local) < 0.5 * dp * (1 - 1e-6)) return true;
    }
    return false;
  };
  std::size_t expected_removed = 0;
  for (const Vec3d& x : fill_box({spec.fills[0].box.min, spec.fills[0].box.max, 3}, dp))
    expected_removed += removed_by_some_body(x);
  std::printf("fluid removed inside 3 bodies, two across periodic ends: %zu (brute force %zu)\n",
              scene.removed_in_bodies, expected_removed);
  EXPECT_EQ(scene.removed_in_bodies, expected_removed);
  const ParticleSet& p = scene.particles;
  std::size_t body_particles = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == ParticleKind::Fluid) {
      ASSERT_FALSE(removed_by_some_body(p.pos[i])) << i;
    }
    if (p.kind[i] != ParticleKind::Body) continue;
    ++body_particles;
    for (const int a : {0, 2}) {
      ASSERT_GE(p.pos[i][a], 0.0) << i;
      ASSERT_LT(p.pos[i][a], 0.4) << i;
    }
    // Where the body put it, a whole number of periods away.
    const RigidBody& body = scene.bodies[p.group[i]];
    const Vec3d r = rotate(body.state.q, Vec3d(body.offsets[p.id[i] - body.first_id]));
    ASSERT_LT(norm(rigid_lever_arm(body.state, p.pos[i], period) - r), 1e-7) << i;  // float offsets
  }
  EXPECT_GT(body_particles, 1000u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(scene.bodies[k].state.com, centres[k]);
  // A body as wide as half the period is refused, naming it, the axis and the sizes.
  spec.bodies.resize(1);
  spec.bodies[0].lengths = {0.3, 0.3, 0.1};  // corners 0.22 m from the centre
  try {
    build_scene(spec);
    ADD_FAILURE() << "a body wider than half the period was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("body 'box0' has particles up to"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("half the periodic x axis's period (0.4 m)"),
              std::string::npos)
        << e.what();
  }
}

TEST(SceneSetup, ABuiltCaseHoldsNoSpareCapacity) {
  // Built in batches with doubling (O(n) copies), then trimmed: the run starts exact.
  CaseSpec spec = fluid_cube(0.01);
  WallSpec w;
  w.name = "tank";
  w.box = {{0, 0, 0}, {0.4, 0.4, 0.4}};
  w.faces.fill(true);
  spec.walls.push_back(w);
  const Scene scene = build_scene(spec);
  const ParticleSet& p = scene.particles;
  EXPECT_EQ(p.pos.capacity(), p.size());
  EXPECT_EQ(p.ghost.capacity(), p.size());
  EXPECT_EQ(p.bytes(), p.size() * (sizeof(Vec3d) + 2 * sizeof(Vec3f) + sizeof(Real) +
                                   sizeof(ParticleKind) + 2 * sizeof(std::uint32_t)));
}

TEST(MemoryPreflight, TheEstimateFromTheBoxesIsTheBuiltCountOrALittleLess) {
  // Fills exactly; wall faces without their edges and corners: a few percent low at most, so
  // that a case is refused only when it cannot fit.
  for (const char* name : {"dambreak3d.toml", "net_bi2014.toml", "channel3d.toml",
                           "hydrostatic2d.toml", "paper/element_square_plate_reduced.toml"}) {
    const CaseSpec spec = read_case_file(std::string(NETSPH_CASES_DIR) + "/" + name, {});
    const Scene scene = build_scene(spec);
    const ParticleSet& p = scene.particles;
    const double built = static_cast<double>(p.size() - p.count(ParticleKind::Body) +
                                             scene.removed_in_bodies + scene.removed_overlaps);
    const MemoryEstimate e = estimate_case_memory(spec, 200);
    std::printf("%-40s built %.0f, estimated %.0f (%.3f)\n", name, built, e.particles,
                e.particles / built);
    EXPECT_LE(e.particles, built) << name;
    EXPECT_GE(e.particles, 0.9 * built) << name;
    EXPECT_DOUBLE_EQ(e.bytes, 200 * e.particles);
  }
  EXPECT_GT(available_memory().value_or(1), 0);
}

bool warns_about_c0(const Scene& scene) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(), [](const std::string& w) {
    return w.find("times the fastest flow the case sets up") != std::string::npos;
  });
}

TEST(SceneWarnings, ASoundSpeedNearTheFlowSpeedIsNamedWithWhatSetsTheFlow) {
  // The dam break: 2 m of water, free fall sqrt(2 g H) = 6.26 m/s; its c0 (coef 10: 44 m/s) is
  // 7 times that, and 10 m/s is 1.6 times.
  const std::string dam = std::string(NETSPH_CASES_DIR) + "/dambreak2d.toml";
  EXPECT_FALSE(warns_about_c0(build_scene(read_case_file(dam, {}))));
  const Scene slow = build_scene(read_case_file(dam, {"fluid.sound_speed=10.0"}));
  ASSERT_TRUE(warns_about_c0(slow));
  const ExpectedFlow fall = expected_flow_speed(read_case_file(dam, {}), 2.0);
  EXPECT_NEAR(fall.speed, std::sqrt(2 * 9.81 * 2.0), 1e-9);
  // A closed duct without gravity: the inlet sets the flow (0.226 m/s; c0 = 3 m/s is 13 times).
  const std::string net = std::string(NETSPH_CASES_DIR) + "/net_bi2014.toml";
  EXPECT_FALSE(warns_about_c0(build_scene(read_case_file(net, {}))));
  const CaseSpec fast = read_case_file(net, {"inlet.0.velocity=1.0"});
  const ExpectedFlow inflow = expected_flow_speed(fast, 0.0);
  EXPECT_DOUBLE_EQ(inflow.speed, 1.0);
  EXPECT_NE(inflow.source.find("inlet"), std::string::npos) << inflow.source;
  const auto w = sound_speed_warning(fast, 0.0, 3.0);
  ASSERT_TRUE(w.has_value());
  EXPECT_NE(w->find("c0 = 3 m/s is only 3.0 times"), std::string::npos) << *w;
  EXPECT_NE(w->find("(the velocity of inlet 'inlet1')"), std::string::npos) << *w;
  EXPECT_NE(w->find("c0 >= 10 U (10 m/s here)"), std::string::npos) << *w;
}

bool warns(const Scene& scene, const std::string& part) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

TEST(SceneWarnings, SurfaceHeightsAndProfilesFarFromTheWaterAreNamed) {
  // The open channel: water from z = 0 to 0.2 m, an inlet on xmin.
  const std::string channel = std::string(NETSPH_CASES_DIR) + "/channel2d.toml";
  const auto scene_with = [&](const std::vector<std::string>& set) {
    return build_scene(read_case_file(channel, set));
  };
  const Scene plain = scene_with({});
  EXPECT_FALSE(warns(plain, "surface_z"));
  EXPECT_FALSE(warns(plain, "profile covers"));
  EXPECT_TRUE(warns(scene_with({"inlet.0.surface_z=5.0"}),
                    "inlet 'inlet1': surface_z = 5 m lies 4.8 m above the highest water (0.2 m)"));
  EXPECT_FALSE(warns(scene_with({"inlet.0.surface_z=0.21"}), "surface_z"));  // within 2h
  EXPECT_TRUE(warns(scene_with({"inlet.0.surface_z=-0.5"}), "lies below the water's bottom"));
  // Without hydrostatic density a buffer's surface sets no head; an outlet creates nothing.
  EXPECT_FALSE(warns(scene_with({"inlet.0.density=\"extrapolated\"", "inlet.0.surface_z=0.35"}),
                     "surface_z"));
  EXPECT_FALSE(warns(scene_with({"outlet.0.density=\"extrapolated\"", "outlet.0.surface_z=1.0"}),
                     "surface_z"));
  EXPECT_FALSE(warns(scene_with({"outlet.0.density=\"reference\"", "outlet.0.surface_z=-0.5"}),
                     "surface_z"));
  EXPECT_TRUE(warns(scene_with({"inlet.0.profile={z=[10.0, 11.0], u=[0.0, 0.5]}"}),
                    "its profile covers z = 10 to 11 m, wholly outside the water (0 to 0.2 m): "
                    "the whole inflow takes its end value, 0 m/s"));
  // A fill's head: the dam break's 2 m column under a 100 m surface.
  const std::string dam = std::string(NETSPH_CASES_DIR) + "/dambreak2d.toml";
  EXPECT_TRUE(warns(build_scene(read_case_file(dam, {"fill.0.surface_z=100.0"})),
                    "fill[1].surface_z = 100 m lies 98 m above the highest water (2 m)"));
}

TEST(SceneWarnings, AMovingBodyStartingInsideAWallOrABodyIsNamed) {
  // The sinking box (0.2 x 0.1 m, floating) over the tank floor at z = 0, dp = 0.02 m.
  const std::string box = std::string(NETSPH_CASES_DIR) + "/sinking_box2d.toml";
  const auto scene_at = [&](const char* center) {
    return build_scene(read_case_file(box, {"simulation.dp=0.02", center}));
  };
  EXPECT_FALSE(warns(scene_at("body.0.center=[0.5, 0.0, 0.4]"), "starts inside"));
  // Resting on the floor (1 mm into it): the layers stay a dp apart.
  EXPECT_FALSE(warns(scene_at("body.0.center=[0.5, 0.0, 0.049]"), "starts inside"));
  // Half its height into the floor: its lowest layer sits on the wall's first.
  EXPECT_TRUE(
      warns(scene_at("body.0.center=[0.5, 0.0, 0.0]"), "body 'box' starts inside wall 'tank'"));
  // Two nets on each other (3D): each floating knot of one sits in the other's.
  const std::string knot = std::string(NETSPH_CASES_DIR) + "/net_tethered_knot.toml";
  const std::vector<std::string> twin = {"net.1.name=\"twin\"",
                                         "net.1.center=[0.0, 0.0, 0.0]",
                                         "net.1.normal=[0.9239, 0.0, -0.3827]",
                                         "net.1.up=[0.3827, 0.0, 0.9239]",
                                         "net.1.width=0.1",
                                         "net.1.height=0.2",
                                         "net.1.twine_length=0.1",
                                         "net.1.twine_diameter=0.02",
                                         "net.1.knot_layout=\"inset\"",
                                         "net.1.equivalent_knot=\"full\"",
                                         "net.1.material=\"nylon\"",
                                         "net.1.fixed_edges=[\"top\"]"};
  EXPECT_FALSE(warns(build_scene(spec_with_net_knots(read_case_file(knot, {}))), "starts inside"));
  EXPECT_TRUE(warns(build_scene(spec_with_net_knots(read_case_file(knot, twin))),
                    "body 'tether.knot0_0' starts inside body 'twin.knot0_0'"));
  // Fixed bodies may cross each other (the panel's twines) and touch walls.
  const std::string panel = std::string(NETSPH_CASES_DIR) + "/paper/panel5_twines_reduced.toml";
  EXPECT_FALSE(warns(build_scene(read_case_file(panel, {})), "starts inside"));
}

TEST(SceneWarnings, AWallClosingAPeriodicAxisAcrossTheWaterIsNamed) {
  // The dam break's tank made periodic along x: its end walls stop every crossing.
  const std::string dam = std::string(NETSPH_CASES_DIR) + "/dambreak2d.toml";
  const std::string periodic_x =
      "domain={min=[-0.2, 0, -0.2], max=[4.2, 0, 3.2], periodic=[\"x\"]}";
  EXPECT_TRUE(warns(build_scene(read_case_file(dam, {"simulation.dp=0.04", periodic_x})),
                    "wall 'tank' closes the periodic axis x with its faces xmin and xmax"));
  // Without the end faces the tank is a periodic channel.
  EXPECT_FALSE(warns(build_scene(read_case_file(
                         dam, {"simulation.dp=0.04", periodic_x, "wall.0.faces=[\"zmin\"]"})),
                     "closes the periodic axis"));
  // A block on the bed across part of the water is an obstacle (periodic Poiseuille has
  // walls along the axis only; the shipped channels none across it).
  EXPECT_FALSE(warns(build_scene(read_case_file(
                         dam, {"simulation.dp=0.04", periodic_x, "wall.0.max=[4.0, 0.0, 1.0]"})),
                     "closes the periodic axis"));
}

}  // namespace
}  // namespace netsph
