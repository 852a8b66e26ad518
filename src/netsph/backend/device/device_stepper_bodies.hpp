#pragma once
// The rigid bodies' part of a device step: body particles placed on their bodies, contact and
// fluid loads reduced per body, the bodies advanced on the host, the water loads of the
// host's modelled parts (sinker bars) added to the fluid.
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
double DeviceStepper<Exec>::place_bodies(bool from_start) {
  if (!has_bodies_) return 0;
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Bodies);
  const DeviceState st = state();
  const DeviceBody* bodies = bodies_.data();
  const Vec3f* offsets = offsets_.data();
  const Vec3f* ghosts = body_ghosts_.data();
  const int dims = s_.model.dims;
  const Vec3d period = s_.grid.period;
  Real* moved = scalars();
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    moved[i] = static_cast<Real>(
        device_place_body_particle(st, bodies, offsets, ghosts, dims, period, from_start, i));
  });
  return from_start ? std::sqrt(static_cast<double>(Exec::max_of(moved, n_))) : 0.0;
}

template <class Exec>
void DeviceStepper<Exec>::contacts() {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Bodies);
  double* loads = reinterpret_cast<double*>(loads_.data());
  Exec::for_each(s_.bodies.size() * 12, [=] NETSPH_LAMBDA(std::uint32_t k) { loads[k] = 0; });
  const GridIndex g = s_.grid;
  const std::uint32_t* begin = cell_begin_.data();
  const std::uint32_t* keys = keys_.data();
  const DeviceState st = state();
  const DeviceBody* bodies = bodies_.data();
  const DeviceView v = step_arrays().view;
  const ContactModel c = s_.contact;
  const double mass = s_.model.mass;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t a) {
    const Vec3f acc = device_contact_particle(g, begin, keys, st.kind, st.group, v, c, a);
    if (acc.x == 0 && acc.y == 0 && acc.z == 0) return;
    const std::uint32_t b = st.group[a];
    double load[6];
    device_particle_load(rigid_lever_arm(bodies[b].state, st.pos[a], g.period), acc, mass, load);
    for (int k = 0; k < 6; ++k) {
      if (load[k] != 0) Exec::atomic_add(loads + 12 * b + 6 + k, load[k]);
    }
  });
}

template <class Exec>
void DeviceStepper<Exec>::advance_bodies(bool corrector, double dt) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::Bodies);
  const std::size_t nb = s_.bodies.size();
  double* loads = reinterpret_cast<double*>(loads_.data());
  const DeviceState st = state();
  const DeviceBody* bodies = bodies_.data();
  const Vec3f* acc = step_arrays().rates.acc;
  const double mass = s_.model.mass;
  const Vec3d period = s_.grid.period;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (st.kind[i] != ParticleKind::Body) return;
    const std::uint32_t b = st.group[i];
    double load[6];
    device_particle_load(rigid_lever_arm(bodies[b].state, st.pos[i], period), acc[i], mass, load);
    for (int k = 0; k < 6; ++k) {
      if (load[k] != 0) Exec::atomic_add(loads + 12 * b + k, load[k]);
    }
  });
  Exec::download(loads_host_.data(), loads_, nb);
  s_.advance_bodies(
      corrector, time_, dt, loads_host_, states_,
      [this](std::span<const Vec3d> points, std::span<ShepardValue> values) {
        sample_fluid(points, values);
      },
      water_loads_host_);
  for (std::size_t b = 0; b < nb; ++b) s_.bodies[b].state = states_[b];
  Exec::upload(bodies_, s_.bodies.data(), nb);
  if (s_.model.kernel_type == KernelType::Wendland) {
    add_water_loads<WendlandC2>();
  } else {
    add_water_loads<CubicSpline>();
  }
}

template <class Exec>
template <class K>
void DeviceStepper<Exec>::add_water_loads() {
  const std::size_t nl = water_loads_host_.size();
  if (nl == 0) return;
  Exec::upload(water_loads_, water_loads_host_.data(), nl);
  FluidPointLoadSet set =
      point_load_set(water_loads_host_.data(), static_cast<std::uint32_t>(nl), s_.model.support);
  set.loads = water_loads_.data();
  const DeviceState st = state();
  Vec3f* acc = step_arrays().rates.acc;
  const FluidModel m = s_.model;
  const Vec3d period = s_.grid.period;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (st.kind[i] != ParticleKind::Fluid) return;
    acc[i] += point_loads_acceleration<K>(set, m.kernel, m.support2, period, st.pos[i]);
  });
}

}  // namespace netsph
