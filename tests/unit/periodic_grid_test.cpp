// Periodic axes of the cell grid: the ranges (with their shifts) must find exactly the pairs a
// brute-force minimum-image search finds, each once; wrap() must move positions by whole
// periods into [lo, hi); too short periodic extents are refused; the period holds a whole
// number of cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/neighbours/cell_grid.hpp"

namespace netsph {
namespace {

/// A pair a-b (by original index) and its separation pos_a - (pos_b + shift).
struct Entry {
  std::uint32_t a, b;
  double dx, dy, dz;
  bool operator<(const Entry& o) const { return a != o.a ? a < o.a : b < o.b; }
  bool same_pair(const Entry& o) const { return a == o.a && b == o.b; }
};

struct GridPairs {
  std::vector<Entry> pairs;  ///< sorted, duplicates removed
  std::size_t duplicates = 0;
  std::size_t shifted = 0;  ///< pairs found through a range with a non-zero shift
};

/// Pairs within `radius` found through the grid's ranges, with the separation the shift gives.
GridPairs grid_pairs(CellGrid& grid, const std::vector<Vec3d>& pos, double radius) {
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  EXPECT_EQ(order.size(), pos.size()) << "every particle lies inside the grid";
  GridPairs out;
  NeighbourRanges ranges;
  const double r2 = radius * radius;
  for (std::int64_t c = 0; c < grid.cell_count(); ++c) {
    const IndexRange own = grid.cell_range(c);
    if (own.begin == own.end) continue;
    const int nr = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t s = own.begin; s < own.end; ++s)
      for (int k = 0; k < nr; ++k) {
        const double sx = ranges[k].shift.x, sy = ranges[k].shift.y, sz = ranges[k].shift.z;
        for (std::uint32_t t = ranges[k].begin; t < ranges[k].end; ++t) {
          const auto a = order[s], b = order[t];
          const double dx = pos[a].x - (pos[b].x + sx), dy = pos[a].y - (pos[b].y + sy),
                       dz = pos[a].z - (pos[b].z + sz);
          if (a == b || dx * dx + dy * dy + dz * dz >= r2) continue;
          out.pairs.push_back({a, b, dx, dy, dz});
          if (sx != 0 || sy != 0 || sz != 0) ++out.shifted;
        }
      }
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  const auto last = std::unique(out.pairs.begin(), out.pairs.end(),
                                [](const Entry& x, const Entry& y) { return x.same_pair(y); });
  out.duplicates = static_cast<std::size_t>(out.pairs.end() - last);
  out.pairs.erase(last, out.pairs.end());
  return out;
}

/// Brute force with the minimum image on the periodic axes (period > 2 radius: one image at
/// most); sorted by (a, b).
std::vector<Entry> brute_pairs(const std::vector<Vec3d>& pos, double radius, const Vec3d& period,
                               std::array<bool, 3> periodic) {
  std::vector<Entry> pairs;
  const double r2 = radius * radius;
  auto image = [&](double d, int axis) {
    return periodic[axis] ? d - period[axis] * std::round(d / period[axis]) : d;
  };
  const auto n = static_cast<std::uint32_t>(pos.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const double dx = image(pos[a].x - pos[b].x, 0), dy = image(pos[a].y - pos[b].y, 1),
                   dz = image(pos[a].z - pos[b].z, 2);
      if (dx * dx + dy * dy + dz * dz < r2) pairs.push_back({a, b, dx, dy, dz});
    }
  return pairs;
}

/// Checks the grid against brute force for random particles in [lo, hi).
void check_random(int dims, const Vec3d& lo, const Vec3d& hi, std::array<bool, 3> periodic,
                  double support, double skin, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3d> pos(n);
  for (auto& p : pos) {
    for (int a = 0; a < 3; ++a) p[a] = lo[a] + u(rng) * (hi[a] - lo[a]);
    if (dims == 2) p.y = 0;
  }
  CellGrid grid;
  grid.configure(lo, hi, support, skin, dims, periodic);
  Vec3d period{};
  std::array<bool, 3> effective{};
  for (int a = 0; a < 3; ++a) {
    const bool on = periodic[a] && !(dims == 2 && a == 1);
    effective[a] = on;
    EXPECT_EQ(grid.periodic(a), on) << "axis " << a;
    if (on) period[a] = hi[a] - lo[a];
    EXPECT_DOUBLE_EQ(grid.period()[a], period[a]) << "axis " << a;
  }
  const GridPairs found = grid_pairs(grid, pos, support);
  const std::vector<Entry> expect = brute_pairs(pos, support, period, effective);
  ASSERT_GT(expect.size(), 1000u);
  EXPECT_EQ(found.duplicates, 0u) << "pairs seen more than once";
  EXPECT_EQ(found.pairs.size(), expect.size());
  // Merge the two sorted lists.
  std::size_t missing = 0, extra = 0, wrong_image = 0, i = 0, j = 0;
  while (i < expect.size() || j < found.pairs.size()) {
    if (j == found.pairs.size() || (i < expect.size() && expect[i] < found.pairs[j])) {
      ++missing, ++i;
    } else if (i == expect.size() || found.pairs[j] < expect[i]) {
      ++extra, ++j;
    } else {
      // The shift must give the minimum image (float shifts: 1e-7 of the period).
      const Entry &e = expect[i], &f = found.pairs[j];
      if (std::fabs(e.dx - f.dx) + std::fabs(e.dy - f.dy) + std::fabs(e.dz - f.dz) > 1e-6)
        ++wrong_image;
      ++i, ++j;
    }
  }
  EXPECT_EQ(missing, 0u);
  EXPECT_EQ(extra, 0u);
  EXPECT_EQ(wrong_image, 0u);
  EXPECT_GT(found.shifted, 100u) << "too few pairs across the periodic boundary";
}

TEST(PeriodicGrid, RandomParticlesPeriodicInX3D) {
  // Offset origin; the x period (0.5) and z (0.25) are exact in float.
  check_random(3, {-0.25, 0.1, -0.05}, {0.25, 0.3, 0.2}, {true, false, false}, 0.045, 0.05, 2000,
               11);
}

TEST(PeriodicGrid, RandomParticlesPeriodicInXAndZ3D) {
  check_random(3, {0.0, 0.0, -0.125}, {0.5, 0.2, 0.125}, {true, false, true}, 0.045, 0.05, 2000,
               12);
}

TEST(PeriodicGrid, RandomParticlesFullyPeriodic3D) {
  check_random(3, {0.0, 0.0, 0.0}, {0.25, 0.25, 0.25}, {true, true, true}, 0.045, 0.0, 2000, 13);
}

TEST(PeriodicGrid, RandomParticlesPeriodicInX2D) {
  // The y flag is ignored in 2D (one y cell).
  check_random(2, {-0.5, 0, 0.0}, {0.5, 0, 0.25}, {true, true, false}, 0.03, 0.05, 2000, 14);
}

TEST(PeriodicGrid, ShortestAllowedPeriodFiveCells) {
  // Exactly 2R + 1 = 5 cells along x: every cell sees the whole period, each cell once.
  const double support = 0.03, skin = 0.05;
  const double min_cell = support * (1 + skin) / CellGrid::kSearchCells;
  const double len = 5.2 * min_cell;
  CellGrid probe;
  probe.configure({0, 0, 0}, {len, 0, 0.2}, support, skin, 2, {true, false, false});
  EXPECT_EQ(probe.dims()[0], 5);
  check_random(2, {0, 0, 0}, {len, 0, 0.2}, {true, false, false}, support, skin, 600, 15);
  check_random(3, {0, 0, 0}, {len, 0.1, len}, {true, false, true}, support, skin, 800, 16);
}

TEST(PeriodicGrid, LatticeAcrossThePeriodSeesFullNeighbourhood) {
  // A periodic lattice: every particle has the same number of neighbours within the support.
  const double dp = 0.01, support = 0.03;
  const int n = 9;
  std::vector<Vec3d> pos;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) pos.push_back({(i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp});
  CellGrid grid;
  const double L = n * dp;
  grid.configure({0, 0, 0}, {L, L, L}, support, 0.05, 3, {true, true, true});
  const GridPairs found = grid_pairs(grid, pos, support * (1 - 1e-9));
  EXPECT_EQ(found.duplicates, 0u);
  std::vector<int> count(pos.size(), 0);
  for (const Entry& e : found.pairs) ++count[e.a];
  // Lattice points strictly inside a sphere of radius 3 (in units of dp): 122 without the origin.
  int inside = 0;
  for (int k = -3; k <= 3; ++k)
    for (int j = -3; j <= 3; ++j)
      for (int i = -3; i <= 3; ++i) inside += (i * i + j * j + k * k < 9) ? 1 : 0;
  for (std::size_t a = 0; a < pos.size(); ++a) EXPECT_EQ(count[a], inside - 1) << "particle " << a;
}

TEST(PeriodicGrid, WrapMovesByWholePeriodsIntoTheBox) {
  CellGrid grid;
  const Vec3d lo{-0.25, 0.0, 0.1}, hi{0.25, 0.3, 0.6};  // x period 0.5, z period 0.5
  grid.configure(lo, hi, 0.03, 0.05, 3, {true, false, true});
  std::vector<Vec3d> pos = {
      {0.1, 0.1, 0.2},           // inside: unchanged
      {0.25, 0.1, 0.2},          // exactly at hi.x -> lo.x
      {-0.25, 0.1, 0.2},         // exactly at lo.x: unchanged
      {1.85, 0.1, 0.2},          // 3 periods + 0.1 above hi
      {-3.76, 0.1, 0.2},         // far below lo
      {0.0, 5.0, 0.6},           // y is not periodic: stays outside; z at hi -> lo
      {0.0, -1.0, -0.4 - 1e-3},  // z below lo
  };
  const std::vector<Vec3d> before = pos;
  EXPECT_EQ(grid.wrap(pos), 5u);
  const Vec3d expect[] = {{0.1, 0.1, 0.2},        {-0.25, 0.1, 0.2}, {-0.25, 0.1, 0.2},
                          {-0.15, 0.1, 0.2},      {0.24, 0.1, 0.2},  {0.0, 5.0, 0.1},
                          {0.0, -1.0, 0.6 - 1e-3}};
  for (std::size_t i = 0; i < pos.size(); ++i) {
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(pos[i][a], expect[i][a], 1e-12) << i << " axis " << a;
    EXPECT_EQ(pos[i].y, before[i].y) << "non-periodic axis moved";
  }
}

TEST(PeriodicGrid, WrapRandomValues) {
  CellGrid grid;
  const Vec3d lo{0.0, 0.0, 0.1}, hi{0.7, 0.3, 0.4};
  grid.configure(lo, hi, 0.03, 0.05, 3, {true, false, true});
  const double Lx = hi.x - lo.x, Lz = hi.z - lo.z;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-200.0, 200.0);
  std::vector<Vec3d> pos(20000);
  for (auto& p : pos) p = {u(rng), u(rng), u(rng)};
  // Values a hair below lo (x: lo = 0) and whole periods away from lo.
  pos.push_back({-1e-20, 0.1, 0.2});
  pos.push_back({-1e-300, 0.1, 0.2});
  pos.push_back({std::nextafter(0.0, -1.0), 0.1, 0.2});
  pos.push_back({-Lx, 0.1, lo.z - Lz});
  pos.push_back({Lx, 0.1, lo.z + 3 * Lz});
  const std::vector<Vec3d> before = pos;
  const std::size_t moved = grid.wrap(pos);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const Vec3d& p = pos[i];
    changed += (p == before[i]) ? 0 : 1;
    EXPECT_GE(p.x, lo.x) << i;
    EXPECT_LT(p.x, hi.x) << i;
    EXPECT_GE(p.z, lo.z) << i;
    EXPECT_LT(p.z, hi.z) << i;
    EXPECT_EQ(p.y, before[i].y) << "non-periodic axis moved " << i;
    // Moved by a whole number of periods.
    const double kx = (p.x - before[i].x) / Lx, kz = (p.z - before[i].z) / Lz;
    EXPECT_NEAR(kx, std::round(kx), 1e-9) << i;
    EXPECT_NEAR(kz, std::round(kz), 1e-9) << i;
    // wrap_shift is what wrap applied (to round-off: wrap assigns the wrapped value itself);
    // a wrapped position needs no further shift.
    const Vec3d s = grid.wrap_shift(before[i]);
    EXPECT_EQ(s.y, 0.0);
    EXPECT_NEAR(before[i].x + s.x, p.x, 1e-12) << i;
    EXPECT_NEAR(before[i].z + s.z, p.z, 1e-12) << i;
    EXPECT_TRUE(grid.wrap_shift(p) == Vec3d{}) << i;
  }
  EXPECT_EQ(moved, changed);
  const std::size_t n = pos.size();
  for (std::size_t i = n - 5; i < n; ++i) {
    EXPECT_NEAR(pos[i].x, 0.0, 1e-12) << i;
    EXPECT_NEAR(pos[i].z, i < n - 2 ? 0.2 : lo.z, 1e-12) << i;
  }
}

