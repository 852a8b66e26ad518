#include "netsph/case/case_spec.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace netsph {

std::string SourceLocation::str() const {
  // Line 0 means "no position": a --set option or a programmatically built case.
  if (line == 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

}  // namespace netsph

namespace netsph {

Vec3d VelocityHistory::at(double t) const {
  if (velocities.empty()) return {};
  if (t <= times.front()) return velocities.front();
  // A wavemaker's history holds a hundred points per period: a binary search.
  const auto after = std::lower_bound(times.begin(), times.end(), t);
  if (after == times.end()) return velocities.back();
  const auto k = static_cast<std::size_t>(after - times.begin());
  const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
  return velocities[k - 1] * (1 - w) + velocities[k] * w;
}

double WaveSpec::reference_wavelength() const {
  const RegularWave* tallest = tallest_component(train);
  return tallest ? 2 * M_PI / tallest->k : 0.0;
}

}  // namespace netsph

namespace netsph {

namespace {
/// Points evenly spread over [lo, hi]: round(|hi - lo| / spacing) + 1 of them.
int grid_count(double lo, double hi, double spacing) {
  return static_cast<int>(std::lround(std::fabs(hi - lo) / spacing)) + 1;
}
}  // namespace

std::vector<Vec3d> ProbeSpec::sample_points() const {
  std::vector<Vec3d> out;
  switch (type) {
    case ProbeType::Point:
      out.push_back(a);
      break;
    case ProbeType::Line:
      for (int k = 0; k < points; ++k)
        out.push_back(a + (b - a) * (static_cast<double>(k) / (points - 1)));
      break;
    case ProbeType::Plane: {
      // The two in-plane axes, in x, y, z order; the flat one is the normal.
      int axes[2], n = 0;
      for (int axis = 0; axis < 3 && n < 2; ++axis)
        if (a[axis] != b[axis]) axes[n++] = axis;
      const int nu = grid_count(a[axes[0]], b[axes[0]], spacing);
      const int nv = grid_count(a[axes[1]], b[axes[1]], spacing);
      for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
          Vec3d x = a;
          x[axes[0]] +=
              (b[axes[0]] - a[axes[0]]) * (nu > 1 ? static_cast<double>(i) / (nu - 1) : 0);
          x[axes[1]] +=
              (b[axes[1]] - a[axes[1]]) * (nv > 1 ? static_cast<double>(j) / (nv - 1) : 0);
          out.push_back(x);
        }
      }
      break;
    }
  }
  return out;
}

}  // namespace netsph
