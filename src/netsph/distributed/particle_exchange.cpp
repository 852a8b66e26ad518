#include "netsph/distributed/particle_exchange.hpp"

#include <cmath>
#include <cstring>

namespace netsph {
namespace {

// One particle on the wire: every field of ParticleSet.
struct PackedParticle {
  Vec3d pos;
  Vec3f vel;
  Vec3f ghost;
  Real rho;
  std::uint32_t id;
  std::uint32_t group;
  ParticleKind kind;
};

void pack(Bytes& out, const ParticleSet& p, std::size_t i) {
  const PackedParticle q{p.pos[i], p.vel[i], p.ghost[i], p.rho[i], p.id[i], p.group[i], p.kind[i]};
  const std::size_t at = out.size();
  out.resize(at + sizeof q);
  std::memcpy(out.data() + at, &q, sizeof q);
}

/// Moves particle `from` to slot `to` (to <= from), every field.
void move_slot(ParticleSet& p, std::size_t to, std::size_t from) {
  p.pos[to] = p.pos[from], p.vel[to] = p.vel[from], p.ghost[to] = p.ghost[from];
  p.rho[to] = p.rho[from], p.id[to] = p.id[from], p.group[to] = p.group[from];
  p.kind[to] = p.kind[from];
}

void truncate(ParticleSet& p, std::size_t n) {
  p.pos.resize(n), p.vel.resize(n), p.ghost.resize(n), p.rho.resize(n), p.id.resize(n);
  p.group.resize(n), p.kind.resize(n);
}

void note_lost(ExchangeReport& r, const ParticleSet& p, std::size_t i) {
  ++r.lost;
  if (r.last_lost.size() == 5) r.last_lost.erase(r.last_lost.begin());
  r.last_lost.push_back({p.id[i], p.pos[i], p.vel[i]});
}

}  // namespace

ParticleExchange::ParticleExchange(const SlabPartition& slabs, Collectives& coll)
    : slabs_(slabs), coll_(coll), halo_neighbours_(slabs.halo_neighbours(coll.rank())) {}

void ParticleExchange::set_owned(std::uint32_t id, bool on) {
  if (id / 64 >= owned_.size()) owned_.resize(id / 64 + 1, 0);
  const std::uint64_t bit = std::uint64_t{1} << (id % 64);
  if (on && !(owned_[id / 64] & bit)) ++owned_count_;
  if (!on && (owned_[id / 64] & bit)) --owned_count_;
  owned_[id / 64] = on ? owned_[id / 64] | bit : owned_[id / 64] & ~bit;
}

void ParticleExchange::unpack(const Bytes& bytes, ParticleSet& p) {
  const std::size_t n = bytes.size() / sizeof(PackedParticle);
  p.reserve_more(n);
  for (std::size_t k = 0; k < n; ++k) {
    PackedParticle q;
    std::memcpy(&q, bytes.data() + k * sizeof q, sizeof q);
    p.pos.push_back(q.pos), p.vel.push_back(q.vel), p.ghost.push_back(q.ghost);
    p.rho.push_back(q.rho), p.id.push_back(q.id), p.group.push_back(q.group);
    p.kind.push_back(q.kind);
  }
}

Bytes ParticleExchange::pack_owned(const ParticleSet& p, std::span<const std::uint8_t> keep) const {
  Bytes out;
  if (keep.empty()) out.reserve(owned_count_ * sizeof(PackedParticle));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (owned(p.id[i]) && (keep.empty() || keep[i])) pack(out, p, i);
  return out;
}

void ParticleExchange::own_all(const ParticleSet& p) {
  owned_.assign(p.next_id / 64 + 1, 0);
  owned_count_ = 0;
  for (const std::uint32_t id : p.id) set_owned(id, true);
}

ExchangeReport ParticleExchange::exchange(ParticleSet& p, const CellGrid& grid) {
  const int me = coll_.rank();
  ExchangeReport report;
  std::vector<Bytes> send(coll_.size());
  const std::size_t owned_before = owned_count_;
  std::size_t w = 0, present = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!owned(p.id[i])) continue;  // a halo copy: its owner sends it again
    ++present;
    const Vec3d x = grid.wrapped(p.pos[i]);
    // The sort's own test: outside the grid, the step would drop it as lost.
    if (!std::isfinite(x.x + x.y + x.z) || grid.cell_of(x) < 0) {
      note_lost(report, p, i);
      set_owned(p.id[i], false);
      continue;
    }
    const int owner = slabs_.owner_of(x);
    if (owner != me) {
      pack(send[owner], p, i);
      set_owned(p.id[i], false);
      ++report.sent;
      continue;
    }
    move_slot(p, w++, i);
  }
  // Own particles the step itself dropped (a mid-step re-sort finding them outside the grid).
  if (present < owned_before) {
    std::vector<std::uint64_t> seen(owned_.size(), 0);
    for (std::size_t i = 0; i < w; ++i) seen[p.id[i] / 64] |= std::uint64_t{1} << (p.id[i] % 64);
    for (std::size_t k = 0; k < owned_.size(); ++k) {
      const std::uint64_t gone = owned_[k] & ~seen[k];
      for (int b = 0; b < 64; ++b) {
        if (!(gone >> b & 1u)) continue;
        set_owned(static_cast<std::uint32_t>(64 * k + b), false);
        ++report.lost;
      }
    }
  }
  truncate(p, w);
  const std::vector<Bytes> received = coll_.exchange(send);
  for (const Bytes& b : received) {
    const std::size_t first = p.size();
    unpack(b, p);
    for (std::size_t i = first; i < p.size(); ++i) set_owned(p.id[i], true);
    report.received += p.size() - first;
  }
  send_halo(p, report);
  return report;
}

void ParticleExchange::send_halo(ParticleSet& p, ExchangeReport& report) {
  std::vector<Bytes> send(coll_.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const int r : halo_neighbours_)
      if (slabs_.distance_to(r, p.pos[i]) < slabs_.halo) pack(send[r], p, i);
  const std::vector<Bytes> received = coll_.exchange(send);
  const std::size_t before = p.size();
  for (const Bytes& b : received) unpack(b, p);
  report.halo = p.size() - before;
}

}  // namespace netsph
