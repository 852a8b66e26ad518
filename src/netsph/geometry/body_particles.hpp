#pragma once
// Body particles of a shape, in its local frame: which layout each shape gets.
//
// Flat-faced shapes (box, plates) and the cruciform take the dp lattice of body_lattice(),
// aligned with the faces, so a plate of n dp holds exactly n layers and its faces lie dp/2
// beyond the outer layer (the mDBC convention).
//
// Round sections (sphere; a cylinder's or disc's circular cross-section) are body-fitted:
// rings (2D, and 3D cylinder layers) or shells (3D sphere) at depths dp/2, 3dp/2, ... below
// the surface, each with round(circumference / dp) (or round(area / dp^2)) evenly spaced
// points. A lattice cannot do this: a lattice point lies anywhere between 0 and dp below a
// curved surface, so keeping only points at least dp/2 deep leaves a staircase whose
// effective radius is up to dp short (a D = 10 dp cylinder lost 10-20% of its diameter along
// the lattice axes and read a drag 9% low in the DFG benchmark; docs/VALIDATION.md).
#include <vector>

#include "netsph/core/vec3.hpp"
#include "netsph/geometry/shapes.hpp"

namespace netsph {

/// `plane` (2D only): the local-frame directions of world x and z, which span the simulation
/// plane. shell_layers > 0 keeps only particles at most shell_layers dp deep (0: solid).
std::vector<Vec3d> body_particles(const Shape& s, double dp, int shell_layers, int dims,
                                  const std::vector<Vec3d>& plane);

}  // namespace netsph
