#pragma once
// The equivalent knot of Shi et al. (2024), section 2.2 and Table 1: a rigid shape with the
// same volume (and, for plates, the same projected area) as the cruciform net element it
// stands for: two crossing twines of length l and diameter d. The paper is not consistent in
// how it counts the crossing; EquivalentKnotRule names the three readings that reproduce its
// stated numbers (docs/NETS.md compares them).
#include "netsph/core/physics_options.hpp"

namespace netsph {

/// Projected area (m^2) and volume (m^3) of one cruciform element.
struct CruciformElement {
  double area = 0;
  double volume = 0;
};

/// l: twine (bar) length, d: twine diameter, both m; requires 0 < d < l.
CruciformElement cruciform_element(double l, double d, EquivalentKnotRule rule);

/// The rigid knot standing for an element: square plate (side, thickness), circular plate
/// (diameter, thickness) or sphere (diameter, thickness 0).
struct KnotGeometry {
  KnotShape shape = KnotShape::SquarePlate;
  double size = 0;            ///< plate side, disc diameter or sphere diameter, m
  double thickness = 0;       ///< plate thickness along the net normal, m (0 for spheres)
  double projected_area = 0;  ///< area seen along the net normal, m^2
  double volume = 0;          ///< m^3
};

/// Plates keep the element's area and volume: side sqrt(A) or diameter sqrt(4A/pi), thickness
/// V/A. A sphere keeps only the volume, d = (6V/pi)^(1/3) (Table 1), so its projected area is
/// smaller than the element's.
KnotGeometry equivalent_knot(const CruciformElement& element, KnotShape shape);

/// Solidity of an endless square-mesh netting: Sn = 2d/l - (d/l)^2 (the ratio of twine
/// projected area to outline area).
double netting_solidity(double l, double d);

}  // namespace netsph
