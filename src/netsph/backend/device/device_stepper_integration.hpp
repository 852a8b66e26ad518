#pragma once
// The time integration of a device step: wall kinematics, the step start, the symplectic
// predictor and corrector, and the reductions dt and the report need.
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
void DeviceStepper<Exec>::wall_motion(double dt) {
  if (!s_.wall_velocity) return;
  for (std::size_t w = 0; w < motion_host_.size(); ++w) {
    WallKinematics& k = motion_host_[w];  // shows_own_velocity is the wall's, set once
    k.start = s_.wall_velocity(w, time_);
    k.half = s_.wall_velocity(w, time_ + 0.5 * dt);
    k.end = s_.wall_velocity(w, time_ + dt);
  }
  Exec::upload(motion_, motion_host_.data(), motion_host_.size());
}

template <class Exec>
void DeviceStepper<Exec>::save_start() {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::TimeStep);
  const DeviceState st = state();
  const DeviceStart ss = start();
  Exec::for_each(
      n_, [=] NETSPH_LAMBDA(std::uint32_t i) { ss.vel[i] = st.vel[i], ss.rho[i] = st.rho[i]; });
}

template <class Exec>
double DeviceStepper<Exec>::max_fluid_acceleration() {
  const ParticleKind* kind = kind_.data();
  const Vec3f* acc = step_arrays().rates.acc;
  Real* acc2 = scalars();
  Exec::for_each(n_,
                 [=] NETSPH_LAMBDA(std::uint32_t i) { acc2[i] = device_fluid_acc2(kind, acc, i); });
  return std::sqrt(static_cast<double>(Exec::max_of(acc2, n_)));
}

template <class Exec>
double DeviceStepper<Exec>::predict(double dt) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Integration);
  const DeviceState st = state();
  const DeviceRates r = step_arrays().rates;
  const WallKinematics* motion = motion_.data();
  const FluidModel m = s_.model;
  Real* moved = scalars();
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    moved[i] = static_cast<Real>(device_predict_particle(st, r, motion, m, dt, i));
  });
  return std::sqrt(static_cast<double>(Exec::max_of(moved, n_)));
}

template <class Exec>
double DeviceStepper<Exec>::max_fluid_speed() {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::TimeStep);
  const DeviceState st = state();
  Real* speed2 = scalars();
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    const Vec3f v = st.vel[i];
    speed2[i] = st.kind[i] == ParticleKind::Fluid ? v.x * v.x + v.y * v.y + v.z * v.z : Real(0);
  });
  return std::sqrt(static_cast<double>(Exec::max_of(speed2, n_)));
}

template <class Exec>
bool DeviceStepper<Exec>::correct(double dt) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Integration);
  const DeviceState st = state();
  const DeviceStart ss = start();
  const DeviceRates r = step_arrays().rates;
  const WallKinematics* motion = motion_.data();
  const FluidModel m = s_.model;
  const bool shift = s_.shifting;
  const ShiftingParams sp = s_.shift_params;
  Real* bad = scalars();  // 1 where the state is not finite
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    bad[i] = device_correct_particle(st, ss, r, motion, m, shift, sp, dt, i) ? Real(0) : Real(1);
  });
  return !(Exec::max_of(bad, n_) > 0);
}

template <class Exec>
void DeviceStepper<Exec>::damp(double dt) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Integration);
  const DeviceState st = state();
  const DampingZone* zones = damping_.data();
  const auto count = static_cast<std::uint32_t>(s_.damping.size());
  const double t = time_ + dt;  // the step's end: the velocities are the corrected ones
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (st.kind[i] != ParticleKind::Fluid) return;
    for (std::uint32_t z = 0; z < count; ++z) damp_velocity(zones[z], st.pos[i], t, dt, st.vel[i]);
  });
}

}  // namespace netsph
