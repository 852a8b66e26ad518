// The parts of a scene that the processes of a distributed run build (build_scene_part,
// fill_box_part): together they must be the whole scene's particles, bit for bit and with the
// same ids, whatever the cuts: across overlapping fills whose removal chains cross a cut,
// bodies, walls with mDBC ghosts, open-boundary buffers and a net's knots.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "netsph/case/case_reader.hpp"
#include "netsph/geometry/box_lattice.hpp"
#include "netsph/setup/scene.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "scene_cases.hpp"

namespace netsph {
namespace {

/// `part` holds exactly the points of `whole` in `range`, each with its index there.
void expect_part_of(const LatticePart& part, const std::vector<Vec3d>& whole,
                    const AxisRange& range) {
  EXPECT_EQ(part.total, whole.size());
  std::vector<std::uint64_t> expected;
  for (std::uint64_t i = 0; i < whole.size(); ++i)
    if (range.contains(whole[i])) expected.push_back(i);
  ASSERT_EQ(part.index, expected);
  for (std::size_t k = 0; k < part.points.size(); ++k)
    EXPECT_EQ(part.points[k], whole[part.index[k]]);
}

TEST(SceneParts, APartOfAFillIsTheWholeFillsPointsInTheRangeWithTheirIndexes) {
  const double dp = 0.1;
  for (const int dims : {2, 3}) {
    const LatticeBox box{{0, 0, 0}, {1.0, 0.5, 0.7}, dims};
    const std::vector<Vec3d> whole = fill_box(box, dp);
    // A cut on a lattice coordinate (0.35 on x: the point belongs to the range above it),
    // between two, outside the box, and an empty range.
    for (const AxisRange range : {AxisRange{0, 0.35, 0.62}, AxisRange{2, -1.0, 0.3},
                                  AxisRange{0, 0.9, 5.0}, AxisRange{2, 0.31, 0.32}}) {
      SCOPED_TRACE(std::to_string(dims) + "D, axis " + std::to_string(range.axis));
      expect_part_of(fill_box_part(box, dp, range), whole, range);
    }
  }
}

TEST(SceneParts, APartOfAWallIsTheWholeWallsPointsInTheRangeWithTheirIndexes) {
  const double dp = 0.1;
  for (const int dims : {2, 3}) {
    const LatticeBox box{{0, 0, 0}, {1.0, 0.5, 0.7}, dims};
    // A tank open at the top, and walls on every face.
    for (const std::array<bool, 6> faces :
         {std::array<bool, 6>{true, true, true, true, true, false},
          std::array<bool, 6>{true, true, true, true, true, true}}) {
      const std::vector<Vec3d> whole = wall_box_layers(box, dp, faces, 3);
      for (const AxisRange range : {AxisRange{0, 0.35, 0.62}, AxisRange{2, -1.0, 0.3},
                                    AxisRange{0, -0.15, -0.05}, AxisRange{2, 0.31, 0.32}}) {
        SCOPED_TRACE(std::to_string(dims) + "D, axis " + std::to_string(range.axis));
        expect_part_of(wall_box_layers_part(box, dp, faces, 3, range), whole, range);
      }
    }
  }
  // The layers themselves, counted: a 10 x 7 box in 2D with three layers on all four sides.
  const LatticeBox flat{{0, 0, 0}, {1.0, 0.0, 0.7}, 2};
  EXPECT_EQ(wall_box_layers(flat, dp, {true, true, false, false, true, true}, 3).size(),
            16u * 13u - 10u * 7u);
}

/// Builds the parts of `spec` between `cuts` along `axis` as the processes would (each sees the
/// others' bounding boxes through the bounds callback) and checks they make up the whole.
void expect_parts_make_up_the_whole(const CaseSpec& spec, int axis, std::vector<double> cuts) {
  const double inf = std::numeric_limits<double>::infinity();
  cuts.insert(cuts.begin(), -inf);
  cuts.push_back(inf);
  const std::size_t parts = cuts.size() - 1;
  // First pass: each part's own bounding box (the default domain is all it feeds).
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (std::size_t r = 0; r < parts; ++r) {
    build_scene_part(spec, {axis, cuts[r], cuts[r + 1]}, [&](Vec3d& l, Vec3d& h) {
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], l[a]), hi[a] = std::max(hi[a], h[a]);
    });
  }
  const Scene whole = build_scene(spec);
  std::map<std::uint32_t, std::size_t> slot;
  for (std::size_t i = 0; i < whole.particles.size(); ++i) slot[whole.particles.id[i]] = i;
  std::vector<int> seen(whole.particles.size(), 0);
  std::size_t largest = 0;
  for (std::size_t r = 0; r < parts; ++r) {
    const Scene part =
        build_scene_part(spec, {axis, cuts[r], cuts[r + 1]}, [&](Vec3d& l, Vec3d& h) {
          l = lo;
          h = hi;
        });
    EXPECT_EQ(part.domain_min, whole.domain_min);
    EXPECT_EQ(part.domain_max, whole.domain_max);
    EXPECT_EQ(part.particles.next_id, whole.particles.next_id);
    EXPECT_EQ(part.bodies.size(), whole.bodies.size());
    EXPECT_EQ(part.sound_speed, whole.sound_speed);
    const ParticleSet& p = part.particles;
    const ParticleSet& w = whole.particles;
    largest = std::max(largest, p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto it = slot.find(p.id[i]);
      ASSERT_NE(it, slot.end()) << "part " << r << " holds particle " << p.id[i]
                                << ", which the whole scene removed";
      const std::size_t j = it->second;
      ++seen[j];
      EXPECT_TRUE(p.pos[i] == w.pos[j] && p.vel[i] == w.vel[j] && p.rho[i] == w.rho[j] &&
                  p.kind[i] == w.kind[j] && p.group[i] == w.group[j] && p.ghost[i] == w.ghost[j])
          << "particle " << p.id[i] << " differs in part " << r;
    }
  }
  for (std::size_t j = 0; j < seen.size(); ++j) {
    ASSERT_EQ(seen[j], 1) << "particle " << whole.particles.id[j]
                          << " at x = " << whole.particles.pos[j].x << " is in " << seen[j]
                          << " parts";
  }
  // The parts split the case: none holds it all.
  EXPECT_LT(largest, whole.particles.size());
}

