#pragma once
// Whether a body starts inside a wall or another body. Fluid that overlaps a solid is removed
// at set-up; a body that overlaps one is kept as placed, and a floating body buried in a floor
// stays stuck there, two nets placed on each other are thrown apart in the first steps, a
// net's knot inside a wall is held by it. Each is almost certainly a placement mistake, and
// nothing else would say so.
#include <string>
#include <vector>

#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// Warnings for the floating bodies (nets' knots included) with particles within dp/2 of a
/// wall's particle or of another body's: one per body, naming the solid it overlaps most and
/// how many of its particles do (at most kMaxListedOverlaps bodies named, then a count of the
/// others). Fixed bodies may overlap walls and each other (a panel's crossing twines do), and
/// a prescribed one goes where it is told (a paddle sunk into the floor to seal it).
/// `wall_names[g]`, `body_names[g]` and `body_moves[g]` describe the walls' and bodies' particle
/// groups.
std::vector<std::string> solid_overlap_warnings(const ParticleSet& p, double dp, int dims,
                                                const std::vector<std::string>& wall_names,
                                                const std::vector<std::string>& body_names,
                                                const std::vector<bool>& body_moves);

inline constexpr std::size_t kMaxListedOverlaps = 5;

}  // namespace netsph
