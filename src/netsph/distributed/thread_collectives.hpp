#pragma once
// Collectives between the threads of one process: rank r of a ThreadTeam of n is the thread
// that calls through its ThreadCollectives. Each operation is two barriers around shared
// slots. For tests and for checking a decomposition without MPI; a thread that throws while
// others wait in an operation leaves them waiting, so callers keep errors collective (as the
// distributed step does).
#include <barrier>
#include <memory>

#include "netsph/distributed/collectives.hpp"

namespace netsph {

class ThreadTeam {
 public:
  explicit ThreadTeam(int size);
  int size() const { return size_; }

 private:
  friend class ThreadCollectives;
  int size_;
  std::barrier<> barrier_;
  std::vector<std::vector<double>> reals_;  // by rank
  std::vector<std::string> texts_;
  std::vector<std::vector<Bytes>> mail_;  // [from][to]
};

class ThreadCollectives final : public Collectives {
 public:
  ThreadCollectives(ThreadTeam& team, int rank) : team_(team), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return team_.size(); }
  /// The threads of one process share its machine.
  int processes_on_this_machine() override { return team_.size(); }
  double max(double v) override;
  void sum(std::span<double> v) override;
  std::uint64_t sum(std::uint64_t v) override;
  int min(int v) override;
  void broadcast(std::string& text, int root) override;
  std::vector<Bytes> exchange(const std::vector<Bytes>& send) override;
  std::vector<Bytes> gather(const Bytes& mine) override;
  void gather_each(const Bytes& mine, const std::function<void(int, const Bytes&)>& take) override;

 private:
  /// Publishes v, waits for all, returns everyone's values by rank (valid until the next call).
  const std::vector<std::vector<double>>& all_reals(std::span<const double> v);
  ThreadTeam& team_;
  int rank_;
};

}  // namespace netsph