TEST(SceneParts, OverlappingFillsAreRemovedAcrossTheCutsAsInTheWholeScene) {
  // The second copy goes because of the first, the third stays only where the second
  // (removed) was its only neighbour, so the fate of a particle near a cut depends on a chain
  // of two others across it.
  const double dp = 0.04;
  const CaseSpec spec = test::shifted_fill_copies(dp);
  // Cuts on the first fill's lattice (x = 0.5 dp + k dp), on the others', and between.
  expect_parts_make_up_the_whole(spec, 0, {2.5 * dp, 4.8 * dp, 6.1 * dp, 9.5 * dp});
  expect_parts_make_up_the_whole(spec, 2, {0.13, 0.3});
}

TEST(SceneParts, CaseFilesWithWallsBodiesBuffersAndNetsSplitIntoTheirParts) {
  const std::string dir = NETSPH_CASES_DIR;
  struct Split {
    std::string file;
    std::vector<std::string> overrides;
    int axis;
    std::vector<double> cuts;
  };
  const std::vector<Split> splits = {
      // mDBC walls and a floating body straddling a cut.
      {"floating_box2d.toml", {"simulation.dp=0.02"}, 0, {0.2, 0.5, 0.51}},
      // Inlet and outlet buffers (fills starting inside them).
      {"channel2d.toml", {}, 0, {0.01, 0.5, 0.97}},
      // A floating box across a periodic end: its particles past it are wrapped to the
      // other end, into the first part.
      {"poiseuille2d.toml",
       {"domain.max=[0.3, 0.0, 0.13]", "fill=[{min=[0.0, 0.0, 0.0], max=[0.3, 0.0, 0.1]}]",
        "wall=[{name=\"plates\", min=[0.0, 0.0, 0.0], max=[0.3, 0.0, 0.1], faces=[\"zmin\", "
        "\"zmax\"], layers=3, model=\"mdbc\", slip=\"no_slip\"}]",
        "body=[{name=\"box\", shape=\"box\", size=[0.02, 0.02, 0.02], center=[0.2965, 0, "
        "0.035], motion=\"floating\", density=1000}]"},
       0,
       {0.005, 0.15, 0.29}},
      // The dam break's walls and fill, cut along z too.
      {"dambreak2d.toml", {"simulation.dp=0.04"}, 2, {0.3, 0.61}},
      // A coupled net: its knots are bodies.
      {"net_tethered_knot.toml", {}, 0, {-0.05, 0.0, 0.1}},
  };
  for (const Split& s : splits) {
    SCOPED_TRACE(s.file);
    const CaseSpec spec = spec_with_net_knots(read_case_file(dir + "/" + s.file, s.overrides));
    expect_parts_make_up_the_whole(spec, s.axis, s.cuts);
  }
}

}  // namespace
}  // namespace netsph
