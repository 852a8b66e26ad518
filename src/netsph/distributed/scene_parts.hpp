#pragma once
// Where each process of a distributed run builds its part of the scene (build_scene_part),
// before the slabs are cut from the particles themselves: a first split along the axis the
// case's boxes spread furthest, at equal shares of the fills' volume, so that no process
// needs the memory of the whole case at the start. The particles then move to the owners of
// the balanced slabs in one exchange (distributed_simulation.cpp).
#include "netsph/case/case_spec.hpp"
#include "netsph/geometry/box_lattice.hpp"

namespace netsph {

/// Process `rank`'s region of `ranks`: the regions tile the axis (the first and last reach to
/// infinity, so every particle lies in exactly one).
AxisRange set_up_region(const CaseSpec& spec, int ranks, int rank);

}  // namespace netsph
