#pragma once
// Nearest periodic images, for what is not sorted into the periodic cells: a rigid body's
// centre of mass follows its motion without being wrapped, while its particles are wrapped
// into the period with the fluid, so a particle and its body's centre may lie a whole number
// of periods apart.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

/// The whole number of periods to take from offset d along one axis to bring it to its image
/// nearest zero (period 0: not periodic, no shift).
NETSPH_HD double nearest_image_correction(double d, double period) {
  return period > 0 ? period * std::floor(d / period + 0.5) : 0.0;
}

/// The same along each axis (period 0 on the axes that are not periodic).
NETSPH_HD Vec3d nearest_image_correction(const Vec3d& d, const Vec3d& period) {
  return {nearest_image_correction(d.x, period.x), nearest_image_correction(d.y, period.y),
          nearest_image_correction(d.z, period.z)};
}

/// Coordinate x moved by whole periods into [lo, lo + period) (period > 0); bit for bit x when
/// it is inside already.
NETSPH_HD double wrapped_into_period(double x, double lo, double period) {
  x -= period * std::floor((x - lo) / period);
  return x >= lo + period ? lo : x;  // round-off just below the period's start
}

/// Offset d moved to its nearest image, |d| <= period / 2 along each periodic axis; bit for bit
/// d when it is already nearest (d - 0).
NETSPH_HD Vec3d nearest_image_offset(const Vec3d& d, const Vec3d& period) {
  return d - nearest_image_correction(d, period);
}

}  // namespace netsph
