#include "netsph/case/case_spec.hpp"

#include <fmt/format.h>

namespace netsph {

std::string SourceLocation::str() const {
  // Line 0 means "no position": a --set option or a programmatically built case.
  if (line == 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

}  // namespace netsph

namespace netsph {

Vec3d VelocityHistory::at(double t) const {
  if (velocities.empty()) return {};
  if (t <= times.front()) return velocities.front();
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (t <= times[k]) {
      const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
      return velocities[k - 1] * (1 - w) + velocities[k] * w;
    }
  }
  return velocities.back();
}

}  // namespace netsph