TEST(PeriodicGrid, WrapEdgeValuesLandInsideLoHi) {
  // Values exactly at hi, or one ulp below lo, must end inside [lo, hi): a naive p + shift or
  // a test against origin + period (which can round above hi) leaves them outside.
  {
    CellGrid grid;
    const Vec3d lo{0.0, 0.0, 0.1}, hi{0.7, 0.3, 0.4};
    grid.configure(lo, hi, 0.03, 0.05, 3, {true, false, true});
    std::vector<Vec3d> pos = {{0.2, 0.1, hi.z}, {0.2, 0.1, std::nextafter(lo.z, -1.0)}};
    grid.wrap(pos);
    for (const auto& p : pos) {
      EXPECT_GE(p.z, lo.z);
      EXPECT_LT(p.z, hi.z);
    }
    EXPECT_EQ(pos[0].z, lo.z);
  }
  {
    CellGrid grid;
    const Vec3d lo{-0.731, 0.0, 0.0}, hi{0.994, 0.3, 0.5};
    grid.configure(lo, hi, 0.03, 0.05, 3, {true, false, false});
    std::vector<Vec3d> pos = {{hi.x, 0.1, 0.1}};
    EXPECT_EQ(grid.wrap(pos), 1u);
    EXPECT_EQ(pos[0].x, lo.x);
  }
}

