#include "netsph/neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "netsph/core/growth.hpp"

#include "netsph/core/error.hpp"

namespace netsph {

namespace {

/// Whether particle i comes before particle j within their cell: by z, then y, then x, and
/// by the earlier order only for two particles at one position.
bool before_in_cell(std::span<const Vec3d> pos, std::uint32_t i, std::uint32_t j) {
  const Vec3d &a = pos[i], &b = pos[j];
  if (a.z != b.z) return a.z < b.z;
  if (a.y != b.y) return a.y < b.y;
  if (a.x != b.x) return a.x < b.x;
  return i < j;
}

/// The cell table's keys are 32-bit, with one key kept for "outside the grid".
constexpr double kMostCells = 2e9;

[[noreturn]] void throw_too_many_cells(double cells, double cell_size) {
  throw Error("[domain]",
              fmt::format("the domain holds {:.3g} cells of the neighbour grid ({:.4g} m "
                          "wide), more than {:.0e}; shrink [domain] or raise dp",
                          cells, cell_size, kMostCells));
}

}  // namespace

void CellGrid::configure(const Vec3d& lo, const Vec3d& hi, double support, double skin, int dims,
                         std::array<bool, 3> periodic) {
  if (!(support > 0) || !(skin >= 0)) throw Error("neighbours", "invalid support or skin");
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
    if (!(len > 0)) throw Error("neighbours", std::string("empty domain on ") + axis_name[a]);
    if (periodic_[a]) {
      // A whole number of cells per period, each at least min_cell wide.
      const double count = std::floor(len / min_cell);
      if (!(count <= kMostCells)) throw_too_many_cells(count, min_cell);
      n_[a] = static_cast<int>(count);
      if (n_[a] < 2 * kSearchCells + 1) {
        throw Error("[domain]", std::string("the periodic ") + axis_name[a] + " extent " +
                                    std::to_string(len) + " m is shorter than " +
                                    std::to_string((2 * kSearchCells + 1) * min_cell) +
                                    " m (2.5 kernel supports); make the domain longer");
      }
      cell_[a] = len / n_[a];
      period_[a] = len;
    } else {
      // Counted in double first: a domain of 1e8 m or more on one axis at millimetre cells
      // overflowed the int, every particle then lay "outside" the grid and the run stopped at
      // step 0 blaming the fluid for leaving the domain.
      const double count = std::ceil(len / min_cell);
      if (!(count <= kMostCells)) throw_too_many_cells(count, min_cell);
      n_[a] = std::max(1, static_cast<int>(count));
      cell_[a] = min_cell;
    }
    inv_cell_[a] = 1.0 / cell_[a];
    smallest = std::min(smallest, cell_[a]);
  }
  // The displacement budget is split evenly between the two particles of a pair.
  max_displacement_ = 0.5 * (kSearchCells * smallest - support);
  const double cells = static_cast<double>(n_[0]) * n_[1] * n_[2];
  if (cells > kMostCells) throw_too_many_cells(cells, min_cell);
  begin_.assign(static_cast<std::size_t>(cell_count()) + 1, 0);
  index_.origin = origin_;
  index_.upper = upper_;
  index_.inv_cell = inv_cell_;
  index_.period = period_;
  index_.dims = dims_;
  for (int a = 0; a < 3; ++a) index_.n[a] = n_[a], index_.periodic[a] = periodic_[a];
}

std::int64_t CellGrid::cell_of(const Vec3d& p) const {
  const std::uint32_t key = index_.key_of(p);
  return key == index_.sentinel() ? -1 : static_cast<std::int64_t>(key);
}

Vec3d CellGrid::wrapped(const Vec3d& p) const {
  return index_.wrapped(p);
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
  resize_for(cell, pos.size());
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
  resize_for(order, kept);
  // Use begin_ shifted by one as the running insertion cursor, then shift back.
  for (std::int64_t i = 0; i < n; ++i) {
    if (cell[i] >= 0) order[begin_[cell[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::int64_t c = nc; c > 0; --c) begin_[c] = begin_[c - 1];
  begin_[0] = 0;

  // Within each cell, by position. The particles' earlier order is their arrays' history:
  // on one process the fill order, in a run split over processes also which process held a
  // particle and when it arrived there. A pair sum visits the neighbours in this order, and
  // its float round-off depends on it; with the order set by the positions alone, a split run
  // sums every pair in the order of the run on one process and the two agree to the bit
  // (tests/physics/distributed_test.cpp), on any CPU. Insertion sort: a cell holds a few
  // particles (cells are half the support wide), and the last step's order is nearly this one.
  const auto occupied = static_cast<std::int64_t>(occupied_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < occupied; ++k) {
    const std::int64_t c = occupied_[k];
    std::uint32_t* first = order.data() + begin_[c];
    std::uint32_t* last = order.data() + begin_[c + 1];
    for (std::uint32_t* it = first + 1; it < last; ++it) {
      const std::uint32_t moving = *it;
      std::uint32_t* hole = it;
      for (; hole > first && before_in_cell(pos, moving, hole[-1]); --hole) *hole = hole[-1];
      *hole = moving;
    }
  }
}

void CellGrid::adopt_ranges(std::span<const std::uint32_t> begin) {
  const auto nc = static_cast<std::size_t>(cell_count());
  if (begin.size() < nc + 1) throw Error("neighbours", "cell table shorter than the grid");
  begin_.assign(begin.begin(), begin.begin() + static_cast<std::ptrdiff_t>(nc + 1));
  occupied_.clear();
  for (std::size_t c = 0; c < nc; ++c)
    if (begin_[c + 1] > begin_[c]) occupied_.push_back(static_cast<std::int64_t>(c));
}

int CellGrid::neighbour_ranges(std::int64_t c, NeighbourRanges& out) const {
  int count = 0;
  index_.for_each_range(begin_.data(), static_cast<std::uint32_t>(c),
                        [&](std::uint32_t b, std::uint32_t e, Vec3f shift) {
                          out[static_cast<std::size_t>(count++)] = {b, e, shift};
                        });
  return count;
}

}  // namespace netsph
