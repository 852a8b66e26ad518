// A trimmed scan (GridIndex::first_range with a point) leaves out the cells farther from the
// point than the support plus the largest displacement since the sort. It must still find
// every pair within the support after every particle has moved by up to that displacement
// (the state at the half step), across periodic boundaries too; its ranges must be pieces of
// the whole scan's, in the same order (so sums over them are bit for bit those over the whole
// scan); and in 3D it must test about a third fewer candidates, which is what it is for.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "netsph/neighbors/cell_grid.hpp"

namespace netsph {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;  // sorted slots

struct Case {
  Vec3d lo, hi;
  double support;
  int dims;
  std::array<bool, 3> periodic;
  std::size_t count;
  /// Where the particles go along x, if not over the whole domain (a far end of a long one).
  double fill_x0 = 0, fill_x1 = 0;
};

struct Scanned {
  PairSet pairs;                       ///< pairs within the support found by the trimmed scans
  PairSet expected;                    ///< by brute force (nearest image on periodic axes)
  std::size_t trimmed = 0, whole = 0;  ///< candidates tested
  bool pieces_in_order = true;         ///< every trimmed range lies in the whole scan's, in order
  /// Candidates of the whole scan whose cell (as sorted, moved by the range's shift) lies
  /// within the support plus the largest displacement of the point but which the trimmed scan
  /// left out: the random pairs above rarely come near that bound, this checks it directly.
  std::size_t reachable_left_out = 0;
};

/// The distance from p to the box [lo, lo + size] (size 0 on an axis: that axis ignored).
double box_distance(const Vec3d& p, const Vec3d& lo, const Vec3d& size) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    if (size[a] == 0) continue;
    const double g = std::max({lo[a] - p[a], p[a] - (lo[a] + size[a]), 0.0});
    d2 += g * g;
  }
  return std::sqrt(d2);
}

/// Sorts random particles, moves each by up to the grid's largest displacement in a random
/// direction (without wrapping, as between two sorts), then scans every particle's trimmed
/// ranges from its sorted cell and position.
Scanned scan(const Case& k, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), m(-1.0, 1.0);
  CellGrid grid;
  grid.configure(k.lo, k.hi, k.support, 0.05, k.dims, k.periodic);
  std::vector<Vec3d> pos(k.count);
  for (std::size_t i = 0; i < pos.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const bool fill = a == 0 && k.fill_x1 > k.fill_x0;
      const double lo = fill ? k.fill_x0 : k.lo[a], hi = fill ? k.fill_x1 : k.hi[a];
      // 2D: y = 0; a closed axis keeps the particles a displacement inside its faces.
      const double margin = k.periodic[a] ? 0.0 : grid.max_displacement();
      double x = k.dims == 2 && a == 1 ? 0.0 : lo + margin + u(rng) * (hi - lo - 2 * margin);
      if (i % 3 == 0 && !(k.dims == 2 && a == 1)) {
        // A third of them on a cell face, where a cell's distance is decided by round-off.
        const double cell = grid.cell_size()[a];
        const double face = k.lo[a] + std::round((x - k.lo[a]) / cell) * cell;
        if (face >= lo + margin && face <= hi - margin) x = face;
      }
      pos[i][a] = x;
    }
  }
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  const std::size_t n = order.size();
  std::vector<Vec3d> moved(n);
  for (std::size_t s = 0; s < n; ++s) {
    Vec3d d{m(rng), k.dims == 2 ? 0.0 : m(rng), m(rng)};
    // Half the particles go the whole displacement, the rest part of it.
    const double len = grid.max_displacement() * (s % 2 == 0 ? 1.0 : u(rng));
    moved[s] = pos[order[s]] + d * (len / std::max(norm(d), 1e-12));
  }
  const GridIndex& g = grid.index();
  std::vector<std::uint32_t> begin(static_cast<std::size_t>(grid.cell_count()) + 1);
  for (std::int64_t c = 0; c < grid.cell_count(); ++c) begin[c] = grid.cell_range(c).begin;
  begin.back() = static_cast<std::uint32_t>(n);
  const double s2 = k.support * k.support;
  Scanned out;
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::uint32_t c = static_cast<std::uint32_t>(grid.cell_of(pos[order[a]]));
    std::vector<NeighbourRange> whole;
    g.for_each_range(begin.data(), c, [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      whole.push_back({b0, b1, shift});
      out.whole += b1 - b0;
    });
    std::size_t w = 0;        // the whole scan's range the last trimmed one lay in
    std::uint32_t after = 0;  // where the last trimmed range ended, in whole range w
    const Vec3f at(moved[a] - k.lo);
    std::set<std::uint32_t> kept;
    g.for_each_range(begin.data(), c, at, [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      out.trimmed += b1 - b0;
      for (std::uint32_t b = b0; b < b1; ++b) kept.insert(b);
      // In the whole range w after the last piece, or in a later one: never overlapping,
      // repeated or out of order.
      while (w < whole.size() && !(std::max(whole[w].begin, after) <= b0 && b1 <= whole[w].end &&
                                   whole[w].shift == shift)) {
        ++w;
        after = 0;
      }
      if (w == whole.size()) out.pieces_in_order = false;
      after = b1;
      for (std::uint32_t b = b0; b < b1; ++b)
        if (b != a && norm2(moved[a] - (moved[b] + Vec3d(shift))) < s2) out.pairs.insert({a, b});
    });
    const double reach = k.support + grid.max_displacement();
    const Vec3d size =
        k.dims == 2 ? Vec3d{grid.cell_size().x, 0, grid.cell_size().z} : grid.cell_size();
    for (const NeighbourRange& r : whole)
      for (std::uint32_t b = r.begin; b < r.end; ++b) {
        const auto cb = static_cast<std::uint32_t>(grid.cell_of(pos[order[b]]));
        const auto nx = static_cast<std::uint32_t>(grid.dims()[0]);
        const auto ny = static_cast<std::uint32_t>(grid.dims()[1]);
        const Vec3d corner =
            k.lo + Vec3d(cb % nx * size.x, (cb / nx) % ny * size.y, cb / (nx * ny) * size.z) +
            Vec3d(r.shift);
        if (box_distance(moved[a], corner, size) < reach && !kept.count(b))
          ++out.reachable_left_out;
      }
    for (std::uint32_t b = 0; b < n; ++b) {
      if (b == a) continue;
      Vec3d d = moved[a] - moved[b];
      for (int ax = 0; ax < 3; ++ax) {
        if (!grid.periodic(ax)) continue;
        const double len = grid.period()[ax];
        d[ax] -= len * std::round(d[ax] / len);
      }
      if (norm2(d) < s2) out.expected.insert({a, b});
    }
  }
  return out;
}

