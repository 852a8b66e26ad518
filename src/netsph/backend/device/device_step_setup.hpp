#pragma once
// What the device step (device_stepper.hpp) takes from a case and gives back each step: its
// constants and hooks (DeviceSetup, built by solver/device_setup.cpp) and its report.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "netsph/backend/device/device_types.hpp"
#include "netsph/neighbours/grid_index.hpp"
#include "netsph/sph/contact.hpp"
#include "netsph/sph/damping_zone.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/fluid_point_loads.hpp"
#include "netsph/sph/fluid_sampler.hpp"
#include "netsph/sph/lost_particle.hpp"
#include "netsph/sph/shifting.hpp"
#include "netsph/sph/time_step.hpp"

namespace netsph {

/// How many registers a thread of the rates kernel may use. A multiprocessor has 65536,
/// given out 8 a thread at a time: To80 lets 3 blocks of 256 threads share one (nvcc fits
/// every rates variant in 78-80 registers with at most 12 B of spills; uncapped they take
/// 89-94, room for 2 blocks), To64 4 blocks (44-192 B of spills), None as many as the
/// compiler likes. On an H200 (2026-12-04, docs/PERFORMANCE.md "CUDA") To64 was the fastest:
/// 2.67e8 particle-steps/s at 1e7 particles, against 2.47e8 at To80 and 1.89e8 uncapped (the
/// spills stay in L1; the occupancy they buy hides more of the pair loop's latency).
enum class RatesRegisterCap : std::uint8_t { To80, To64, None };

/// What a device step needs from the case (solver/device_setup.cpp builds it).
struct DeviceSetup {
  FluidModel model;
  GridIndex grid;
  double max_displacement = 0;  ///< CellGrid::max_displacement()
  double cfl = 0.2;
  double dt_max = 0;  ///< 0: none
  double dt_min = 0;  ///< 0: 1e-4 of the first dt
  bool shifting = false;
  ShiftingParams shift_params;
  std::vector<DeviceWall> walls;  ///< by wall index
  /// Velocity of wall w at time t (null: every wall is at rest).
  std::function<Vec3f(std::size_t w, double t)> wall_velocity;
  std::vector<DeviceZone> zones;             ///< open boundaries: inlets, then outlets
  std::vector<DampingZone> damping;          ///< damping zones (sph/damping_zone.hpp)
  std::vector<double> profile_z, profile_u;  ///< the zones' inflow profiles, concatenated
  double gz = 0;                             ///< gravity's z component, m/s^2 (hydrostatic buffers)
  std::vector<DeviceBody> bodies;            ///< by body index, with their initial states
  std::vector<Vec3f> body_offsets, body_ghosts;  ///< body frame, by DeviceBody::offset_base + k
  ContactModel contact;
  /// How many neighbours a thread of the rates pass holds before its warp sums what it has
  /// gathered, 1 to kRatesBatchMax, or 0: each pair summed where it is found
  /// (device_rates_particle; NETSPH_RATES_BATCH, device_setup.cpp).
  std::uint32_t rates_batch = kRatesBatchDefault;
  /// The registers a thread of the rates kernel may use (NETSPH_RATES_MAX_REGISTERS).
  RatesRegisterCap rates_registers = RatesRegisterCap::To64;
  /// The CUDA step compiled with nvcc's --use_fast_math (backend/cuda/device_run_cuda_fast.cu;
  /// NETSPH_CUDA_FAST_MATH=1); no effect on the host executor.
  bool cuda_fast_math = false;
  /// Advances the bodies one stage (body_motion.hpp) from the loads of that stage: `states`
  /// holds the bodies' states on entry and receives the new ones; `sample` samples the fluid
  /// as the stage has it (DeviceStepper::sample_fluid); `water_loads` receives what the
  /// modelled parts put on the water, for the stepper to add to the fluid's accelerations.
  /// `time` is the step's start.
  std::function<void(bool corrector, double time, double dt,
                     const std::vector<DeviceBodyLoads>& loads, std::vector<RigidState>& states,
                     const FluidSampler& sample, std::vector<FluidPointLoad>& water_loads)>
      advance_bodies;
};

/// Why a step stopped early.
enum class DeviceStepStatus { Ok, DtCollapsed, NonFinite };

struct DeviceStepReport {
  DeviceStepStatus status = DeviceStepStatus::Ok;
  TimeStepLimits dt_limits;
  double dt_floor = 0;
  std::size_t lost = 0;                 ///< particles dropped this step for leaving the grid
  std::vector<LostParticle> last_lost;  ///< the last kLostParticlesKept of them, when lost > 0
  std::size_t created = 0;              ///< inlet buffer particles created this step
  std::size_t removed = 0;              ///< buffer particles that left through a face this step
  std::size_t entered_fluid = 0;        ///< buffer particles that became fluid this step
  std::size_t absorbed = 0;             ///< fluid particles that became buffer particles this step
  bool resorted = false;
  double max_speed = 0;  ///< largest fluid speed at the end of the step, m/s
};

}  // namespace netsph
