#include "netsph/setup/periodic_body_check.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace netsph {

std::string body_wider_than_half_period(const CaseSpec& spec, const RigidBody& b) {
  double radius = 0;
  for (const Vec3f& o : b.offsets) radius = std::max(radius, norm(Vec3d(o)));
  static const char* axis_name[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const double period = spec.domain.period(a);
    if (!(period > 0) || radius < 0.5 * period) continue;
    return fmt::format(
        "body '{}' has particles up to {:.4g} m from its centre of mass, not less than half the "
        "periodic {} axis's period ({:.4g} m): a particle's offset from the centre, taken at its "
        "nearest periodic image, would not be its own",
        b.name, radius, axis_name[a], period);
  }
  return {};
}

}  // namespace netsph
