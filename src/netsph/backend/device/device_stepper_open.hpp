#pragma once
// The open boundaries on the device: buffer transitions, the inlets' new particles (a scan of
// flags), and the buffer particles' imposed or extrapolated state.
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
void DeviceStepper<Exec>::open_boundaries(DeviceStepReport& rep) {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::OpenBoundaries);
  const DeviceState st = state();
  const ZoneGeometry* geo = zone_geo_.data();
  const std::size_t nz = s_.zones.size();
  WorkCarver carve(work_.data(), n_);
  const OpenArrays oa = open_layout(carve);
  std::uint32_t* create = oa.create;
  std::uint32_t* event = oa.event;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    device_transition_particle(st, geo, nz, create, event, i);
  });
  // create_at is free until the creations' scan below.
  rep.removed = count_events(event, kRemovedEvent, oa.flag, oa.create_at);
  rep.entered_fluid = count_events(event, kEnteredEvent, oa.flag, oa.create_at);
  rep.absorbed = count_events(event, kAbsorbedEvent, oa.flag, oa.create_at);
  const std::size_t created = Exec::exclusive_scan(oa.create, oa.create_at, n_);
  rep.created = created;
  if (created == 0) return;
  const std::size_t n = n_;
  alloc_state(n + created);  // the work area, which holds the flags, grows after
  const DeviceState grown = state();
  const std::uint32_t* flag = oa.create;
  const std::uint32_t* offset = oa.create_at;
  const std::uint32_t first_id = next_id_;
  const auto base = static_cast<std::uint32_t>(n);
  Exec::for_each(n, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (flag[i])
      device_create_buffer_particle(grown, geo, i, base + offset[i], first_id + offset[i]);
  });
  n_ = n + created;
  next_id_ += static_cast<std::uint32_t>(created);
  alloc_work(n_);
}

template <class Exec>
std::size_t DeviceStepper<Exec>::count_events(const std::uint32_t* event, std::uint32_t kind,
                                              std::uint32_t* flag, std::uint32_t* scan) {
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) { flag[i] = event[i] == kind ? 1 : 0; });
  return Exec::exclusive_scan(flag, scan, n_);
}

template <class Exec>
void DeviceStepper<Exec>::buffer_state() {
  const PhaseTimer<Exec> timer(profile(), DevicePhase::BoundaryState);
  if (s_.model.kernel_type == KernelType::Wendland) return buffer_state_for<WendlandC2>();
  buffer_state_for<CubicSpline>();
}

template <class Exec>
template <class K>
void DeviceStepper<Exec>::buffer_state_for() {
  const GridIndex g = s_.grid;
  const std::uint32_t* begin = cell_begin_.data();
  const DeviceState st = state();
  const DeviceZone* zones = zones_.data();
  const double* pz = profile_z_.data();
  const double* pu = profile_u_.data();
  const double gz = s_.gz;
  const FluidModel m = s_.model;
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    device_buffer_state_particle<K>(g, begin, st, zones, pz, pu, gz, m, i);
  });
}

}  // namespace netsph
