#include "netsph/net/equivalent_knot.hpp"

#include <cmath>
#include <numbers>

namespace netsph {

CruciformElement cruciform_element(double l, double d, EquivalentKnotRule rule) {
  constexpr double pi = std::numbers::pi;
  // Two twines of length l each; their crossing is a d x d square in projection and, read
  // as a cylinder of length d, a volume (pi/4) d^3 that the exact rule counts once.
  const bool overlap_area = rule != EquivalentKnotRule::Full;
  const bool overlap_volume = rule == EquivalentKnotRule::Exact;
  CruciformElement e;
  e.area = 2 * l * d - (overlap_area ? d * d : 0.0);
  e.volume = pi / 4 * d * d * (2 * l - (overlap_volume ? d : 0.0));
  return e;
}

KnotGeometry equivalent_knot(const CruciformElement& e, KnotShape shape) {
  constexpr double pi = std::numbers::pi;
  KnotGeometry k;
  k.shape = shape;
  k.volume = e.volume;
  switch (shape) {
    case KnotShape::SquarePlate:
      k.size = std::sqrt(e.area);
      k.thickness = e.volume / e.area;
      k.projected_area = e.area;
      break;
    case KnotShape::CircularPlate:
      k.size = std::sqrt(4 * e.area / pi);
      k.thickness = e.volume / e.area;
      k.projected_area = e.area;
      break;
    case KnotShape::Sphere:
      k.size = std::cbrt(6 * e.volume / pi);
      k.thickness = 0;
      k.projected_area = pi / 4 * k.size * k.size;
      break;
  }
  return k;
}

double netting_solidity(double l, double d) {
  const double r = d / l;
  return 2 * r - r * r;
}

}  // namespace netsph
