#include "netsph/distributed/scene_parts.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace netsph {
namespace {

/// The fills' volume (area in 2D) below coordinate x along `axis`, overlaps counted twice:
/// an estimate of the fluid particles there, good enough for a first split.
double fill_measure_below(const CaseSpec& spec, int axis, double x) {
  const int dims = spec.simulation.dimensions;
  double v = 0;
  for (const FillSpec& f : spec.fills) {
    double section = 1;
    for (int a = 0; a < 3; ++a) {
      if (a == axis || (dims == 2 && a == 1)) continue;
      section *= std::max(0.0, f.box.max[a] - f.box.min[a]);
    }
    v += section * std::clamp(x - f.box.min[axis], 0.0, f.box.max[axis] - f.box.min[axis]);
  }
  return v;
}

}  // namespace

AxisRange set_up_region(const CaseSpec& spec, int ranks, int rank) {
  const double inf = std::numeric_limits<double>::infinity();
  // The extent of the case's boxes (and bodies' centres): the particles spread about as far.
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  const auto extend = [&](const Vec3d& a, const Vec3d& b) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], a[k]), hi[k] = std::max(hi[k], b[k]);
  };
  for (const FillSpec& f : spec.fills) extend(f.box.min, f.box.max);
  for (const WallSpec& w : spec.walls) extend(w.box.min, w.box.max);
  for (const BodySpec& b : spec.bodies) extend(b.center, b.center);
  AxisRange r;
  if (ranks <= 1 || !(lo.x <= hi.x)) return r;
  const int dims = spec.simulation.dimensions;
  for (int a = 0; a < 3; ++a) {
    if (dims == 2 && a == 1) continue;
    if (hi[a] - lo[a] > hi[r.axis] - lo[r.axis]) r.axis = a;
  }
  const int axis = r.axis;
  const double total = fill_measure_below(spec, axis, hi[axis]);
  const auto cut = [&](int k) {
    if (k <= 0) return -inf;
    if (k >= ranks) return inf;
    if (!(total > 0)) return lo[axis] + (hi[axis] - lo[axis]) * k / ranks;
    // Bisection on the (monotone) measure below.
    double a = lo[axis], b = hi[axis];
    const double target = total * k / ranks;
    for (int it = 0; it < 100; ++it) {
      const double m = 0.5 * (a + b);
      (fill_measure_below(spec, axis, m) < target ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  r.lo = cut(rank);
  r.hi = cut(rank + 1);
  return r;
}

}  // namespace netsph
