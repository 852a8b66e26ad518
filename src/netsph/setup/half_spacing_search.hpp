#pragma once
// Particles within dp/2 of a particle: set-up's test for particles on top of each other (fluid
// on walls or on earlier fills, bodies inside walls or other bodies).
//
// The grid's cells are dp wide, and a particle's candidates are those of the 2 cells on each
// axis nearest it (its own and the neighbour on the side of its nearer face; 3 within a
// round-off of the middle): every particle within dp/2 lies in them. The grid spans the
// particles' bounding box, air included, at 4 B a cell: with cells of dp/2 (the grid of the
// kernel support searched +-2 cells) it took 8 times as much, 270 MB for the 3D dam break at
// dp = 3.75 mm (1.7e6 particles), more than the run itself holds, and refused that case at
// dp = 1.2 mm for having over 2e9 cells.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

class HalfSpacingSearch {
 public:
  /// Over the particles of `p` as they are now, in a grid spanning [lo, hi].
  HalfSpacingSearch(const ParticleSet& p, double dp, const Vec3d& lo, const Vec3d& hi, int dims)
      : p_(p), dims_(dims), tol2_(0.25 * dp * dp) {
    grid_.configure(lo, hi, CellGrid::kSearchCells * dp, 0.0, dims);  // cells of dp
    grid_.sort(p.pos, order_);
  }

  /// A particle b with accept(b) closer than dp/2 to particle a (the first in the grid's
  /// order), or -1.
  template <class Accept>
  std::int64_t find(std::uint32_t a, Accept accept) const {
    const GridIndex& index = grid_.index();
    int first[3] = {0, 0, 0}, last[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (dims_ == 2 && k == 1) continue;
      const double f = (p_.pos[a][k] - index.origin[k]) * index.inv_cell[k];
      const int own = static_cast<int>(std::floor(f));
      const double within = f - own;    // 0..1 in its cell
      constexpr double kMargin = 1e-6;  // of a cell: covers the round-off of f
      first[k] = std::max(within < 0.5 + kMargin ? own - 1 : own, 0);
      last[k] = std::min(within > 0.5 - kMargin ? own + 1 : own, index.n[k] - 1);
    }
    if (first[0] > last[0]) return -1;  // outside the grid (none is: it spans them all)
    for (int z = first[2]; z <= last[2]; ++z)
      for (int y = first[1]; y <= last[1]; ++y) {
        const std::int64_t row = (static_cast<std::int64_t>(z) * index.n[1] + y) * index.n[0];
        const std::uint32_t begin = grid_.cell_range(row + first[0]).begin;
        const std::uint32_t end = grid_.cell_range(row + last[0]).end;
        for (std::uint32_t t = begin; t < end; ++t) {
          const std::uint32_t b = order_[t];
          if (accept(b) && norm2(p_.pos[a] - p_.pos[b]) < tol2_) return b;
        }
      }
    return -1;
  }

 private:
  const ParticleSet& p_;
  int dims_;
  double tol2_;
  CellGrid grid_;
  std::vector<std::uint32_t> order_;
};

}  // namespace netsph
