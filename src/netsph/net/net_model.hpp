#pragma once
// A generated net: knots (lumped masses that stand for equivalent cruciform elements) joined by
// twines (tension-only springs), on a rows x columns grid in the net's plane. Built by
// net_generator.hpp from a [[net]] table; moved by knot_spring_solver.hpp.
#include <algorithm>
#include <string>
#include <vector>

#include "netsph/core/vec3.hpp"
#include "netsph/net/equivalent_knot.hpp"
#include "netsph/net/twine_law.hpp"

namespace netsph {

struct NetKnot {
  Vec3d position{};  ///< m
  Vec3d velocity{};  ///< m/s
  double mass = 0;   ///< kg: the netting it stands for, plus its sinker share
  /// Fraction of a whole equivalent element: 1, or 1/2 and 1/4 on edges and corners when the
  /// edges are solidity-matched.
  double element_fraction = 1;
  KnotGeometry geometry;     ///< the (possibly scaled) knot shape, numerical size
  double screen_area = 0;    ///< outline area the knot carries in the screen model, m^2
  double sinker_length = 0;  ///< sinker length the knot carries, m
  Vec3d constant_force{};    ///< gravity, buoyancy, sinker weight and point loads, N
  bool fixed = false;        ///< anchored: does not move
  int row = 0;               ///< 0: bottom row
  int column = 0;            ///< 0: left column seen from upstream
};

/// The mass a twine's axial mode moves: the reduced mass of its end knots, an anchored end
/// counting as infinitely heavy (0 when both ends are anchored).
inline double twine_modal_mass(const NetKnot& a, const NetKnot& b) {
  if (a.fixed && b.fixed) return 0;
  if (a.fixed) return b.mass;
  if (b.fixed) return a.mass;
  return a.mass * b.mass / (a.mass + b.mass);
}

struct NetTwine {
  int a = 0, b = 0;     ///< knot indices
  double rest = 0;      ///< unstretched length, m
  TwineLaw law;         ///< of the numerical twine (lambda real twines in parallel)
  double damping = 0;   ///< N s/m
  double diameter = 0;  ///< numerical (hydrodynamic) diameter lambda d0, m
};

struct NetModel {
  std::string name;
  int rows = 0, columns = 0;
  Vec3d center{}, normal{}, across{}, up{};   ///< outline centre and the net's frame
  double width = 0, height = 0;               ///< outline, m
  double spacing_across = 0, spacing_up = 0;  ///< knot spacing = numerical twine length, m
  double mesh_grouping = 1;
  double twine_length = 0, twine_diameter = 0;  ///< real l0, d0, m
  CruciformElement element;                     ///< numerical element (lambda l0, lambda d0)
  KnotGeometry knot;                            ///< the whole equivalent knot
  double real_solidity = 0;                     ///< 2d/l - (d/l)^2
  double numerical_solidity = 0;                ///< sum of knot projected areas / outline area
  double netting_mass = 0;                      ///< kg, the real netting
  double sinker_mass = 0;                       ///< kg
  double sinker_diameter = 0, sinker_drag_coefficient = 0;
  /// The bar's distance below the bottom row of knots (the net's bottom edge), m: half a
  /// spacing in the inset layout, 0 in the crossings layout.
  double sinker_offset = 0;
  bool crossings = false;  ///< knots on the twine crossings (the outline's edges among them)
  std::vector<NetKnot> knots;
  std::vector<NetTwine> twines;

  int index(int row, int column) const { return row * columns + column; }
};

/// Present strain (L - L0) / L0 of a twine (negative when slack).
inline double twine_strain(const NetModel& net, const NetTwine& t) {
  return (norm(net.knots[t.b].position - net.knots[t.a].position) - t.rest) / t.rest;
}

/// Largest twine tension of the net at its present shape, N.
inline double max_twine_tension(const NetModel& net) {
  double m = 0;
  for (const NetTwine& t : net.twines) m = std::max(m, twine_tension(t.law, twine_strain(net, t)));
  return m;
}

}  // namespace netsph
