#pragma once
// The communication a distributed run needs, behind one interface: MPI between processes
// (mpi_collectives.hpp) or threads of one process (thread_collectives.hpp, which the tests use
// to check the decomposition without mpirun). Every call is collective: all ranks make the
// same calls in the same order.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace netsph {

using Bytes = std::vector<std::byte>;

class Collectives {
 public:
  virtual ~Collectives() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// How many of the ranks share this one's machine (its memory), this one included.
  virtual int processes_on_this_machine() = 0;

  virtual double max(double v) = 0;
  /// Element-wise sums, bit for bit the same on every rank (summed in rank order on one).
  virtual void sum(std::span<double> v) = 0;
  virtual std::uint64_t sum(std::uint64_t v) = 0;
  virtual int min(int v) = 0;
  /// root's text on every rank.
  virtual void broadcast(std::string& text, int root) = 0;
  /// Sends send[r] to rank r (one entry per rank, this rank's own ignored) and returns what
  /// every rank sent this one, by rank.
  virtual std::vector<Bytes> exchange(const std::vector<Bytes>& send) = 0;
  /// Every rank's bytes on rank 0, by rank (an empty list elsewhere).
  virtual std::vector<Bytes> gather(const Bytes& mine) = 0;
  /// Every rank's bytes handed to `take(rank, bytes)` on rank 0, one rank at a time in rank
  /// order, so that rank 0 never holds them all at once (a whole run's particles gathered
  /// for an output); `take` is called on rank 0 only.
  virtual void gather_each(const Bytes& mine,
                           const std::function<void(int, const Bytes&)>& take) = 0;
};

}  // namespace netsph
