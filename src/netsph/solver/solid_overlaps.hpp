#pragma once
// Whether a body starts inside a wall or another body. Fluid that overlaps a solid is removed
// at set-up; a body that overlaps one is kept as placed, and a floating body buried in a floor
// stays stuck there, two nets placed on each other are thrown apart in the first steps, a
// net's knot inside a wall is held by it. Each is almost certainly a placement mistake, and
// nothing else would say so.
#include <string>
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/solver/half_spacing_search.hpp"

namespace netsph {

/// Warnings for the floating bodies (nets' knots included) with particles within dp/2 of a
/// wall's particle or of another body's (found by `search`, over `p`): one per body, naming
/// the solid it overlaps most and how many of its particles do (at most kMaxListedOverlaps
/// bodies named, then a count of the others). Fixed bodies may overlap walls and each other
/// (a panel's crossing twines do), and a prescribed one goes where it is told (a paddle sunk
/// into the floor to seal it). `bodies` are the bodies of the particles' groups.
std::vector<std::string> solid_overlap_warnings(const ParticleSet& p,
                                                const HalfSpacingSearch& search,
                                                const CaseSpec& spec,
                                                const std::vector<RigidBody>& bodies);

inline constexpr std::size_t kMaxListedOverlaps = 5;

}  // namespace netsph
