#pragma once
// The interaction of a device step: the mDBC state of walls and bodies, the view of the
// particles the pair loop reads, and the rates pass (kernel, viscosity, diffusion and shifting
// dispatched to compile-time variants).
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
void DeviceStepper<Exec>::mdbc() {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::BoundaryState);
  if (s_.model.kernel_type == KernelType::Wendland) return mdbc_for<WendlandC2>();
  mdbc_for<CubicSpline>();
}

template <class Exec>
template <class K>
void DeviceStepper<Exec>::mdbc_for() {
  const GridIndex g = s_.grid;
  const std::uint32_t* begin = cell_begin_.data();
  const DeviceState st = state();
  const DeviceWall* walls = walls_.data();
  const WallKinematics* motion = motion_.data();
  const DeviceBody* bodies = bodies_.data();
  const DeviceGhosts gh = ghosts();
  const FluidModel m = s_.model;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    device_mdbc_particle<K>(g, begin, st, walls, motion, bodies, gh, m, i);
  });
}

template <class Exec>
void DeviceStepper<Exec>::view(bool half_step) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::View);
  const DeviceState st = state();
  const DeviceView v = step_arrays().view;
  const FluidModel m = s_.model;
  const DeviceWall* walls = walls_.data();
  const WallKinematics* motion = motion_.data();
  const DeviceBody* bodies = bodies_.data();
  const Vec3d origin = s_.grid.origin, period = s_.grid.period;
  const bool mirrors = mirrors_;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    device_view_particle(st, v, m, walls, motion, bodies, origin, period, i, mirrors, half_step);
  });
}

template <class Exec>
void DeviceStepper<Exec>::rates(bool shift) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Rates);
  if (s_.model.kernel_type == KernelType::Wendland) return rates_kernel<WendlandC2>(shift);
  rates_kernel<CubicSpline>(shift);
}

template <class Exec>
template <class K>
void DeviceStepper<Exec>::rates_kernel(bool shift) {
  if (s_.model.viscosity == ViscosityModel::Laminar)
    return rates_for<K, ViscosityModel::Laminar>(shift);
  rates_for<K, ViscosityModel::Artificial>(shift);
}

template <class Exec>
template <class K, ViscosityModel Visc>
void DeviceStepper<Exec>::rates_for(bool shift) {
  switch (s_.model.diffusion) {
    case DensityDiffusion::None:
      return shift ? rates_launch<K, Visc, DensityDiffusion::None, true>()
                   : rates_launch<K, Visc, DensityDiffusion::None, false>();
    case DensityDiffusion::Molteni:
      return shift ? rates_launch<K, Visc, DensityDiffusion::Molteni, true>()
                   : rates_launch<K, Visc, DensityDiffusion::Molteni, false>();
    case DensityDiffusion::Fourtakas:
      return shift ? rates_launch<K, Visc, DensityDiffusion::Fourtakas, true>()
                   : rates_launch<K, Visc, DensityDiffusion::Fourtakas, false>();
  }
}

template <class Exec>
template <class K, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
void DeviceStepper<Exec>::rates_launch() {
  const GridIndex g = s_.grid;
  const std::uint32_t* begin = cell_begin_.data();
  const std::uint32_t* keys = keys_.data();
  const ParticleKind* kind = kind_.data();
  const StepArrays arrays = step_arrays();
  const DeviceView v = arrays.view;
  const FluidModel m = s_.model;
  const DeviceRates out = arrays.rates;
  // The kernel's batch array holds kRatesBatchMax: never more, whoever built the setup.
  const std::uint32_t batch = std::min(s_.rates_batch, kRatesBatchMax);
  const auto f = [=] NETSPH_LAMBDA(std::uint32_t a) {
    device_rates_particle<K, Visc, Diff, Shift>(g, begin, keys, kind, v, m, out, a, batch);
  };
  switch (s_.rates_registers) {
    case RatesRegisterCap::To80:
      return Exec::template for_each_occupying<3>(n_, f);
    case RatesRegisterCap::To64:
      return Exec::template for_each_occupying<4>(n_, f);
    case RatesRegisterCap::None:
      return Exec::for_each(n_, f);
  }
}

}  // namespace netsph
