// The cell-grid search must find exactly the pairs a brute-force search finds, for random and
// lattice particles, in 2D and 3D, and drop particles outside the domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

#include "netsph/neighbours/cell_grid.hpp"

namespace netsph {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

/// Pairs (by original index) within `radius`, found through the grid's ranges.
PairSet grid_pairs(CellGrid& grid, const std::vector<Vec3d>& pos, double radius) {
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  PairSet pairs;
  NeighbourRanges ranges;
  for (std::int64_t c = 0; c < grid.cell_count(); ++c) {
    const IndexRange own = grid.cell_range(c);
    const int nr = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t s = own.begin; s < own.end; ++s)
      for (int k = 0; k < nr; ++k)
        for (std::uint32_t t = ranges[k].begin; t < ranges[k].end; ++t) {
          const auto a = order[s], b = order[t];
          if (a != b && norm2(pos[a] - pos[b]) < radius * radius) pairs.insert({a, b});
        }
  }
  return pairs;
}

PairSet brute_pairs(const std::vector<Vec3d>& pos, double radius) {
  PairSet pairs;
  for (std::uint32_t a = 0; a < pos.size(); ++a)
    for (std::uint32_t b = 0; b < pos.size(); ++b)
      if (a != b && norm2(pos[a] - pos[b]) < radius * radius) pairs.insert({a, b});
  return pairs;
}

TEST(NeighbourSearch, RandomParticles3D) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3d> pos(3000);
  for (auto& p : pos) p = {u(rng) * 0.5, u(rng) * 0.3, u(rng) * 0.2};
  const double support = 0.045;
  CellGrid grid;
  grid.configure({0, 0, 0}, {0.5, 0.3, 0.2}, support, 0.05, 3);
  const PairSet expect = brute_pairs(pos, support);
  EXPECT_GT(expect.size(), 10000u);
  EXPECT_EQ(grid_pairs(grid, pos, support), expect);
}

TEST(NeighbourSearch, RandomParticles2D) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3d> pos(2000);
  for (auto& p : pos) p = {u(rng) * 1.0, 0.0, u(rng) * 0.4};
  const double support = 0.03;
  CellGrid grid;
  grid.configure({0, 0, 0}, {1.0, 0, 0.4}, support, 0.0, 2);
  EXPECT_EQ(grid_pairs(grid, pos, support), brute_pairs(pos, support));
}

TEST(NeighbourSearch, LatticeParticlesAtCellBoundaries) {
  // Spacing commensurate with the cells: many particles sit exactly on cell faces, and pairs
  // at exactly the support radius must be excluded consistently (strict <).
  const double dp = 0.01, support = 0.03;
  std::vector<Vec3d> pos;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 12; ++i) pos.push_back({i * dp, j * dp, k * dp});
  CellGrid grid;
  grid.configure({0, 0, 0}, {0.12, 0.08, 0.1}, support, 0.0, 3);
  EXPECT_EQ(grid_pairs(grid, pos, support), brute_pairs(pos, support));
}

TEST(NeighbourSearch, SkinCoversDisplacedParticles) {
  // Sort, then move every particle by up to max_displacement(): all pairs within the support
  // after the move must still be found through the ranges of the old sort.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0), m(-1.0, 1.0);
  std::vector<Vec3d> pos(2500);
  for (auto& p : pos) p = {0.05 + u(rng) * 0.4, 0.05 + u(rng) * 0.2, 0.05 + u(rng) * 0.1};
  const double support = 0.04;
  CellGrid grid;
  grid.configure({0, 0, 0}, {0.5, 0.3, 0.2}, support, 0.1, 3);
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  std::vector<Vec3d> moved(pos.size());
  for (std::size_t s = 0; s < order.size(); ++s) {
    Vec3d d{m(rng), m(rng), m(rng)};
    d = d * (grid.max_displacement() * 0.999 / std::max(norm(d), 1e-12));
    moved[s] = pos[order[s]] + d;
  }
  PairSet found;
  NeighbourRanges ranges;
  for (std::int64_t c = 0; c < grid.cell_count(); ++c) {
    const IndexRange own = grid.cell_range(c);
    const int nr = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t s = own.begin; s < own.end; ++s)
      for (int k = 0; k < nr; ++k)
        for (std::uint32_t t = ranges[k].begin; t < ranges[k].end; ++t)
          if (s != t && norm2(moved[s] - moved[t]) < support * support) found.insert({s, t});
  }
  EXPECT_EQ(found, brute_pairs(moved, support));
}

TEST(NeighbourSearch, ParticlesOutsideTheGridAreDropped) {
  std::vector<Vec3d> pos = {{0.05, 0.05, 0.05},
                            {-0.01, 0.05, 0.05},
                            {0.05, 0.05, 0.2},
                            {0.09, 0.01, 0.01},
                            {0.05, 0.05, std::nan("")}};
  CellGrid grid;
  grid.configure({0, 0, 0}, {0.1, 0.1, 0.1}, 0.02, 0.0, 3);
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  std::vector<std::uint32_t> kept(order.begin(), order.end());
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(kept, (std::vector<std::uint32_t>{0, 3}));
}

// By cell, and within a cell by position, whatever order the particles came in: a run split
// over processes (or restarted) then sums each particle's pairs in the same order as the run
// on one process (cell_grid.cpp).
TEST(NeighbourSearch, SortIsByCellThenByPositionWhateverTheEarlierOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3d> pos(500);
  for (auto& p : pos) p = {u(rng), u(rng), u(rng)};
  // In particle 3's cell: one at its z (ordered by y), one at its z and y (ordered by x).
  pos[7] = {pos[3].x, pos[3].y - 0.01, pos[3].z};
  pos[8] = {pos[3].x - 0.01, pos[3].y, pos[3].z};
  CellGrid grid;
  grid.configure({0, 0, 0}, {1, 1, 1}, 0.6, 0.0, 3);  // 4 x 4 x 4 cells, about 8 particles each
  ASSERT_EQ(grid.cell_of(pos[7]), grid.cell_of(pos[3]));
  ASSERT_EQ(grid.cell_of(pos[8]), grid.cell_of(pos[3]));
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  ASSERT_EQ(order.size(), pos.size());
  const auto before = [](const Vec3d& a, const Vec3d& b) {
    return a.z != b.z ? a.z < b.z : a.y != b.y ? a.y < b.y : a.x < b.x;
  };
  for (std::size_t s = 1; s < order.size(); ++s) {
    const Vec3d &a = pos[order[s - 1]], &b = pos[order[s]];
    const auto c0 = grid.cell_of(a), c1 = grid.cell_of(b);
    EXPECT_TRUE(c0 < c1 || (c0 == c1 && before(a, b))) << s;
  }
  // The same particles in another order: the same sorted sequence.
  std::vector<Vec3d> shuffled = pos;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  std::vector<std::uint32_t> again;
  grid.sort(shuffled, again);
  ASSERT_EQ(again.size(), order.size());
  for (std::size_t s = 0; s < order.size(); ++s) EXPECT_EQ(shuffled[again[s]], pos[order[s]]) << s;
}

}  // namespace
}  // namespace netsph
