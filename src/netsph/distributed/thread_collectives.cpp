#include "netsph/distributed/thread_collectives.hpp"

#include <algorithm>

namespace netsph {

ThreadTeam::ThreadTeam(int size)
    : size_(size),
      barrier_(size),
      reals_(size),
      texts_(size),
      mail_(size, std::vector<Bytes>(size)) {}

const std::vector<std::vector<double>>& ThreadCollectives::all_reals(std::span<const double> v) {
  team_.barrier_.arrive_and_wait();  // everyone has read the previous operation's slots
  team_.reals_[rank_].assign(v.begin(), v.end());
  team_.barrier_.arrive_and_wait();
  return team_.reals_;
}

double ThreadCollectives::max(double v) {
  double out = v;
  for (const auto& r : all_reals({&v, 1})) out = std::max(out, r[0]);
  return out;
}

void ThreadCollectives::sum(std::span<double> v) {
  const auto& all = all_reals(v);
  for (std::size_t k = 0; k < v.size(); ++k) {
    double s = 0;
    for (const auto& r : all) s += r[k];  // rank order: the same sum on every rank
    v[k] = s;
  }
}

std::uint64_t ThreadCollectives::sum(std::uint64_t v) {
  const double d = static_cast<double>(v);
  std::uint64_t s = 0;
  for (const auto& r : all_reals({&d, 1})) s += static_cast<std::uint64_t>(r[0]);
  return s;
}

int ThreadCollectives::min(int v) {
  const double d = v;
  int out = v;
  for (const auto& r : all_reals({&d, 1})) out = std::min(out, static_cast<int>(r[0]));
  return out;
}

void ThreadCollectives::broadcast(std::string& text, int root) {
  team_.barrier_.arrive_and_wait();
  if (rank_ == root) team_.texts_[root] = text;
  team_.barrier_.arrive_and_wait();
  text = team_.texts_[root];
}

std::vector<Bytes> ThreadCollectives::exchange(const std::vector<Bytes>& send) {
  team_.barrier_.arrive_and_wait();
  for (int to = 0; to < size(); ++to) team_.mail_[rank_][to] = to == rank_ ? Bytes{} : send[to];
  team_.barrier_.arrive_and_wait();
  std::vector<Bytes> received(size());
  for (int from = 0; from < size(); ++from) received[from] = team_.mail_[from][rank_];
  return received;
}

std::vector<Bytes> ThreadCollectives::gather(const Bytes& mine) {
  std::vector<Bytes> send(size());
  send[0] = mine;
  std::vector<Bytes> received = exchange(send);
  if (rank_ != 0) return {};
  received[0] = mine;
  return received;
}

void ThreadCollectives::gather_each(const Bytes& mine,
                                    const std::function<void(int, const Bytes&)>& take) {
  const std::vector<Bytes> all = gather(mine);
  for (std::size_t r = 0; r < all.size(); ++r) take(static_cast<int>(r), all[r]);
}

}  // namespace netsph
