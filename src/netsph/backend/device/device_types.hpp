#pragma once
// The plain data the device step takes from the host (DeviceSetup, device_step_setup.hpp):
// walls, bodies and open-boundary zones as the kernels read them, and the rates pass's batch
// limits. Kept apart from the kernels (device_kernels.hpp) so that host code that sets up or
// drives a device run (device_run.hpp) does not parse the pair loop.
#include <cstdint>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/boundary/open_boundary.hpp"
#include "netsph/core/physics_options.hpp"

namespace netsph {

/// Per-wall constants a kernel needs.
struct DeviceWall {
  bool mdbc = false;
  WallSlip slip = WallSlip::WallVelocity;
  /// DBC, or mDBC showing the wall's own velocity: the fluid sees it in both equations.
  bool shows_own_velocity = true;
};

/// A rigid body as its particles need it: the state of the current stage, where its particles'
/// body-frame offsets and ghost vectors start in the concatenated tables, and its boundary
/// condition.
struct DeviceBody {
  RigidState state;
  std::uint32_t first_id = 0;     ///< id of its first particle (ids are consecutive)
  std::uint32_t offset_base = 0;  ///< index of that particle in the offset and ghost tables
  bool mdbc = false;
  WallSlip slip = WallSlip::WallVelocity;
  bool shows_own_velocity = true;
};

/// An open boundary's buffer state rules (Simulation::apply_open_boundary_state); the
/// profile, if any, is [profile_begin, profile_begin + profile_count) of the profile tables.
struct DeviceZone {
  ZoneGeometry geo;
  bool velocity_imposed = true;
  double speed = 0;
  std::uint32_t profile_begin = 0, profile_count = 0;
  BufferDensity density = BufferDensity::Extrapolated;
};

/// Fluid and contact force and torque on one body, summed over its particles (world frame,
/// torque about the centre of mass), as Simulation::reduce_body_forces.
struct DeviceBodyLoads {
  double f[12];  ///< fluid force, fluid torque, contact force, contact torque
};

/// The most neighbours a rates pass gathers before summing them (device_rates_particle).
inline constexpr std::uint32_t kRatesBatchMax = 32;
/// The batch a rates pass sums at unless NETSPH_RATES_BATCH says otherwise: the fastest on an
/// H200 at 1e7 particles (untrimmed, 64 registers; docs/PERFORMANCE.md "CUDA"): 2.67e8
/// particle-steps/s at 12, 2.64e8 at 8, 2.63e8 at 4 and 6, 2.47e8 at 16, 2.34e8 at 0. Larger
/// batches overflow the 32 inside a row, where each thread sums alone (1.33e8 at 24).
inline constexpr std::uint32_t kRatesBatchDefault = 12;

}  // namespace netsph
