#pragma once
// Whether the case's free-surface heights (a fill's or an open boundary's surface_z) and inflow
// profiles lie near its water. Each is checked alone by the case reader (a surface not below
// its own fill); these are the combinations that pass it but are hardly meant: a surface far
// above the water (of a fill, or of a buffer with hydrostatic density) starts the water under
// that head, which springs up unless a lid holds it; an inlet's surface below the bed creates
// no particle; a profile wholly outside the water imposes its end value everywhere.
#include <string>
#include <vector>

#include "netsph/case/case_spec.hpp"

namespace netsph {

/// Warnings for the case (empty when every height is near the water). `water_top` and
/// `water_bottom`: the highest top and lowest bottom of the fills' particle lattices, m.
std::vector<std::string> hydrostatic_warnings(const CaseSpec& spec, double water_top,
                                              double water_bottom);

}  // namespace netsph
