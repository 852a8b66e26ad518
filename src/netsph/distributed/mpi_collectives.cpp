#include "netsph/distributed/mpi_collectives.hpp"

#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

#ifdef NETSPH_HAVE_MPI
#include <mpi.h>
#endif

namespace netsph {

bool launched_by_mpi() {
  // OpenMPI's mpirun, PMI/PMIx launchers (MPICH's mpiexec, Slurm's srun). Without MPI in the
  // build too: MpiSession then stops the run with a message instead of N processes each
  // running the whole case into the same folder.
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* v = std::getenv(var);
    if (v && std::atoi(v) > 1) return true;
  }
  return false;
}

#ifdef NETSPH_HAVE_MPI

namespace {

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error("mpi", fmt::format("{} failed: {}", what, std::string(text, length)));
}

int count_of(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw Error("mpi", fmt::format("{} bytes in one message: more than MPI's int count; use "
                                   "more processes",
                                   bytes));
  }
  return static_cast<int>(bytes);
}

}  // namespace

MpiSession::MpiSession() {
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

void MpiSession::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

MpiCollectives::MpiCollectives() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

int MpiCollectives::processes_on_this_machine() {
  // The ranks that can share memory with this one: those on its node.
  MPI_Comm machine = MPI_COMM_NULL;
  check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &machine),
        "MPI_Comm_split_type");
  int count = 1;
  MPI_Comm_size(machine, &count);
  MPI_Comm_free(&machine);
  return count;
}

double MpiCollectives::max(double v) {
  double out = v;
  check(MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

void MpiCollectives::sum(std::span<double> v) {
  // Reduced on rank 0 and broadcast: every rank gets the same bits, which MPI_Allreduce does
  // not promise (the bodies every rank advances from these sums must stay identical).
  std::vector<double> out(v.size());
  check(MPI_Reduce(v.data(), out.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, 0,
                   MPI_COMM_WORLD),
        "MPI_Reduce");
  if (rank_ == 0) std::copy(out.begin(), out.end(), v.begin());
  check(MPI_Bcast(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD),
        "MPI_Bcast");
}

std::uint64_t MpiCollectives::sum(std::uint64_t v) {
  std::uint64_t out = 0;
  check(MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

int MpiCollectives::min(int v) {
  int out = v;
  check(MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

void MpiCollectives::broadcast(std::string& text, int root) {
  int length = static_cast<int>(text.size());
  check(MPI_Bcast(&length, 1, MPI_INT, root, MPI_COMM_WORLD), "MPI_Bcast");
  text.resize(length);
  check(MPI_Bcast(text.data(), length, MPI_CHAR, root, MPI_COMM_WORLD), "MPI_Bcast");
}

std::vector<Bytes> MpiCollectives::exchange(const std::vector<Bytes>& send) {
  std::vector<int> send_counts(size_), recv_counts(size_), send_at(size_), recv_at(size_);
  for (int r = 0; r < size_; ++r) send_counts[r] = r == rank_ ? 0 : count_of(send[r].size());
  check(
      MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD),
      "MPI_Alltoall");
  Bytes out_buffer, in_buffer;
  std::size_t out_total = 0, in_total = 0;
  for (int r = 0; r < size_; ++r) {
    send_at[r] = count_of(out_total), recv_at[r] = count_of(in_total);
    out_total += send_counts[r], in_total += recv_counts[r];
  }
  out_buffer.resize(out_total);
  for (int r = 0; r < size_; ++r)
    if (send_counts[r] > 0)
      std::copy(send[r].begin(), send[r].end(), out_buffer.begin() + send_at[r]);
  in_buffer.resize(in_total);
  check(
      MPI_Alltoallv(out_buffer.data(), send_counts.data(), send_at.data(), MPI_BYTE,
                    in_buffer.data(), recv_counts.data(), recv_at.data(), MPI_BYTE, MPI_COMM_WORLD),
      "MPI_Alltoallv");
  std::vector<Bytes> received(size_);
  for (int r = 0; r < size_; ++r)
    received[r].assign(in_buffer.begin() + recv_at[r],
                       in_buffer.begin() + recv_at[r] + recv_counts[r]);
  return received;
}

std::vector<Bytes> MpiCollectives::gather(const Bytes& mine) {
  int count = count_of(mine.size());
  std::vector<int> counts(size_), at(size_);
  check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  Bytes all;
  if (rank_ == 0) {
    std::size_t total = 0;
    for (int r = 0; r < size_; ++r) at[r] = count_of(total), total += counts[r];
    all.resize(total);
  }
  check(MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE, 0,
                    MPI_COMM_WORLD),
        "MPI_Gatherv");
  if (rank_ != 0) return {};
  std::vector<Bytes> out(size_);
  for (int r = 0; r < size_; ++r)
    out[r].assign(all.begin() + at[r], all.begin() + at[r] + counts[r]);
  return out;
}

void MpiCollectives::gather_each(const Bytes& mine,
                                 const std::function<void(int, const Bytes&)>& take) {
  // Point to point, rank by rank: rank 0 holds one rank's bytes at a time, and no count or
  // displacement spans the whole (MPI's int counts would cap a gather at 2 GB, 4.5e7
  // particles).
  constexpr int kCountTag = 71, kBytesTag = 72;
  if (rank_ != 0) {
    int count = count_of(mine.size());
    check(MPI_Send(&count, 1, MPI_INT, 0, kCountTag, MPI_COMM_WORLD), "MPI_Send");
    check(MPI_Send(mine.data(), count, MPI_BYTE, 0, kBytesTag, MPI_COMM_WORLD), "MPI_Send");
    return;
  }
  take(0, mine);
  Bytes received;
  for (int r = 1; r < size_; ++r) {
    int count = 0;
    check(MPI_Recv(&count, 1, MPI_INT, r, kCountTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    received.resize(static_cast<std::size_t>(count));
    check(
        MPI_Recv(received.data(), count, MPI_BYTE, r, kBytesTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
    take(r, received);
  }
}

#else  // built without MPI

MpiSession::MpiSession() {
  throw Error("mpi", "netsph was built without MPI (install libopenmpi-dev and rebuild)");
}
MpiSession::~MpiSession() = default;
void MpiSession::abort(int code) {
  std::exit(code);
}
MpiCollectives::MpiCollectives() {
  throw Error("mpi", "netsph was built without MPI (install libopenmpi-dev and rebuild)");
}
int MpiCollectives::processes_on_this_machine() {
  return 1;
}
double MpiCollectives::max(double v) {
  return v;
}
void MpiCollectives::sum(std::span<double>) {}
std::uint64_t MpiCollectives::sum(std::uint64_t v) {
  return v;
}
int MpiCollectives::min(int v) {
  return v;
}
void MpiCollectives::broadcast(std::string&, int) {}
std::vector<Bytes> MpiCollectives::exchange(const std::vector<Bytes>&) {
  return {};
}
std::vector<Bytes> MpiCollectives::gather(const Bytes& mine) {
  return {mine};
}

void MpiCollectives::gather_each(const Bytes& mine,
                                 const std::function<void(int, const Bytes&)>& take) {
  take(0, mine);
}

#endif

}  // namespace netsph
