#pragma once
// What the outputs and the nets read from the device: the fluid sampled at points (Shepard
// sums) and the series rows' measures (a reduction).
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
void DeviceStepper<Exec>::sample_fluid(std::span<const Vec3d> points,
                                       std::span<ShepardValue> values) {
  const std::size_t n = points.size();
  if (n == 0) return;
  Exec::upload(sample_points_, points.data(), n);
  Exec::resize_discarding(sample_sums_, n);
  if (s_.model.kernel_type == KernelType::Wendland) {
    sample_for<WendlandC2>(n);
  } else {
    sample_for<CubicSpline>(n);
  }
  sample_sums_host_.resize(n);
  Exec::download(sample_sums_host_.data(), sample_sums_, n);
  for (std::size_t k = 0; k < n; ++k) values[k] = shepard_value(sample_sums_host_[k]);
}

template <class Exec>
ParticleTally DeviceStepper<Exec>::tally() {
  const DeviceState st = state();
  const double mass = s_.model.mass;
  return Exec::reduce(
      n_, ParticleTally{},
      [=] NETSPH_LAMBDA(std::uint32_t i) {
        return tally_particle(st.kind[i], st.vel[i], st.rho[i], mass);
      },
      MergeTallies{});
}

template <class Exec>
template <class K>
void DeviceStepper<Exec>::sample_for(std::size_t n) {
  const GridIndex g = s_.grid;
  const std::uint32_t* begin = cell_begin_.data();
  const DeviceState st = state();
  const FluidModel m = s_.model;
  const Vec3d* points = sample_points_.data();
  ShepardSums* sums = sample_sums_.data();
  Exec::for_each(n, [=] NETSPH_LAMBDA(std::uint32_t i) {
    sums[i] = device_point_sums<K>(g, begin, st, m, points[i]);
  });
}

}  // namespace netsph
