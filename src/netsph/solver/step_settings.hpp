#pragma once
// Settings of the time step that the CPU solver (simulation.cpp) and the device-shaped step
// (device_setup.cpp) derive the same way from a case.
#include "netsph/case/case_spec.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/shifting.hpp"

namespace netsph {

/// Relative skin of the neighbour grid. 5% costs 16% more candidates in 3D but lets one sort
/// serve both stages: the half-step displacement is at most CFL h v/(2 c0) ~ 0.01 h, so
/// re-sorts are rare.
inline constexpr double kGridSkin = 0.05;

/// The shifting parameters of a case (sph/shifting.hpp).
inline ShiftingParams shifting_params(const CaseSpec& spec, const FluidModel& m) {
  ShiftingParams s;
  s.coefficient = static_cast<Real>(spec.fluid.shifting_coefficient);
  s.h = m.kernel.h;
  s.threshold = static_cast<Real>(spec.fluid.shifting_surface_threshold > 0
                                      ? spec.fluid.shifting_surface_threshold
                                      : default_shifting_threshold(m.dims));
  s.dims = static_cast<Real>(m.dims);
  s.max_component = static_cast<Real>(0.1 * spec.simulation.dp);
  return s;
}

}  // namespace netsph
