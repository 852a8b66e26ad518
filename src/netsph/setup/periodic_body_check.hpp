#pragma once
// A set-up check of a rigid body against the periodic axes (setup/scene_bodies.cpp).
#include <string>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"

namespace netsph {

/// What is wrong, in words, if body `b` is as wide as half a periodic axis's period or wider
/// (judged by its particle farthest from the centre of mass, so whatever its rotation); empty
/// if not. A body may cross a periodic end (place_rigid_particle puts each particle at the image
/// nearest the cell it was sorted into), but its lever arms are taken at the nearest image of
/// each particle (rigid_lever_arm), which is its own only while the body spans less than half
/// a period.
std::string body_wider_than_half_period(const CaseSpec& spec, const RigidBody& b);

}  // namespace netsph
