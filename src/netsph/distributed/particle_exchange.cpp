#include "netsph/distributed/particle_exchange.hpp"

#include <omp.h>

#include <algorithm>
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

PackedParticle packed(const ParticleSet& p, std::size_t i) {
  return {p.pos[i], p.vel[i], p.ghost[i], p.rho[i], p.id[i], p.group[i], p.kind[i]};
}

/// Packs, for each rank r, the particles i with goes_to(i, r), in index order, into out[r]:
/// in parallel, each thread counting then writing its own contiguous share of the particles
/// at its offset, so the bytes are those of one thread packing them in turn.
template <class GoesTo>
void pack_where(std::vector<Bytes>& out, const ParticleSet& p, std::span<const int> ranks,
                const GoesTo& goes_to) {
  const std::size_t n = p.size(), nr = ranks.size();
  if (nr == 0) return;
  const int threads = std::max(1, std::min(omp_get_max_threads(), static_cast<int>(n / 4096) + 1));
  // counts[t * nr + k]: thread t's particles for ranks[k]; then its offset within out[ranks[k]].
  std::vector<std::size_t> counts(static_cast<std::size_t>(threads) * nr, 0);
  const auto share = [n, threads](int t) { return n * static_cast<std::size_t>(t) / threads; };
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    std::size_t* mine = counts.data() + static_cast<std::size_t>(t) * nr;
    for (std::size_t i = share(t); i < share(t + 1); ++i)
      for (std::size_t k = 0; k < nr; ++k) mine[k] += goes_to(i, ranks[k]);
#pragma omp barrier
#pragma omp single
    for (std::size_t k = 0; k < nr; ++k) {
      std::size_t total = 0;
      for (int u = 0; u < threads; ++u) {
        const std::size_t c = counts[static_cast<std::size_t>(u) * nr + k];
        counts[static_cast<std::size_t>(u) * nr + k] = total;
        total += c;
      }
      out[ranks[k]].resize(total * sizeof(PackedParticle));
    }
    for (std::size_t i = share(t); i < share(t + 1); ++i)
      for (std::size_t k = 0; k < nr; ++k) {
        if (!goes_to(i, ranks[k])) continue;
        const PackedParticle q = packed(p, i);
        std::memcpy(out[ranks[k]].data() + mine[k]++ * sizeof q, &q, sizeof q);
      }
  }
}

/// Moves particle `from` to slot `to` (to <= from), every field.
void move_slot(ParticleSet& p, std::size_t to, std::size_t from) {
  p.pos[to] = p.pos[from], p.vel[to] = p.vel[from], p.ghost[to] = p.ghost[from];
  p.rho[to] = p.rho[from], p.id[to] = p.id[from], p.group[to] = p.group[from];
  p.kind[to] = p.kind[from];
}

/// Every array to n particles, grown as a running case's arrays grow (core/growth.hpp), not
/// doubled.
void resize_all(ParticleSet& p, std::size_t n) {
  resize_for(p.pos, n), resize_for(p.vel, n), resize_for(p.ghost, n), resize_for(p.rho, n);
  resize_for(p.id, n), resize_for(p.group, n), resize_for(p.kind, n);
}

void note_lost(ExchangeReport& r, const ParticleSet& p, std::size_t i) {
  ++r.lost;
  remember_lost(r.last_lost, {p.id[i], p.pos[i], p.vel[i]});
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

std::size_t ParticleExchange::packed_count(const Bytes& bytes) {
  return bytes.size() / sizeof(PackedParticle);
}

void ParticleExchange::unpack(const Bytes& bytes, ParticleSet& p, std::size_t from,
                              std::size_t count) {
  const std::size_t rows = packed_count(bytes), first = p.size();
  from = std::min(from, rows);
  const std::size_t n = std::min(count, rows - from);
  resize_all(p, first + n);
  const auto unpacked = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (n > 8192)
  for (std::int64_t k = 0; k < unpacked; ++k) {
    PackedParticle q;
    std::memcpy(&q, bytes.data() + (from + static_cast<std::size_t>(k)) * sizeof q, sizeof q);
    const std::size_t i = first + static_cast<std::size_t>(k);
    p.pos[i] = q.pos, p.vel[i] = q.vel, p.ghost[i] = q.ghost, p.rho[i] = q.rho;
    p.id[i] = q.id, p.group[i] = q.group, p.kind[i] = q.kind;
  }
}

Bytes ParticleExchange::pack_owned(const ParticleSet& p, std::span<const std::uint8_t> keep) const {
  std::vector<Bytes> out(1);
  const int only = 0;
  pack_where(out, p, {&only, 1},
             [&](std::size_t i, int) { return owned(p.id[i]) && (keep.empty() || keep[i]); });
  return std::move(out[0]);
}

void ParticleExchange::own_all(const ParticleSet& p) {
  owned_.assign(p.next_id / 64 + 1, 0);
  owned_count_ = 0;
  for (const std::uint32_t id : p.id) set_owned(id, true);
}

ExchangeReport ParticleExchange::exchange(ParticleSet& p, const CellGrid& grid) {
  const int me = coll_.rank();
  ExchangeReport report;
  const std::size_t owned_before = owned_count_;
  // Where each particle goes, decided in parallel (the owner's search and the grid's test are
  // most of the work): a halo copy is dropped (its owner sends it again), an own particle
  // outside the grid is lost (the sort's own test: the step would drop it), one in another
  // slab goes to its owner.
  constexpr int kHaloCopy = -3, kLost = -2, kKeep = -1;
  const auto n = static_cast<std::int64_t>(p.size());
  std::vector<int> dest(p.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!owned(p.id[i])) {
      dest[i] = kHaloCopy;
      continue;
    }
    const Vec3d x = grid.wrapped(p.pos[i]);
    if (!std::isfinite(x.x + x.y + x.z) || grid.cell_of(x) < 0) {
      dest[i] = kLost;
      continue;
    }
    const int owner = slabs_.owner_of(x);
    dest[i] = owner == me ? kKeep : owner;
  }
  // The ranks some particle goes to (usually a neighbour or two; any after the slabs were cut
  // again): packing tests each particle against these only.
  std::vector<char> targeted(coll_.size(), 0);
  for (const int d : dest)
    if (d >= 0) targeted[d] = 1;
  std::vector<int> targets;
  for (int r = 0; r < coll_.size(); ++r)
    if (targeted[r]) targets.push_back(r);
  std::vector<Bytes> send(coll_.size());
  pack_where(send, p, targets, [&dest](std::size_t i, int r) { return dest[i] == r; });
  // In index order: the lost particles' report, ownership, and the kept ones moved down.
  std::size_t w = 0, present = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (dest[i] == kHaloCopy) continue;
    ++present;
    if (dest[i] == kLost) {
      note_lost(report, p, i);
      set_owned(p.id[i], false);
    } else if (dest[i] != kKeep) {
      set_owned(p.id[i], false);
      ++report.sent;
    } else {
      move_slot(p, w++, i);
    }
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
  resize_all(p, w);
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
  pack_where(send, p, halo_neighbours_,
             [&](std::size_t i, int r) { return slabs_.distance_to(r, p.pos[i]) < slabs_.halo; });
  const std::vector<Bytes> received = coll_.exchange(send);
  const std::size_t before = p.size();
  for (const Bytes& b : received) unpack(b, p);
  report.halo = p.size() - before;
}

}  // namespace netsph
