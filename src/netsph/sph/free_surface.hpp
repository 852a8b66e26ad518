#pragma once
// The free surface's height on a vertical line from the fluid's kernel coverage (sum V W,
// sph/shepard.hpp) sampled up it: where the coverage falls through one half, the middle of the
// kernel-smoothed step from water (about 1) to air (0). Wave gauges (run/wave_gauges.hpp) and
// a paddle's active absorption (solver/paddle_absorption.cpp) read the surface this way.
#include <cmath>
#include <limits>
#include <vector>

namespace netsph {

/// The coverage at which a gauge puts the surface.
inline constexpr double kGaugeSurfaceCoverage = 0.5;

/// The surface's height from the coverage sampled at `z` (increasing, equally spaced): the
/// highest crossing of kGaugeSurfaceCoverage; NaN when no sample reaches it. A top sample at or
/// above it gives the top (the water reaches the line's end).
inline double surface_from_coverage(const std::vector<double>& z,
                                    const std::vector<double>& coverage) {
  for (std::size_t k = coverage.size(); k-- > 0;) {
    if (!(coverage[k] >= kGaugeSurfaceCoverage)) continue;
    if (k + 1 == coverage.size()) return z[k];
    const double c0 = coverage[k], c1 = coverage[k + 1];
    return z[k] + (c0 - kGaugeSurfaceCoverage) / (c0 - c1) * (z[k + 1] - z[k]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace netsph
