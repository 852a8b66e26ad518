#pragma once
// Uniform cell grid for the neighbour search. Particles are sorted by cell (x fastest), so
// the candidates of a particle are a few contiguous index ranges: for every (dy, dz) offset,
// the run of cells ix-R..ix+R is one range. Cells are support/2 (plus a skin) wide and R = 2:
// a third fewer candidates than cells of the full support with R = 1 (in 3D, 125 cells of
// 1.05 h = 145 h^3 against 27 cells of 2h = 216 h^3), at 25 ranges per cell instead of 9.
//
// The skin lets one sort serve both symplectic stages: a pair that is within the support at
// the half step was within support + 2*max_displacement when the grid was built, and the
// search covers R * cell_size >= support * (1 + skin). The solver checks the displacement and
// rebuilds when it exceeds the skin (docs/ARCHITECTURE.md, "Neighbour search").
//
// Periodic axes: the cell size is stretched so that the period holds a whole number of cells
// (at least 2R + 1, so that no neighbour is seen twice), and ranges that cross the period end
// are split, each carrying the shift (+-L) to add to the neighbours' positions. Positions must
// lie inside the period when sorting (the solver wraps them first).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/core/vec3.hpp"
#include "netsph/neighbours/grid_index.hpp"

namespace netsph {

/// A contiguous range of sorted particle indices [begin, end).
struct IndexRange {
  std::uint32_t begin;
  std::uint32_t end;
};

/// Candidate neighbours: a range of sorted indices and the periodic shift to add to their
/// positions (zero unless the range lies across a periodic boundary).
struct NeighbourRange {
  std::uint32_t begin;
  std::uint32_t end;
  Vec3f shift;
};

/// Enough for 3D: (2R+1)^2 rows of cells, each split in two at most by a periodic x boundary.
using NeighbourRanges = std::array<NeighbourRange, 50>;

class CellGrid {
 public:
  static constexpr int kSearchCells = GridIndex::kSearchCells;  ///< R: cells searched on each side

  /// Lays the grid over the box [lo, hi] (the domain). `support` is the kernel radius;
  /// `skin` the relative margin (cell = support (1 + skin) / R). dims = 2 uses one y cell.
  /// Throws netsph::Error if a periodic axis is shorter than 2R + 1 cells.
  void configure(const Vec3d& lo, const Vec3d& hi, double support, double skin, int dims,
                 std::array<bool, 3> periodic = {});

  /// Cell index of a position, or -1 outside the grid (on a periodic axis a position a
  /// round-off outside the period is taken as inside).
  std::int64_t cell_of(const Vec3d& p) const;

  /// Moves positions on periodic axes into [lo, hi) by whole periods; returns how many moved.
  std::size_t wrap(std::span<Vec3d> pos) const;
  /// p moved into [lo, hi) along the periodic axes.
  Vec3d wrapped(const Vec3d& p) const;
  /// The shift wrap() would apply to p (zero when p is inside on every periodic axis).
  Vec3d wrap_shift(const Vec3d& p) const;

  /// Sorts by cell, and within a cell by position (cell_grid.cpp says why). Fills `order`
  /// (sorted slot -> old index; particles outside the grid are left out) and the cell ranges.
  /// The order is a function of the positions alone (but for particles at one position,
  /// kept in their earlier order): the same for any thread count, any earlier order of the
  /// particles, and any split of them over processes.
  void sort(std::span<const Vec3d> pos, std::vector<std::uint32_t>& order);

  /// Adopts the cell table of a sort made elsewhere with the same index (the device step's):
  /// begin[c] is the first sorted index of cell c; cell_count() + 1 entries are read.
  void adopt_ranges(std::span<const std::uint32_t> begin);

  /// Largest displacement allowed since the last sort before a rebuild is needed, m.
  double max_displacement() const { return max_displacement_; }

  /// The candidate ranges of cell `c`; returns how many were written.
  int neighbour_ranges(std::int64_t c, NeighbourRanges& out) const;

  std::int64_t cell_count() const { return static_cast<std::int64_t>(n_[0]) * n_[1] * n_[2]; }
  /// The cells holding at least one particle after the last sort, in increasing order: loops
  /// over particles by cell visit these instead of every cell of a mostly empty domain.
  const std::vector<std::int64_t>& occupied_cells() const { return occupied_; }
  IndexRange cell_range(std::int64_t c) const { return {begin_[c], begin_[c + 1]}; }
  const std::array<int, 3>& dims() const { return n_; }
  const Vec3d& cell_size() const { return cell_; }
  /// The grid's numbers, for kernels (grid_index.hpp).
  const GridIndex& index() const { return index_; }
  const Vec3d& origin() const { return origin_; }
  const Vec3d& period() const { return period_; }  ///< domain length on periodic axes, else 0
  bool periodic(int axis) const { return periodic_[axis]; }
  std::size_t bytes() const {
    return begin_.capacity() * sizeof(std::uint32_t) + occupied_.capacity() * sizeof(std::int64_t) +
           scratch_.capacity_bytes();
  }

 private:
  struct CellScratch {
    std::vector<std::int64_t> cell_of_particle;
    std::size_t capacity_bytes() const {
      return cell_of_particle.capacity() * sizeof(std::int64_t);
    }
  };

  Vec3d origin_{};
  Vec3d upper_{};
  Vec3d cell_{1, 1, 1};
  Vec3d inv_cell_{1, 1, 1};
  Vec3d period_{};
  std::array<bool, 3> periodic_{};
  GridIndex index_;
  double max_displacement_ = 0;
  std::array<int, 3> n_{1, 1, 1};
  int dims_ = 3;
  std::vector<std::uint32_t> begin_;  // size cell_count() + 1
  std::vector<std::int64_t> occupied_;
  CellScratch scratch_;
};

}  // namespace netsph
