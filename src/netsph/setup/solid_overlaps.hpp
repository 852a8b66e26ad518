#pragma once
// Whether a body starts inside a wall or another body. Fluid that overlaps a solid is removed
// at set-up; a body that overlaps one is kept as placed, and a floating body buried in a floor
// stays stuck there, two nets placed on each other are thrown apart in the first steps, a
// net's knot inside a wall is held by it. Each is almost certainly a placement mistake, and
// nothing else would say so.
//
// Found in two stages so that a distributed run reports the whole case: each process counts
// the overlaps of the particles it owns (find_solid_overlaps), the counts are summed
// (SolidOverlaps::add, through pack/unpack between processes), and the sum is worded once
// (solid_overlap_warnings).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/setup/half_spacing_search.hpp"

namespace netsph {

/// Counts of the floating bodies' (nets' knots included) particles within dp/2 of a wall's
/// particle or of another body's. Fixed bodies may overlap walls and each other (a panel's
/// crossing twines do), and a prescribed one goes where it is told (a paddle sunk into the
/// floor to seal it).
struct SolidOverlaps {
  /// Per floating body (its index): its overlapping particles by the solid they overlap,
  /// walls as -1 - wall index, bodies as their index. Bodies without overlaps are absent.
  std::map<std::uint32_t, std::map<std::int64_t, std::size_t>> hits;
  /// Per floating body: its particles counted (with or without overlaps).
  std::map<std::uint32_t, std::size_t> sizes;

  /// Adds another part's counts (a distributed run's processes each count their own).
  void add(const SolidOverlaps& other);
  /// As bytes for the collectives (distributed/collectives.hpp), and back.
  std::vector<std::byte> pack() const;
  static SolidOverlaps unpack(const std::vector<std::byte>& bytes);
};

/// Counts the overlaps of the floating bodies' particles of `p` for which `counted(position)`
/// holds (a process's own, so that the parts' counts add up to the whole case's), searching
/// all of `p` with `search` (built over `p`). `bodies` are the bodies of the particles' groups.
SolidOverlaps find_solid_overlaps(const ParticleSet& p, const HalfSpacingSearch& search,
                                  const std::vector<RigidBody>& bodies,
                                  const std::function<bool(const Vec3d&)>& counted);

/// One warning per overlapping body, naming the solid it overlaps most and how many of its
/// particles do (at most kMaxListedOverlaps bodies named, then a count of the others).
std::vector<std::string> solid_overlap_warnings(const SolidOverlaps& overlaps, const CaseSpec& spec,
                                                const std::vector<RigidBody>& bodies);

inline constexpr std::size_t kMaxListedOverlaps = 5;

}  // namespace netsph
