#pragma once
// Nets the unit tests share.
#include "netsph/case/case_spec.hpp"

namespace netsph::test {

/// A 0.3 m net of 3 x 3 numerical meshes (2 cm twines of 2.6 mm, mesh grouping 5) hung from
/// its top edge, with a 6 mm steel sinker bar along its bottom edge.
inline NetSpec net_with_sinker(KnotLayout layout) {
  NetSpec s;
  s.name = "net";
  s.width = s.height = 0.3;
  s.twine_length = 0.02;
  s.twine_diameter = 0.0026;
  s.mesh_grouping = 5;
  s.layout = layout;
  s.fixed_edges = {false, true, false, false};
  s.sinker = {0.3, 0.006, 8610, 1.2};
  return s;
}

}  // namespace netsph::test
