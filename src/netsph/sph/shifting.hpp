#pragma once
// Particle shifting, the Fickian form of Lind et al. (2012) with the diffusion coefficient of
// Skillen et al. (2013), D = A h |v| dt, as DualSPHysics applies it (Crespo et al. 2015):
//
//   dr = -A h |v| dt grad(C),   grad(C)_a = sum_b V_b grad_a W_ab
//
// moves particles from crowded to sparse regions so that the distribution stays regular in
// wakes and shear flows. At a free surface grad(C) points into the fluid and would pull the
// surface particles outwards, so shifting is switched off where the position divergence
// div(r)_a = -sum_b V_b r_ab . grad_a W_ab (= dims inside the fluid) falls below a threshold
// and ramps up linearly to full strength at div(r) = dims (DualSPHysics' free-surface
// correction). Thresholds: 2.75 in 3D as DualSPHysics recommends; 1.85 in 2D instead of its
// 1.5, because at 1.5 the layers just below the surface of an open channel are shifted
// upwards near the inlet and the channel loses 6.5% of its water (docs/VALIDATION.md); at
// 1.85 the loss is 0.5%. Each component is capped at 0.1 dp.
// Applied to the corrector's positions only, as DualSPHysics recommends.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct ShiftingParams {
  Real coefficient = 2;    ///< A (> 0)
  Real h = 0;              ///< smoothing length, m
  Real threshold = 0;      ///< div(r) below which nothing is shifted
  Real dims = 3;           ///< div(r) inside the fluid
  Real max_component = 0;  ///< 0.1 dp, m
};

/// Default free-surface threshold on div(r) for a dimension.
inline double default_shifting_threshold(int dims) {
  return dims == 2 ? 1.85 : 2.75;
}

NETSPH_HD Vec3f shifting_displacement(const ShiftingParams& s, const Vec3f& grad_c, Real div_r,
                                      Real speed, Real dt) {
  if (!(div_r > s.threshold)) return {};
  Real ramp = (div_r - s.threshold) / (s.dims - s.threshold);
  ramp = ramp < Real(1) ? ramp : Real(1);
  Vec3f d = grad_c * (-s.coefficient * s.h * speed * dt * ramp);
  // In 2D, y is a degenerate direction: shifting along it would push particles out of the
  // plane and amplify round-off (the concentration "gradient" across the plane points at
  // the plane), so it is removed.
  if (s.dims == Real(2)) d.y = 0;
  auto cap = [&](Real x) {
    return x > s.max_component ? s.max_component : (x < -s.max_component ? -s.max_component : x);
  };
  return {cap(d.x), cap(d.y), cap(d.z)};
}

/// Shifts a fluid particle after the corrector: its new velocity v sets the displacement's
/// scale. Both backends' correctors call this.
NETSPH_HD void shift_position(const ShiftingParams& s, const Vec3f& grad_c, Real div_r,
                              const Vec3f& v, double dt, Vec3d& r) {
  r += Vec3d(shifting_displacement(s, grad_c, div_r, norm(v), static_cast<Real>(dt)));
}

}  // namespace netsph
