#include "netsph/neighbors/cell_grid.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/error.hpp"

namespace netsph {

void CellGrid::configure(const Vec3d& lo, const Vec3d& hi, double support, double skin, int dims) {
  if (!(support > 0) || !(skin >= 0)) throw Error("neighbors", "invalid support or skin");
  dims_ = dims;
  cell_ = support * (1.0 + skin) / kSearchCells;
  inv_cell_ = 1.0 / cell_;
  // The displacement budget is split evenly between the two particles of a pair.
  max_displacement_ = 0.5 * (kSearchCells * cell_ - support);
  origin_ = lo;
  for (int a = 0; a < 3; ++a) {
    if (dims == 2 && a == 1) {
      n_[a] = 1;
      continue;
    }
    const double len = hi[a] - lo[a];
    if (!(len > 0)) throw Error("neighbors", "empty domain on one axis");
    n_[a] = std::max(1, static_cast<int>(std::ceil(len * inv_cell_)));
  }
  const double cells = static_cast<double>(n_[0]) * n_[1] * n_[2];
  if (cells > 2e9) {
    throw Error("neighbors", "the domain holds more than 2e9 cells of size " +
                                 std::to_string(cell_) + " m; shrink [domain] or raise dp");
  }
  begin_.assign(static_cast<std::size_t>(cell_count()) + 1, 0);
}

std::int64_t CellGrid::cell_of(const Vec3d& p) const {
  const double fx = (p.x - origin_.x) * inv_cell_;
  const double fy = dims_ == 2 ? 0.0 : (p.y - origin_.y) * inv_cell_;
  const double fz = (p.z - origin_.z) * inv_cell_;
  // The negated comparisons also reject NaN.
  if (!(fx >= 0 && fy >= 0 && fz >= 0 && fx < n_[0] && fy < n_[1] && fz < n_[2])) return -1;
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const auto iz = static_cast<std::int64_t>(fz);
  return ix + n_[0] * (iy + static_cast<std::int64_t>(n_[1]) * iz);
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

int CellGrid::neighbour_ranges(std::int64_t c, std::array<IndexRange, 25>& out) const {
  const std::int64_t nx = n_[0], nxy = static_cast<std::int64_t>(n_[0]) * n_[1];
  const int ix = static_cast<int>(c % nx);
  const int iy = static_cast<int>((c / nx) % n_[1]);
  const int iz = static_cast<int>(c / nxy);
  const int x0 = std::max(ix - kSearchCells, 0), x1 = std::min(ix + kSearchCells, n_[0] - 1);
  const int y0 = std::max(iy - kSearchCells, 0), y1 = std::min(iy + kSearchCells, n_[1] - 1);
  const int z0 = std::max(iz - kSearchCells, 0), z1 = std::min(iz + kSearchCells, n_[2] - 1);
  int count = 0;
  for (int z = z0; z <= z1; ++z) {
    for (int y = y0; y <= y1; ++y) {
      const std::int64_t row = nx * y + nxy * z;
      const std::uint32_t b = begin_[row + x0], e = begin_[row + x1 + 1];
      if (b < e) out[count++] = {b, e};
    }
  }
  return count;
}

}  // namespace netsph
