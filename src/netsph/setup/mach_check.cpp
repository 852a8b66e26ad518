#include "netsph/setup/mach_check.hpp"

#include <cmath>

#include <fmt/format.h>

namespace netsph {

ExpectedFlow expected_flow_speed(const CaseSpec& spec, double depth) {
  ExpectedFlow e;
  const auto consider = [&e](double speed, std::string source) {
    if (speed > e.speed) e.speed = speed, e.source = std::move(source);
  };
  for (std::size_t i = 0; i < spec.fills.size(); ++i)
    consider(norm(spec.fills[i].velocity), fmt::format("the velocity of fill[{}]", i + 1));
  for (const WallSpec& w : spec.walls) {
    for (const Vec3d& v : w.motion.velocities)
      consider(norm(v), fmt::format("the velocity of wall '{}'", w.name));
  }
  for (const OpenBoundarySpec& in : spec.inlets) {
    if (in.velocity)
      consider(std::fabs(*in.velocity), fmt::format("the velocity of inlet '{}'", in.name));
    for (const double u : in.profile_u)
      consider(std::fabs(u), fmt::format("the profile of inlet '{}'", in.name));
  }
  for (const OpenBoundarySpec& out : spec.outlets) {
    if (out.velocity)
      consider(std::fabs(*out.velocity), fmt::format("the velocity of outlet '{}'", out.name));
  }
  for (const BodySpec& b : spec.bodies) {
    for (const Vec3d& v : b.velocity.velocities)
      consider(norm(v), fmt::format("the velocity of body '{}'", b.name));
    consider(norm(b.initial_velocity), fmt::format("the initial velocity of body '{}'", b.name));
  }
  const double g = norm(spec.fluid.gravity);
  consider(std::sqrt(2 * g * depth),
           fmt::format("free fall over the deepest fill, sqrt(2 g H) with H = {:.3g} m", depth));
  return e;
}

std::optional<std::string> sound_speed_warning(const CaseSpec& spec, double depth, double c0) {
  const ExpectedFlow e = expected_flow_speed(spec, depth);
  if (!(e.speed > 0) || c0 >= kMinSoundSpeedRatio * e.speed) return std::nullopt;
  const double mach = e.speed / c0;
  return fmt::format(
      "c0 = {:.3g} m/s is only {:.1f} times the fastest flow the case sets up, {:.3g} m/s ({}): "
      "the water then compresses by about (U/c0)^2 = {:.0f}% and its pressures are wrong; "
      "weakly compressible SPH needs c0 >= 10 U ({:.3g} m/s here). Raise fluid.sound_speed "
      "(or fluid.sound_speed_coef)",
      c0, 1 / mach, e.speed, e.source, 100 * mach * mach, 10 * e.speed);
}

}  // namespace netsph
