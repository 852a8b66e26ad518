#pragma once
// Moves particles between the processes of a distributed run after each step: a particle
// whose position left this process's slab goes to the slab's owner, one that left the domain
// is dropped (lost), and the halo (copies of the particles within the halo width of another
// slab) is sent afresh. Which particles a process owns is kept as a set of ids, not
// recomputed from positions: a halo copy that crossed into this slab during the step is
// still the other process's particle (its owner sends it), so no particle is ever doubled
// or dropped by a round-off difference between two copies.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "netsph/distributed/collectives.hpp"
#include "netsph/distributed/slab_partition.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph {

struct ExchangeReport {
  std::uint64_t lost = 0;  ///< own particles that left the domain (or vanished) in the step
  std::vector<StepDiagnostics::Lost> last_lost;  ///< the last kLostParticlesKept of them
  std::uint64_t sent = 0, received = 0;          ///< migrated to and from other processes
  std::uint64_t halo = 0;                        ///< halo copies received
};

class ParticleExchange {
 public:
  ParticleExchange(const SlabPartition& slabs, Collectives& coll);

  /// At the start: every particle in `p` is this process's own (its part of the scene, each
  /// particle held by one process); the next exchange sends those of other slabs to their
  /// owners and the halo.
  void own_all(const ParticleSet& p);
  /// After a step (collective), or after the slabs were cut again. `grid` is the domain's
  /// (the simulation's).
  ExchangeReport exchange(ParticleSet& p, const CellGrid& grid);
  /// The slabs were cut again (on every process alike): the next exchange sends the halo to
  /// the new neighbours.
  void slabs_changed() { halo_neighbours_ = slabs_.halo_neighbours(coll_.rank()); }

  bool owned(std::uint32_t id) const {
    return id / 64 < owned_.size() && (owned_[id / 64] >> (id % 64) & 1u);
  }
  std::size_t owned_count() const { return owned_count_; }
  /// Makes particle `id` this process's own, or no longer (a particle created or removed by
  /// the open boundaries).
  void set_owned(std::uint32_t id, bool on);
  /// This process's own particles (those with keep[i] != 0 when `keep` is given), packed (for
  /// a gather).
  Bytes pack_owned(const ParticleSet& p, std::span<const std::uint8_t> keep = {}) const;
  /// Appends packed particles to `p`: all of them, or `count` from row `first` on (cut at the
  /// end).
  static void unpack(const Bytes& bytes, ParticleSet& p, std::size_t first = 0,
                     std::size_t count = std::numeric_limits<std::size_t>::max());
  /// How many particles `bytes` hold.
  static std::size_t packed_count(const Bytes& bytes);

 private:
  void send_halo(ParticleSet& p, ExchangeReport& report);

  const SlabPartition& slabs_;
  Collectives& coll_;
  std::vector<int> halo_neighbours_;
  std::vector<std::uint64_t> owned_;  // bit per particle id
  std::size_t owned_count_ = 0;
};

}  // namespace netsph