TEST(PeriodicGrid, WrapWithoutPeriodicAxesDoesNothing) {
  CellGrid grid;
  grid.configure({0, 0, 0}, {1, 1, 1}, 0.03, 0.05, 3);
  std::vector<Vec3d> pos = {{-5, 2, 7}, {0.5, 0.5, 0.5}};
  EXPECT_EQ(grid.wrap(pos), 0u);
  EXPECT_TRUE(pos[0] == Vec3d(-5, 2, 7));
  EXPECT_TRUE(grid.wrap_shift({-5, 2, 7}) == Vec3d{});
}

TEST(PeriodicGrid, ShortPeriodicExtentThrows) {
  const double support = 0.03, skin = 0.05;
  const double five_cells = 5 * support * (1 + skin) / CellGrid::kSearchCells;  // 0.07875
  CellGrid grid;
  EXPECT_THROW(grid.configure({0, 0, 0}, {0.07, 0.5, 0.5}, support, skin, 3, {true, false, false}),
               Error);
  EXPECT_THROW(grid.configure({0, 0, 0}, {0.5, 0.5, 0.07}, support, skin, 3, {false, false, true}),
               Error);
  EXPECT_THROW(grid.configure({0, 0, 0}, {0.5, 0.07, 0.5}, support, skin, 3, {false, true, false}),
               Error);
  EXPECT_THROW(grid.configure({0, 0, 0}, {five_cells * 0.999, 0, 0.5}, support, skin, 2,
                              {true, false, false}),
               Error);
  // Long enough, or not periodic: accepted.
  EXPECT_NO_THROW(grid.configure({0, 0, 0}, {five_cells * 1.001, 0, 0.5}, support, skin, 2,
                                 {true, false, false}));
  EXPECT_NO_THROW(grid.configure({0, 0, 0}, {0.07, 0.5, 0.5}, support, skin, 3));
  // In 2D the y flag is ignored (y has no extent).
  EXPECT_NO_THROW(grid.configure({0, 0, 0}, {0.5, 0, 0.5}, support, skin, 2, {false, true, false}));
  EXPECT_FALSE(grid.periodic(1));
}

