#pragma once
// The numbers of a cell grid as a plain struct that kernels take by value, and the
// host/device functions over it: the cell of a position, wrapping into periodic axes, and the
// candidate ranges of a cell. CellGrid (cell_grid.hpp) sets them up (cell size, skin,
// periodic stretch) and answers its own queries through them, and the device-shaped step
// (backend/device/) takes a copy, so both backends find the same candidates in the same order:
// cells sorted with x fastest, searched kSearchCells cells on each side, each row of cells one
// index range, a row split in two where it crosses a periodic x boundary.
//
// Sorting is by key: the cell index, or `sentinel()` for a particle outside the grid (NaN, or
// past a non-periodic face), which puts the particles to drop at the end of the order.
// `cell_begin[c]` is the first sorted index whose key is >= c, for c in [0, cells + 1].
#include <cmath>
#include <cstdint>

#include "netsph/core/host_device.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct GridIndex {
  static constexpr int kSearchCells = 2;  ///< CellGrid::kSearchCells
  Vec3d origin{};
  Vec3d upper{};
  Vec3d inv_cell{};
  Vec3d period{};  ///< domain length on periodic axes, else 0
  int n[3] = {1, 1, 1};
  bool periodic[3] = {false, false, false};
  int dims = 3;

  NETSPH_HD std::uint32_t cells() const {
    return static_cast<std::uint32_t>(n[0]) * static_cast<std::uint32_t>(n[1]) *
           static_cast<std::uint32_t>(n[2]);
  }
  NETSPH_HD std::uint32_t sentinel() const { return cells(); }

  /// The cell key of a position: as CellGrid::cell_of, with sentinel() for "outside".
  NETSPH_HD std::uint32_t key_of(const Vec3d& p) const {
    std::uint32_t idx[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a) {
      if (dims == 2 && a == 1) continue;
      const double f = (p[a] - origin[a]) * inv_cell[a];
      if (!(f == f)) return sentinel();
      if (periodic[a]) {
        // Positions are wrapped first; this absorbs round-off at the ends, as CellGrid.
        const double fl = std::floor(f);
        idx[a] = fl < 0 ? 0u
                        : (fl > n[a] - 1 ? static_cast<std::uint32_t>(n[a] - 1)
                                         : static_cast<std::uint32_t>(fl));
      } else {
        if (!(f >= 0 && f < n[a])) return sentinel();
        idx[a] = static_cast<std::uint32_t>(f);
      }
    }
    return idx[0] +
           static_cast<std::uint32_t>(n[0]) * (idx[1] + static_cast<std::uint32_t>(n[1]) * idx[2]);
  }

  /// p moved into [origin, upper) along the periodic axes (CellGrid::wrapped).
  NETSPH_HD Vec3d wrapped(const Vec3d& p) const {
    Vec3d q = p;
    for (int a = 0; a < 3; ++a) {
      if (!periodic[a]) continue;
      const double lo = origin[a], hi = upper[a], len = period[a];
      double x = p[a];
      if (x >= lo && x < hi) continue;
      x = lo + std::fmod(x - lo, len);
      if (x < lo) x += len;
      if (x >= hi) x -= len;
      if (x < lo) x = lo;
      if (a == 0) q.x = x;
      if (a == 1) q.y = x;
      if (a == 2) q.z = x;
    }
    return q;
  }

  /// Calls visit(begin, end, shift) for every non-empty candidate range of cell `c`, in the
  /// order of CellGrid::neighbour_ranges (z rows, then y rows, then the x runs).
  template <class Visit>
  NETSPH_HD void for_each_range(const std::uint32_t* cell_begin, std::uint32_t c,
                                Visit&& visit) const {
    const std::uint32_t nx = static_cast<std::uint32_t>(n[0]);
    const std::uint32_t nxy = nx * static_cast<std::uint32_t>(n[1]);
    const int ic[3] = {static_cast<int>(c % nx), static_cast<int>((c / nx) % n[1]),
                       static_cast<int>(c / nxy)};
    // x: one run, split in two where it crosses a periodic boundary.
    int xlo[3], xhi[3];
    float xshift[3];
    int nxr = 0;
    const int x0 = ic[0] - kSearchCells, x1 = ic[0] + kSearchCells;
    const int xmin = x0 > 0 ? x0 : 0, xmax = x1 < n[0] - 1 ? x1 : n[0] - 1;
    if (periodic[0] && x0 < 0) {
      xlo[nxr] = x0 + n[0], xhi[nxr] = n[0] - 1, xshift[nxr++] = static_cast<float>(-period[0]);
    }
    xlo[nxr] = xmin, xhi[nxr] = xmax, xshift[nxr++] = 0.0f;
    if (periodic[0] && x1 >= n[0]) {
      xlo[nxr] = 0, xhi[nxr] = x1 - n[0], xshift[nxr++] = static_cast<float>(period[0]);
    }
    const int rz = kSearchCells, ry = dims == 2 ? 0 : kSearchCells;
    for (int dz = -rz; dz <= rz; ++dz) {
      int iz = ic[2] + dz;
      float sz = 0;
      if (periodic[2]) {
        if (iz < 0) iz += n[2], sz = static_cast<float>(-period[2]);
        if (iz >= n[2]) iz -= n[2], sz = static_cast<float>(period[2]);
      } else if (iz < 0 || iz >= n[2]) {
        continue;
      }
      for (int dy = -ry; dy <= ry; ++dy) {
        int iy = ic[1] + dy;
        float sy = 0;
        if (periodic[1]) {
          if (iy < 0) iy += n[1], sy = static_cast<float>(-period[1]);
          if (iy >= n[1]) iy -= n[1], sy = static_cast<float>(period[1]);
        } else if (iy < 0 || iy >= n[1]) {
          continue;
        }
        const std::uint32_t row =
            nx * static_cast<std::uint32_t>(iy) + nxy * static_cast<std::uint32_t>(iz);
        for (int k = 0; k < nxr; ++k) {
          const std::uint32_t b = cell_begin[row + static_cast<std::uint32_t>(xlo[k])];
          const std::uint32_t e = cell_begin[row + static_cast<std::uint32_t>(xhi[k]) + 1];
          if (b < e) visit(b, e, Vec3f(xshift[k], sy, sz));
        }
      }
    }
  }
};

}  // namespace netsph
