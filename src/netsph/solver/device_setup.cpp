#include "netsph/solver/device_setup.hpp"

#include <cstdlib>
#include <string>

#include "netsph/core/error.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/solver/step_settings.hpp"

namespace netsph {

namespace {

/// A whole number from the environment variable `name`, `fallback` if unset; an error naming
/// the variable and what it may be (`allowed`, in words) unless `valid` accepts it.
template <class Valid>
long whole_number_from_environment(const char* name, long fallback, Valid valid,
                                   const std::string& allowed) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (*end != '\0' || !valid(v)) {
    throw Error("environment",
                std::string(name) + " is '" + text + "': it must be a whole number " + allowed);
  }
  return v;
}

/// NETSPH_RATES_BATCH: how many neighbours a thread of a device rates pass holds before its warp
/// sums them (device_rates_particle; 0: each pair summed where it is found);
/// NETSPH_RATES_MAX_REGISTERS: 64 (the default), 80 or 0 (none) caps the rates kernel's
/// registers (DeviceSetup::rates_registers); NETSPH_CUDA_FAST_MATH: 1 runs the CUDA step compiled
/// with --use_fast_math (DeviceSetup::cuda_fast_math). Knobs for measuring the GPU, not physical
/// settings: the results are the same for every value (fast math: to float round-off).
void rates_kernel_from_environment(DeviceSetup& s) {
  s.rates_batch = static_cast<std::uint32_t>(whole_number_from_environment(
      "NETSPH_RATES_BATCH", kRatesBatchDefault,
      [](long v) { return v >= 0 && v <= static_cast<long>(kRatesBatchMax); },
      "from 0 (no batches) to " + std::to_string(kRatesBatchMax)));
  const long registers = whole_number_from_environment(
      "NETSPH_RATES_MAX_REGISTERS", 64, [](long v) { return v == 0 || v == 64 || v == 80; },
      "0 (no cap), 64 or 80");
  s.rates_registers = registers == 80   ? RatesRegisterCap::To80
                      : registers == 64 ? RatesRegisterCap::To64
                                        : RatesRegisterCap::None;
  // The trimmed scan this chose is gone (GridIndex, 2026-12-04): say so rather than run the
  // whole scan under a setting that asks for another.
  if (const char* trim = std::getenv("NETSPH_RATES_TRIM"); trim != nullptr && *trim != '\0') {
    throw Error("environment", std::string("NETSPH_RATES_TRIM is '") + trim +
                                   "': the trimmed rates scan was removed (slower on an H200, "
                                   "and it kept registers live through every scan); unset it");
  }
  s.cuda_fast_math =
      whole_number_from_environment(
          "NETSPH_CUDA_FAST_MATH", 0, [](long v) { return v == 0 || v == 1; },
          "0 (IEEE float division and square root) or 1 (nvcc's --use_fast_math)") == 1;
}

}  // namespace

DeviceSetup device_setup(const CaseSpec& spec, const Scene& scene) {
  DeviceSetup s;
  s.model = scene.model;
  CellGrid grid;
  grid.configure(scene.domain_min, scene.domain_max, s.model.support, kGridSkin, s.model.dims,
                 spec.domain.periodic);
  s.max_displacement = grid.max_displacement();
  s.grid = grid.index();
  s.cfl = spec.simulation.cfl;
  s.dt_max = spec.simulation.dt_max;
  s.dt_min = spec.simulation.dt_min;
  s.shifting = spec.fluid.shifting == ShiftingModel::Fickian;
  s.shift_params = shifting_params(spec, s.model);
  for (const WallSpec& w : spec.walls) {
    DeviceWall d;
    d.mdbc = w.model == WallModel::Mdbc;
    d.slip = w.slip;
    d.shows_own_velocity = w.model == WallModel::Dbc || w.slip == WallSlip::WallVelocity;
    s.walls.push_back(d);
  }
  for (const OpenBoundaryZone& z : scene.zones) {
    DeviceZone d;
    d.geo = z.geometry();
    d.velocity_imposed = z.velocity_imposed;
    d.speed = z.speed;
    d.profile_begin = static_cast<std::uint32_t>(s.profile_z.size());
    d.profile_count = static_cast<std::uint32_t>(z.profile_z.size());
    d.density = z.density;
    s.zones.push_back(d);
    s.profile_z.insert(s.profile_z.end(), z.profile_z.begin(), z.profile_z.end());
    s.profile_u.insert(s.profile_u.end(), z.profile_u.begin(), z.profile_u.end());
  }
  s.gz = spec.fluid.gravity.z;
  s.damping = scene.damping;
  for (const RigidBody& b : scene.bodies) {
    DeviceBody d;
    d.state = b.state;
    d.first_id = b.first_id;
    d.offset_base = static_cast<std::uint32_t>(s.body_offsets.size());
    d.mdbc = b.model == WallModel::Mdbc;
    d.slip = b.slip;
    d.shows_own_velocity = b.shows_own_velocity();
    s.bodies.push_back(d);
    s.body_offsets.insert(s.body_offsets.end(), b.offsets.begin(), b.offsets.end());
    s.body_ghosts.insert(s.body_ghosts.end(), b.ghosts.begin(), b.ghosts.end());
  }
  s.contact = ContactModel::make(spec.simulation.dp, scene.sound_speed);
  rates_kernel_from_environment(s);
  return s;
}

}  // namespace netsph