void expect_trimmed_scan_finds_every_pair(const Case& k, double most_kept) {
  for (unsigned seed : {1u, 2u}) {
    const Scanned s = scan(k, seed);
    EXPECT_GT(s.expected.size(), 20 * k.count) << "seed " << seed;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> missed;
    std::set_difference(s.expected.begin(), s.expected.end(), s.pairs.begin(), s.pairs.end(),
                        std::back_inserter(missed));
    EXPECT_EQ(missed.size(), 0u) << "pairs within the support not found, seed " << seed;
    EXPECT_EQ(s.pairs.size(), s.expected.size()) << "seed " << seed;
    EXPECT_TRUE(s.pieces_in_order) << "seed " << seed;
    EXPECT_EQ(s.reachable_left_out, 0u) << "seed " << seed;
    const double kept = static_cast<double>(s.trimmed) / static_cast<double>(s.whole);
    EXPECT_LT(kept, most_kept) << "seed " << seed;
    std::printf("candidates kept by the trimmed scan: %.3f\n", kept);
  }
}

TEST(TrimmedScan, FindsEveryPairOfDisplacedParticles3D) {
  // Cells of 1.05 h (support 2h): a ball of radius 2.05 h touches about 65% of the 125 cells
  // around it (a Monte Carlo count over the point's place in its cell), fewer near the walls.
  expect_trimmed_scan_finds_every_pair({{0, 0, 0}, {0.3, 0.25, 0.2}, 0.04, 3, {}, 6000}, 0.70);
}

TEST(TrimmedScan, FindsEveryPairAcrossPeriodicBoundaries3D) {
  // Periodic on every axis: cells stretched to fill each period (x 0.023 m, y 0.021 m, z
  // 0.0248 m: a mix-up of axes shows), particles carried past the ends since the sort, ranges
  // split at the x ends.
  expect_trimmed_scan_finds_every_pair(
      {{-0.1, 0.0, 0.05}, {0.13, 0.21, 0.1739}, 0.04, 3, {true, true, true}, 4000}, 0.62);
}

TEST(TrimmedScan, FindsEveryPairIn2DPeriodicInX) {
  // 25 cells around a point in 2D, about 80% of them within reach.
  expect_trimmed_scan_finds_every_pair(
      {{0.0, 0.0, 0.0}, {0.4, 0.0, 0.3}, 0.03, 2, {true, false, false}, 3000}, 0.86);
}

TEST(TrimmedScan, FindsEveryPairAtTheFarEndOfALongDomain) {
  // 300 m of 2D channel at support 4 mm, the particles in its last 15 cm: a float there keeps
  // 3e-5 m, 1% of the support, and the reach's margin (16 float epsilons of the domain size)
  // must cover the round-off of the point's offset in its cell.
  expect_trimmed_scan_finds_every_pair(
      {{0.0, 0.0, 0.0}, {300.0, 0.0, 0.03}, 0.004, 2, {}, 2500, 299.85, 300.0}, 0.95);
}

TEST(TrimmedScan, WithoutReachTheScanIsTheWholeOne) {
  CellGrid grid;
  grid.configure({0, 0, 0}, {0.2, 0.2, 0.2}, 0.04, 0.05, 3, {true, false, false});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 0.2);
  std::vector<Vec3d> pos(500);
  for (auto& p : pos) p = {u(rng), u(rng), u(rng)};
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  GridIndex g = grid.index();
  g.reach = 0;
  std::vector<std::uint32_t> begin(static_cast<std::size_t>(grid.cell_count()) + 1);
  for (std::int64_t c = 0; c < grid.cell_count(); ++c) begin[c] = grid.cell_range(c).begin;
  begin.back() = static_cast<std::uint32_t>(order.size());
  for (std::uint32_t c = 0; c < g.cells(); ++c) {
    std::vector<std::uint32_t> whole, untrimmed;
    g.for_each_range(begin.data(), c, [&](std::uint32_t b0, std::uint32_t b1, Vec3f) {
      whole.insert(whole.end(), {b0, b1});
    });
    g.for_each_range(begin.data(), c, Vec3f(0.1f, 0.1f, 0.1f),
                     [&](std::uint32_t b0, std::uint32_t b1, Vec3f) {
                       untrimmed.insert(untrimmed.end(), {b0, b1});
                     });
    ASSERT_EQ(whole, untrimmed) << "cell " << c;
  }
}

}  // namespace
}  // namespace netsph
