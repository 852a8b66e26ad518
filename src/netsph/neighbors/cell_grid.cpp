#include "netsph/neighbors/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "netsph/core/error.hpp"

namespace netsph {

void CellGrid::configure(const Vec3d& lo, const Vec3d& hi, double support, double skin, int dims,
                         std::array<bool, 3> periodic) {
  if (!(support > 0) || !(skin >= 0)) throw Error("neighbors", "invalid support or skin");
  dims_ = dims;
  origin_ = lo;
  upper_ = hi;
  const double min_cell = support * (1.0 + skin) / kSearchCells;
  static const char* axis_name[] = {"x", "y", "z"};
  double smallest = 1e300;
  for (int a = 0; a < 3; ++a) {
    periodic_[a] = periodic[a] && !(dims == 2 && a == 1);
    period_[a] = 0;
    if (dims == 2 && a == 1) {
      n_[a] = 1, cell_[a] = min_cell, inv_cell_[a] = 1 / min_cell;
      continue;
    }
    const double len = hi[a] - lo[a];
    if (!(len > 0)) throw Error("neighbors", std::string("empty domain on ") + axis_name[a]);
    if (periodic_[a]) {
      // A whole number of cells per period, each at least min_cell wide.
      n_[a] = static_cast<int>(std::floor(len / min_cell));
      if (n_[a] < 2 * kSearchCells + 1) {
        throw Error("[domain]", std::string("the periodic ") + axis_name[a] + " extent " +
                                    std::to_string(len) + " m is shorter than " +
                                    std::to_string((2 * kSearchCells + 1) * min_cell) +
                                    " m (2.5 kernel supports); make the domain longer");
      }
      cell_[a] = len / n_[a];
      period_[a] = len;
    } else {
      n_[a] = std::max(1, static_cast<int>(std::ceil(len / min_cell)));
      cell_[a] = min_cell;
    }
    inv_cell_[a] = 1.0 / cell_[a];
    smallest = std::min(smallest, cell_[a]);
  }
  // The displacement budget is split evenly between the two particles of a pair.
  max_displacement_ = 0.5 * (kSearchCells * smallest - support);
  const double cells = static_cast<double>(n_[0]) * n_[1] * n_[2];
  if (cells > 2e9) {
    throw Error("neighbors", "the domain holds more than 2e9 cells of size " +
                                 std::to_string(min_cell) + " m; shrink [domain] or raise dp");
  }
  begin_.assign(static_cast<std::size_t>(cell_count()) + 1, 0);
}

std::int64_t CellGrid::cell_of(const Vec3d& p) const {
  std::int64_t idx[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    if (dims_ == 2 && a == 1) continue;
    const double f = (p[a] - origin_[a]) * inv_cell_[a];
    if (!(f == f)) return -1;  // NaN
    if (periodic_[a]) {
      // Positions are wrapped before sorting; this only absorbs round-off at the ends.
      idx[a] = std::clamp(static_cast<std::int64_t>(std::floor(f)), std::int64_t{0},
                          static_cast<std::int64_t>(n_[a] - 1));
    } else {
      if (!(f >= 0 && f < n_[a])) return -1;
      idx[a] = static_cast<std::int64_t>(f);
    }
  }
  return idx[0] + n_[0] * (idx[1] + static_cast<std::int64_t>(n_[1]) * idx[2]);
}

Vec3d CellGrid::wrapped(const Vec3d& p) const {
  Vec3d q = p;
  for (int a = 0; a < 3; ++a) {
    if (!periodic_[a]) continue;
    const double lo = origin_[a], hi = upper_[a], len = period_[a];
    double x = p[a];
    if (x >= lo && x < hi) continue;
    x = lo + std::fmod(x - lo, len);
    // Round-off can leave x a last bit outside [lo, hi): fold it back explicitly.
    if (x < lo) x += len;
    if (x >= hi) x -= len;
    if (x < lo) x = lo;
    q[a] = x;
  }
  return q;
}

Vec3d CellGrid::wrap_shift(const Vec3d& p) const {
  return wrapped(p) - p;
}

std::size_t CellGrid::wrap(std::span<Vec3d> pos) const {
  if (!periodic_[0] && !periodic_[1] && !periodic_[2]) return 0;
  std::size_t moved = 0;
  for (auto& p : pos) {
    const Vec3d q = wrapped(p);
    if (!(q == p)) p = q, ++moved;
  }
  return moved;
}

void CellGrid::sort(std::span<const Vec3d> pos, std::vector<std::uint32_t>& order) {
  const auto n = static_cast<std::int64_t>(pos.size());
  auto& cell = scratch_.cell_of_particle;
  cell.resize(pos.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) cell[i] = cell_of(pos[i]);

  // Counting sort: histogram, exclusive prefix sum, stable scatter. Serial on purpose: it is
  // a few ms for 1e6 particles and gives the same order for any thread count.
  const std::int64_t nc = cell_count();
  std::fill(begin_.begin(), begin_.end(), 0u);
  std::uint32_t kept = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    if (cell[i] >= 0) ++begin_[cell[i] + 1], ++kept;
  }
  occupied_.clear();
  for (std::int64_t c = 0; c < nc; ++c) {
    if (begin_[c + 1] > 0) occupied_.push_back(c);
    begin_[c + 1] += begin_[c];
  }
  order.resize(kept);
  // Use begin_ shifted by one as the running insertion cursor, then shift back.
  for (std::int64_t i = 0; i < n; ++i) {
    if (cell[i] >= 0) order[begin_[cell[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::int64_t c = nc; c > 0; --c) begin_[c] = begin_[c - 1];
  begin_[0] = 0;
}

namespace {

/// Neighbouring index of i + d on an axis: clamped (returns false outside) or wrapped with
/// the period shift the neighbours' positions need.
struct AxisStep {
  int index;
  double shift;
};

}  // namespace

int CellGrid::neighbour_ranges(std::int64_t c, NeighbourRanges& out) const {
  const std::int64_t nx = n_[0], nxy = static_cast<std::int64_t>(n_[0]) * n_[1];
  const int ic[3] = {static_cast<int>(c % nx), static_cast<int>((c / nx) % n_[1]),
                     static_cast<int>(c / nxy)};
  // Rows of cells along y and z (with their wrap shift), and the x span.
  auto rows = [&](int a, AxisStep* steps) {
    int count = 0;
    const int r = (dims_ == 2 && a == 1) ? 0 : kSearchCells;
    for (int d = -r; d <= r; ++d) {
      int i = ic[a] + d;
      double shift = 0;
      if (periodic_[a]) {
        if (i < 0) i += n_[a], shift = -period_[a];
        if (i >= n_[a]) i -= n_[a], shift = period_[a];
      } else if (i < 0 || i >= n_[a]) {
        continue;
      }
      steps[count++] = {i, shift};
    }
    return count;
  };
  AxisStep ys[2 * kSearchCells + 1], zs[2 * kSearchCells + 1];
  const int ny = rows(1, ys), nz = rows(2, zs);

  // x: one contiguous run, split in two where it crosses a periodic boundary.
  struct XRun {
    int lo, hi;
    double shift;
  } xr[3];
  int nxr = 0;
  const int x0 = ic[0] - kSearchCells, x1 = ic[0] + kSearchCells;
  if (periodic_[0]) {
    if (x0 < 0) xr[nxr++] = {x0 + n_[0], n_[0] - 1, -period_[0]};
    xr[nxr++] = {std::max(x0, 0), std::min(x1, n_[0] - 1), 0.0};
    if (x1 >= n_[0]) xr[nxr++] = {0, x1 - n_[0], period_[0]};
  } else {
    xr[nxr++] = {std::max(x0, 0), std::min(x1, n_[0] - 1), 0.0};
  }

  int count = 0;
  for (int kz = 0; kz < nz; ++kz) {
    for (int ky = 0; ky < ny; ++ky) {
      const std::int64_t row = nx * ys[ky].index + nxy * zs[kz].index;
      for (int k = 0; k < nxr; ++k) {
        const std::uint32_t b = begin_[row + xr[k].lo], e = begin_[row + xr[k].hi + 1];
        if (b < e) {
          out[count++] = {b, e,
                          Vec3f(static_cast<float>(xr[k].shift), static_cast<float>(ys[ky].shift),
                                static_cast<float>(zs[kz].shift))};
        }
      }
    }
  }
  return count;
}

}  // namespace netsph
