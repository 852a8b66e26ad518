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

/// Where a scan of a cell's candidate ranges stands (GridIndex::first_range, next_range): the
/// current range [b, e) of sorted indices and the shift its particles' positions take across
/// periodic boundaries.
struct RangeCursor {
  std::uint32_t b = 0, e = 0;
  Vec3f shift{};
  int cx = 0, cy = 0, cz = 0;   ///< the cell searched around
  int dz = 0, dy = 0, run = 0;  ///< the range's z and y rows and x run (0, 1, 2)
  NETSPH_HD bool done() const { return b == e; }
};

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

  /// Cell index i on axis a (y or z) moved into the grid across a periodic boundary, with the
  /// shift that brings the particles there next to the searching cell; false if i is outside a
  /// non-periodic axis.
  NETSPH_HD bool wrap_row(int a, int& i, float& shift) const {
    if (!periodic[a]) return i >= 0 && i < n[a];
    if (i < 0) i += n[a], shift = static_cast<float>(-period[a]);
    if (i >= n[a]) i -= n[a], shift = static_cast<float>(period[a]);
    return true;
  }

  /// Calls visit(begin, end, shift) for every non-empty candidate range of cell `c`, in the
  /// order of next_range.
  template <class Visit>
  NETSPH_HD void for_each_range(const std::uint32_t* cell_begin, std::uint32_t c,
                                Visit&& visit) const {
    for (RangeCursor r = first_range(cell_begin, c); !r.done(); next_range(cell_begin, r))
      visit(r.b, r.e, r.shift);
  }

 private:
  /// The first non-empty candidate range of cell `c` (done() if it has none).
  NETSPH_HD RangeCursor first_range(const std::uint32_t* cell_begin, std::uint32_t c) const {
    RangeCursor r = cursor_at(c);
    next_range(cell_begin, r);
    return r;
  }

  /// Moves r to the next non-empty candidate range, in the order of
  /// CellGrid::neighbour_ranges: z rows, then y rows, then the x runs (the part wrapped from
  /// the low end of a periodic x axis, the run inside the grid, the part wrapped from the high
  /// end). r is done() after the last.
  NETSPH_HD void next_range(const std::uint32_t* cell_begin, RangeCursor& r) const {
    const int rz = kSearchCells, ry = dims == 2 ? 0 : kSearchCells;
    const int x0 = r.cx - kSearchCells, x1 = r.cx + kSearchCells;
    for (;;) {
      if (++r.run > 2) {
        r.run = 0;
        if (++r.dy > ry) {
          r.dy = -ry;
          if (++r.dz > rz) {
            r.b = r.e = 0;
            return;
          }
        }
      }
      if (r.run == 0 && !(periodic[0] && x0 < 0)) continue;
      if (r.run == 2 && !(periodic[0] && x1 >= n[0])) continue;
      int iz = r.cz + r.dz;
      float sz = 0;
      if (!wrap_row(2, iz, sz)) {
        r.dy = ry, r.run = 2;  // the whole z row is outside: on to the next
        continue;
      }
      int iy = r.cy + r.dy;
      float sy = 0;
      if (!wrap_row(1, iy, sy)) {
        r.run = 2;  // the whole y row is outside
        continue;
      }
      // The row's cells [lo, hi], numbered as if the x axis went on past its ends, cut to the
      // run's part of them (the wrapped low end, the grid, the wrapped high end) and moved into
      // the grid.
      int lo = x0, hi = x1;
      float sx = 0;
      if (r.run == 0) {
        hi = hi < -1 ? hi : -1;
        lo += n[0], hi += n[0], sx = static_cast<float>(-period[0]);
      } else if (r.run == 1) {
        lo = lo > 0 ? lo : 0, hi = hi < n[0] - 1 ? hi : n[0] - 1;
      } else {
        lo = lo > n[0] ? lo : n[0];
        lo -= n[0], hi -= n[0], sx = static_cast<float>(period[0]);
      }
      if (lo > hi) continue;
      const std::uint32_t row = static_cast<std::uint32_t>(n[0]) *
                                (static_cast<std::uint32_t>(iy) +
                                 static_cast<std::uint32_t>(n[1]) * static_cast<std::uint32_t>(iz));
      const std::uint32_t b = cell_begin[row + static_cast<std::uint32_t>(lo)];
      const std::uint32_t e = cell_begin[row + static_cast<std::uint32_t>(hi) + 1];
      if (b < e) {
        r.b = b, r.e = e, r.shift = Vec3f(sx, sy, sz);
        return;
      }
    }
  }

  NETSPH_HD RangeCursor cursor_at(std::uint32_t c) const {
    const std::uint32_t nx = static_cast<std::uint32_t>(n[0]);
    const std::uint32_t nxy = nx * static_cast<std::uint32_t>(n[1]);
    RangeCursor r;
    r.cx = static_cast<int>(c % nx), r.cy = static_cast<int>((c / nx) % n[1]);
    r.cz = static_cast<int>(c / nxy);
    r.dz = -kSearchCells, r.dy = dims == 2 ? 0 : -kSearchCells, r.run = -1;
    return r;
  }
};

}  // namespace netsph