TEST(PeriodicGrid, CellSizeDividesThePeriod) {
  const double support = 0.045, skin = 0.05;
  const double min_cell = support * (1 + skin) / CellGrid::kSearchCells;
  for (double len : {0.13, 0.237, 0.5, 1.0 / 3.0, 2.71828}) {
    CellGrid grid;
    const Vec3d lo{-0.3, 0.1, 1.0};
    grid.configure(lo, {lo.x + len, 0.5, 1.0 + 1.37 * len}, support, skin, 3, {true, false, true});
    for (int a : {0, 2}) {
      const double period = a == 0 ? len : 1.37 * len;
      const int n = grid.dims()[a];
      EXPECT_NEAR(grid.cell_size()[a] * n, period, 1e-12 * period) << len << " axis " << a;
      EXPECT_GE(grid.cell_size()[a], min_cell * (1 - 1e-12)) << len;
      // As many cells as fit: one more would be smaller than the minimum.
      EXPECT_LT(period / (n + 1), min_cell) << len;
      EXPECT_GE(n, 2 * CellGrid::kSearchCells + 1);
      EXPECT_DOUBLE_EQ(grid.period()[a], period);
    }
    // The non-periodic axis keeps the minimum cell and has no period.
    EXPECT_DOUBLE_EQ(grid.cell_size().y, min_cell);
    EXPECT_EQ(grid.period().y, 0.0);
    // The search still covers the support with the skin.
    EXPECT_GE(CellGrid::kSearchCells * grid.cell_size().x, support * (1 + skin) * (1 - 1e-12));
    EXPECT_GT(grid.max_displacement(), 0.0);
  }
}

}  // namespace
}  // namespace netsph
