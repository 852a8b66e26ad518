#pragma once
// All particles of a run as a structure of arrays. Fluid and boundary particles share the
// arrays (kept sorted by cell by the neighbour search) and are told apart by `kind`.
// Positions are double (integrated over many steps); fields are Real (float).
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

enum class ParticleKind : std::uint8_t {
  Fluid = 0,
  Wall = 1,  ///< boundary particle of a wall (DBC)
};

inline bool is_fluid(ParticleKind k) {
  return k == ParticleKind::Fluid;
}

struct ParticleSet {
  std::vector<Vec3d> pos;  ///< m
  std::vector<Vec3f> vel;  ///< m/s
  std::vector<Real> rho;   ///< kg/m^3
  std::vector<ParticleKind> kind;
  std::vector<std::uint32_t> id;  ///< unique, never reused
  std::uint32_t next_id = 0;

  std::size_t size() const { return pos.size(); }

  void reserve(std::size_t n) {
    pos.reserve(n), vel.reserve(n), rho.reserve(n), kind.reserve(n), id.reserve(n);
  }

  std::uint32_t add(const Vec3d& p, const Vec3f& v, Real density, ParticleKind k) {
    pos.push_back(p), vel.push_back(v), rho.push_back(density), kind.push_back(k);
    id.push_back(next_id);
    return next_id++;
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
           id.capacity() * sizeof(std::uint32_t);
  }
};

/// Replaces `v` by v[order[0]], v[order[1]], ... using `scratch` (no allocation once warm).
template <class T>
void gather_into(std::vector<T>& v, std::span<const std::uint32_t> order, std::vector<T>& scratch) {
  scratch.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = v[order[i]];
  v.swap(scratch);
}

}  // namespace netsph
