#include "netsph/geometry/box_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "netsph/core/error.hpp"

namespace netsph {

std::array<int, 3> lattice_counts(const LatticeBox& box, double dp) {
  std::array<int, 3> n{1, 1, 1};
  static const char* axis_name[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (box.dims == 2 && a == 1) continue;
    const double len = box.max[a] - box.min[a];
    const double spacings = std::round(len / dp);
    // The case reader refuses such boxes with their file and line; this guards other callers.
    if (!(spacings <= 2147483647.0)) {
      throw Error("geometry", std::string("box holds more than 2^31 - 1 particle spacings on ") +
                                  axis_name[a] + " (length " + std::to_string(len) +
                                  " m): dp is too small");
    }
    n[a] = static_cast<int>(spacings);
    if (n[a] < 1) {
      throw Error("geometry", std::string("box is thinner than dp on ") + axis_name[a] +
                                  " (length " + std::to_string(len) + " m)");
    }
  }
  return n;
}

Vec3d lattice_max(const LatticeBox& box, double dp) {
  const auto n = lattice_counts(box, dp);
  Vec3d m = box.min;
  for (int a = 0; a < 3; ++a) {
    if (box.dims == 2 && a == 1) continue;
    m[a] += n[a] * dp;
  }
  return m;
}

namespace {
double coord(const LatticeBox& box, int axis, int i, double dp) {
  if (box.dims == 2 && axis == 1) return 0.0;
  return box.min[axis] + (i + 0.5) * dp;
}
}  // namespace

std::vector<Vec3d> fill_box(const LatticeBox& box, double dp) {
  return fill_box_part(box, dp, AxisRange{}).points;
}

LatticePart fill_box_part(const LatticeBox& box, double dp, const AxisRange& range) {
  const auto n = lattice_counts(box, dp);
  LatticePart part;
  part.total = static_cast<std::uint64_t>(n[0]) * n[1] * n[2];
  // The index range along the range's axis, from the coordinates themselves (the same
  // expression fill_box uses, so no point is kept or dropped by round-off differently).
  std::array<int, 3> lo{0, 0, 0}, hi = n;
  const int a = range.axis;
  while (lo[a] < n[a] && !(coord(box, a, lo[a], dp) >= range.lo)) ++lo[a];
  hi[a] = lo[a];
  while (hi[a] < n[a] && coord(box, a, hi[a], dp) < range.hi) ++hi[a];
  const std::size_t kept = static_cast<std::size_t>(std::max(0, hi[0] - lo[0])) *
                           std::max(0, hi[1] - lo[1]) * std::max(0, hi[2] - lo[2]);
  part.points.reserve(kept);
  part.index.reserve(kept);
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        part.points.push_back({coord(box, 0, i, dp), coord(box, 1, j, dp), coord(box, 2, k, dp)});
        part.index.push_back(
            static_cast<std::uint64_t>(i) +
            static_cast<std::uint64_t>(n[0]) *
                (static_cast<std::uint64_t>(j) +
                 static_cast<std::uint64_t>(n[1]) * static_cast<std::uint64_t>(k)));
      }
  return part;
}

std::vector<Vec3d> wall_box_layers(const LatticeBox& box, double dp,
                                   const std::array<bool, 6>& faces, int layers) {
  return wall_box_layers_part(box, dp, faces, layers, AxisRange{}).points;
}

LatticePart wall_box_layers_part(const LatticeBox& box, double dp, const std::array<bool, 6>& faces,
                                 int layers, const AxisRange& range) {
  const auto n = lattice_counts(box, dp);
  // Index range per axis: extend by `layers` on a side only if that face carries a wall.
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    const bool flat = box.dims == 2 && a == 1;
    lo[a] = (!flat && faces[2 * a]) ? -layers : 0;
    hi[a] = (!flat && faces[2 * a + 1]) ? n[a] + layers : n[a];
  }
  LatticePart part;
  std::uint64_t index = 0;
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j) {
      // The row's points outside the box: all of it where j or k is outside, else its ends
      // (the interior rows of a 1e8-particle fill cost two segments, not a point each).
      const bool whole_row = j < 0 || j >= n[1] || k < 0 || k >= n[2];
      const std::array<std::array<int, 2>, 2> segments =
          whole_row ? std::array<std::array<int, 2>, 2>{{{lo[0], hi[0]}, {0, 0}}}
                    : std::array<std::array<int, 2>, 2>{{{lo[0], 0}, {n[0], hi[0]}}};
      for (const auto& [first, last] : segments)
        for (int i = first; i < last; ++i, ++index) {
          const Vec3d x{coord(box, 0, i, dp), coord(box, 1, j, dp), coord(box, 2, k, dp)};
          if (!range.contains(x)) continue;
          part.points.push_back(x);
          part.index.push_back(index);
        }
    }
  part.total = index;
  return part;
}

}  // namespace netsph
