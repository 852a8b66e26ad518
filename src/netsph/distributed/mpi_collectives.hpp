#pragma once
// Collectives over MPI_COMM_WORLD. netsph initialises MPI only when a launcher (mpirun,
// mpiexec, srun) started it (launched_by_mpi), so a plain `netsph run` never touches MPI.
#include "netsph/distributed/collectives.hpp"

namespace netsph {

/// Whether this process was started by an MPI launcher with more than one process (its
/// environment says so).
bool launched_by_mpi();

/// MPI_Init on construction (with threads funnelled to the main thread), MPI_Finalize on
/// destruction. Throws netsph::Error when netsph was built without MPI.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  /// Ends every process of the run (after an error on one of them that the others cannot see).
  [[noreturn]] static void abort(int code);
};

class MpiCollectives final : public Collectives {
 public:
  MpiCollectives();
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  int processes_on_this_machine() override;
  double max(double v) override;
  void sum(std::span<double> v) override;
  std::uint64_t sum(std::uint64_t v) override;
  int min(int v) override;
  void broadcast(std::string& text, int root) override;
  std::vector<Bytes> exchange(const std::vector<Bytes>& send) override;
  std::vector<Bytes> gather(const Bytes& mine) override;
  void gather_each(const Bytes& mine, const std::function<void(int, const Bytes&)>& take) override;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace netsph
