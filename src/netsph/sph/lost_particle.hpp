#pragma once
// A particle that left the domain (not through an outlet), as the report of a run stopped for
// losing fluid names it: every backend and the distributed run keep the last few the same way.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "netsph/core/vec3.hpp"

namespace netsph {

struct LostParticle {
  std::uint32_t id;
  Vec3d pos;  ///< m, where it was when dropped (just past the face it crossed)
  Vec3f vel;  ///< m/s
};

/// How many of the last lost particles a report keeps.
inline constexpr std::size_t kLostParticlesKept = 5;

/// Appends `l` to the last lost particles, dropping the oldest beyond kLostParticlesKept.
inline void remember_lost(std::vector<LostParticle>& last, const LostParticle& l) {
  if (last.size() == kLostParticlesKept) last.erase(last.begin());
  last.push_back(l);
}

}  // namespace netsph
