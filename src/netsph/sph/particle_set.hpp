#pragma once
// All particles of a run as a structure of arrays. Fluid and boundary particles share the
// arrays (kept sorted by cell by the neighbour search) and are told apart by `kind`.
// Positions are double (integrated over many steps); fields are Real (float).
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "netsph/core/enum_names.hpp"
#include "netsph/core/growth.hpp"
#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

enum class ParticleKind : std::uint8_t {
  Fluid = 0,
  Wall = 1,    ///< boundary particle of a wall (DBC or mDBC); `group` = wall index
  Buffer = 2,  ///< open-boundary buffer particle; `group` = zone index (inlets, then outlets)
  Body = 3,    ///< boundary particle of a rigid body; `group` = body index
};
/// The kinds as messages about one particle name them.
inline constexpr std::array kParticleKindNames = {
    EnumName<ParticleKind>{"fluid", ParticleKind::Fluid},
    EnumName<ParticleKind>{"wall", ParticleKind::Wall},
    EnumName<ParticleKind>{"buffer", ParticleKind::Buffer},
    EnumName<ParticleKind>{"body", ParticleKind::Body}};
constexpr std::string_view name_of(ParticleKind v) {
  return name_of(kParticleKindNames, v);
}
static_assert(one_to_one(kParticleKindNames));
/// The kinds as the set-up's messages name where a particle came from (setup/scene_domain.cpp):
/// a second spelling, by source.
inline constexpr std::array kParticleKindSources = {
    EnumName<ParticleKind>{"fill", ParticleKind::Fluid},
    EnumName<ParticleKind>{"wall", ParticleKind::Wall},
    EnumName<ParticleKind>{"open-boundary buffer", ParticleKind::Buffer},
    EnumName<ParticleKind>{"body", ParticleKind::Body}};
static_assert(one_to_one(kParticleKindSources));

/// Particles the momentum and continuity equations move.
NETSPH_HD bool is_fluid(ParticleKind k) {
  return k == ParticleKind::Fluid;
}
/// Particles that carry fluid state as neighbours (fluid and open-boundary buffers).
NETSPH_HD bool carries_fluid(ParticleKind k) {
  return k == ParticleKind::Fluid || k == ParticleKind::Buffer;
}
/// Boundary particles: walls and bodies.
NETSPH_HD bool is_solid(ParticleKind k) {
  return k == ParticleKind::Wall || k == ParticleKind::Body;
}

struct ParticleSet {
  std::vector<Vec3d> pos;  ///< m
  std::vector<Vec3f> vel;  ///< m/s
  std::vector<Real> rho;   ///< kg/m^3
  std::vector<ParticleKind> kind;
  std::vector<std::uint32_t> id;     ///< unique, never reused
  std::vector<std::uint32_t> group;  ///< wall or zone index (see ParticleKind); 0 for fluid
  /// mDBC: vector from a wall particle to its ghost node inside the fluid (zero: no ghost).
  std::vector<Vec3f> ghost;
  std::uint32_t next_id = 0;

  std::size_t size() const { return pos.size(); }

  void reserve(std::size_t n) {
    pos.reserve(n), vel.reserve(n), rho.reserve(n), kind.reserve(n), id.reserve(n);
    group.reserve(n), ghost.reserve(n);
  }
  /// Room for k more particles while a case is built: capacities at least double, so that
  /// building n particles in batches copies O(n). (Growing by 1/16, as `make_room` does for a
  /// running case, copied the arrays some 250 times while a 1e7-particle case was built: a
  /// third of `netsph check`'s time, most of it in page faults.) Call `shrink_to_fit` once built.
  void reserve_more(std::size_t k) {
    const std::size_t n = size() + k;
    if (n > pos.capacity()) reserve(std::max(n, 2 * pos.capacity()));
  }
  /// Capacities equal to the size: a built case starts with no slack.
  void shrink_to_fit() {
    pos.shrink_to_fit(), vel.shrink_to_fit(), rho.shrink_to_fit(), kind.shrink_to_fit();
    id.shrink_to_fit(), group.shrink_to_fit(), ghost.shrink_to_fit();
  }
  /// Room for one more particle, growing every array as core/growth.hpp does (each on its
  /// own: the sort's gathers swap arrays with scratch buffers of other capacities).
  void make_room() {
    const std::size_t n = pos.size() + 1;
    reserve_for(pos, n), reserve_for(vel, n), reserve_for(rho, n), reserve_for(kind, n);
    reserve_for(id, n), reserve_for(group, n), reserve_for(ghost, n);
  }

  std::uint32_t add(const Vec3d& p, const Vec3f& v, Real density, ParticleKind k,
                    std::uint32_t grp = 0, const Vec3f& ghost_offset = {}) {
    make_room();
    pos.push_back(p), vel.push_back(v), rho.push_back(density), kind.push_back(k);
    group.push_back(grp), ghost.push_back(ghost_offset);
    id.push_back(next_id);
    return next_id++;
  }

  /// Drops particle i wherever keep[i] is 0, in place (the order of the rest is kept).
  void keep_only(const std::vector<char>& keep) {
    const auto compact = [&](auto& v) {
      std::size_t out = 0;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (keep[i]) v[out++] = v[i];
      v.resize(out);
    };
    compact(pos), compact(vel), compact(rho), compact(kind), compact(id), compact(group);
    compact(ghost);
  }

  std::size_t count(ParticleKind k) const {
    std::size_t n = 0;
    for (auto x : kind) n += (x == k);
    return n;
  }

  /// Bytes held per particle by these arrays (capacity, not size).
  std::size_t bytes() const {
    return pos.capacity() * sizeof(Vec3d) + vel.capacity() * sizeof(Vec3f) +
           rho.capacity() * sizeof(Real) + kind.capacity() * sizeof(ParticleKind) +
           id.capacity() * sizeof(std::uint32_t) + group.capacity() * sizeof(std::uint32_t) +
           ghost.capacity() * sizeof(Vec3f);
  }
};

/// Replaces `v` by v[order[0]], v[order[1]], ... using `scratch` (no allocation once warm).
template <class T>
void gather_into(std::vector<T>& v, std::span<const std::uint32_t> order, std::vector<T>& scratch) {
  resize_for(scratch, order.size());
  for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = v[order[i]];
  v.swap(scratch);
}

/// Puts every array of `p` in the order given (sorted slot -> old index), dropping the
/// particles `order` leaves out. Allocates its scratch: for set-up code and tests; the solver
/// reorders with reused scratch (solver/simulation.cpp).
inline void reorder(ParticleSet& p, std::span<const std::uint32_t> order) {
  std::vector<Vec3d> d3;
  std::vector<Vec3f> f3;
  std::vector<Real> f;
  std::vector<ParticleKind> k;
  std::vector<std::uint32_t> u;
  gather_into(p.pos, order, d3), gather_into(p.vel, order, f3), gather_into(p.rho, order, f);
  gather_into(p.kind, order, k), gather_into(p.id, order, u), gather_into(p.group, order, u);
  gather_into(p.ghost, order, f3);
}

}  // namespace netsph
