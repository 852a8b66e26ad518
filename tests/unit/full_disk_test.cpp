// Output files whose writing fails half-way (a full disk, a quota, a file size limit): the
// checkpoint writer (io/checkpoint_file.hpp) must throw one netsph::Error naming the file,
// keep the previous checkpoint.h5 byte for byte, leave no temporary file, close every HDF5
// object, print nothing of HDF5's own, and leave the process able to exit normally (HDF5 at
// exit used to crash on a file it could not close: SIGSEGV in H5F__close_cb, or "HDF5:
// infinite loop closing library"). The snapshot writer likewise. Each write runs in a child
// process, so that its exit is part of the test. Two ways to fail: RLIMIT_FSIZE (writes past
// the limit fail with EFBIG; any user may set it) at limits that cut the file at many points,
// and, as root, a small tmpfs filled to many levels (ENOSPC, the real thing).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/io/csv_series.hpp"
#include "netsph/io/snapshot_writer.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("netsph_full_disk_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A checkpoint of `n` rows, written in pieces as a run writes its particles, with a few
/// dozen small arrays as well; `after_data` is called when all the data is written (the
/// metadata is written after it).
void write_checkpoint(const fs::path& file, std::size_t n,
                      const std::function<void()>& after_data = {}) {
  CheckpointData global;
  global.f64["sim.time"] = {0.5};
  for (int i = 0; i < 40; ++i) global.f32["body" + std::to_string(i)] = {1.f, 2.f, 3.f};
  global.text["case.toml"] = "[simulation]\nname = \"full\"\n";
  write_checkpoint_file(file, global, [n, &after_data](const auto& add) {
    for (std::size_t first = 0; first < n; first += 40000) {
      const std::size_t m = std::min<std::size_t>(40000, n - first);
      CheckpointData piece;
      for (std::size_t r = first; r < first + m; ++r) {
        const double x = static_cast<double>(r);
        piece.f64["particles.pos"].insert(piece.f64["particles.pos"].end(), {x, x, x});
        piece.u32["particles.id"].push_back(static_cast<std::uint32_t>(r));
        piece.u8["particles.kind"].push_back(static_cast<std::uint8_t>(r % 3));
      }
      add(piece);
    }
    if (after_data) after_data();
  });
}

/// What a child reports through its exit status.
enum Outcome : int {
  kAsExpected = 0,
  kNoError = 10,         // the failed write did not throw netsph::Error
  kOtherException = 11,  // it threw something else
  kBadMessage = 12,      // the message does not name the file
  kOldChanged = 13,      // the previous file changed
  kLeftovers = 14,       // a temporary or partial file was left
  kOpenObjects = 15,     // HDF5 objects left open
  kOpenFiles = 16,       // file descriptors left open (inside HDF5, where no call reaches them)
};

/// The number of file descriptors this process has open.
int open_descriptors() {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

/// Runs `body` in a child process, with writes past `limit` bytes failing (RLIMIT_FSIZE) when
/// given; the child exits through std::exit, so HDF5's clean-up at exit runs. Returns the
/// child's exit status, or 128 + the signal that ended it; `err` receives its stderr (through
/// a pipe: a file would be cut by the limit too).
int in_child(const std::function<int()>& body, std::string& err, std::optional<rlim_t> limit) {
  std::fflush(nullptr);
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipe_fds[1], 2);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    if (limit) {
      std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
      const rlimit l{*limit, RLIM_INFINITY};
      ::setrlimit(RLIMIT_FSIZE, &l);
    }
    int code = kOtherException;
    try {
      code = body();
    } catch (...) {
    }
    std::exit(code);
  }
  ::close(pipe_fds[1]);
  err.clear();
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) err.append(buffer, n);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// In the child: writes the checkpoint `n` rows big over `file`, which must fail and leave it
/// as it was.
int failing_checkpoint_write(const fs::path& file, std::size_t n,
                             const std::function<void()>& after_data = {}) {
  const std::string before = text_of(file);
  const int descriptors = open_descriptors();
  try {
    write_checkpoint(file, n, after_data);
    return kNoError;
  } catch (const Error& e) {
    std::fprintf(stderr, "netsph::Error: %s\n", e.what());
    if (std::string(e.what()).find(file.string()) == std::string::npos) return kBadMessage;
  }
  if (text_of(file) != before) return kOldChanged;
  for (const auto& entry : fs::directory_iterator(file.parent_path()))
    if (entry.path() != file && entry.path().filename() != "filler") return kLeftovers;
  if (H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) != 0) return kOpenObjects;
  if (open_descriptors() != descriptors) return kOpenFiles;
  return kAsExpected;
}

/// The child's stderr must hold its one message and nothing of HDF5's.
void expect_one_message(const std::string& text, const std::string& where) {
  EXPECT_EQ(text.find("HDF5-DIAG"), std::string::npos) << where << ":\n" << text;
  EXPECT_EQ(text.find("HDF5:"), std::string::npos) << where << ":\n" << text;
  EXPECT_NE(text.find("netsph::Error"), std::string::npos) << where << ":\n" << text;
}

constexpr std::size_t kRows = 60000;  // about 2.2 MB of checkpoint

TEST(FullDisk, AFailedCheckpointWriteKeepsThePreviousOneAndExitsCleanly) {
  TempDir tmp;
  const fs::path file = tmp.path() / "run" / "checkpoint.h5";
  fs::create_directories(file.parent_path());
  std::string err;
  write_checkpoint(file, kRows);  // the size of the one that will fail
  const auto size = static_cast<rlim_t>(fs::file_size(file));
  write_checkpoint(file, 100);  // the previous checkpoint, which must survive
  // Cuts at the start (creating the file), in the data and in the metadata at its end.
  for (const rlim_t limit : {rlim_t{0}, rlim_t{100}, rlim_t{3000}, rlim_t{70000}, size / 3,
                             size / 2, size - 70000, size - 5000, size - 600, size - 1}) {
    const std::string where =
        "file size limit " + std::to_string(limit) + " of " + std::to_string(size);
    EXPECT_EQ(in_child([&] { return failing_checkpoint_write(file, kRows); }, err, limit),
              kAsExpected)
        << where << ":\n"
        << err;
    expect_one_message(err, where);
  }
}

/// A tmpfs of `bytes` at `at`, unmounted when done; mounted() false when this process may not
/// mount one (not root, or in a container without the right).
class SmallTmpfs {
 public:
  SmallTmpfs(const fs::path& at, std::size_t bytes) : at_(at) {
    fs::create_directories(at);
    const std::string options = "size=" + std::to_string(bytes);
    mounted_ = ::geteuid() == 0 && ::mount("tmpfs", at.c_str(), "tmpfs", 0, options.c_str()) == 0;
  }
  ~SmallTmpfs() {
    if (mounted_) ::umount2(at_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }

 private:
  fs::path at_;
  bool mounted_ = false;
};

/// Fills the file system at `dir` up to `free_bytes` left free, with a file named "filler".
void leave_free(const fs::path& dir, std::uintmax_t free_bytes) {
  fs::remove(dir / "filler");
  const std::uintmax_t available = fs::space(dir).available;
  if (available <= free_bytes) return;
  std::ofstream out(dir / "filler", std::ios::binary);
  const std::vector<char> block(4096, 'x');
  for (std::uintmax_t left = available - free_bytes; left >= block.size(); left -= block.size())
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
}

TEST(FullDisk, ACheckpointOnAFullTmpfsKeepsThePreviousOneAndExitsCleanly) {
  TempDir tmp;
  const fs::path disk = tmp.path() / "disk", file = disk / "checkpoint.h5";
  std::string err;
  write_checkpoint(tmp.path() / "measure.h5", kRows);
  const std::uintmax_t size = fs::file_size(tmp.path() / "measure.h5");
  SmallTmpfs tmpfs(disk, 2 * size + (1 << 20));
  if (!tmpfs.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  write_checkpoint(file, 100);
  for (const std::uintmax_t free_bytes :
       {std::uintmax_t{0}, std::uintmax_t{4096}, std::uintmax_t{65536}, size / 3, size / 2,
        size - 65536, size - 8192}) {
    leave_free(disk, free_bytes);
    const std::string where =
        std::to_string(free_bytes) + " bytes free for " + std::to_string(size);
    EXPECT_EQ(in_child([&] { return failing_checkpoint_write(file, kRows); }, err, std::nullopt),
              kAsExpected)
        << where << ":\n"
        << err;
    expect_one_message(err, where);
  }
}

// The disk fills after the data and before the metadata (another program's output, say): the
// metadata's flush is where HDF5 1.10 fails beyond repair, so the writer must fail before it.
TEST(FullDisk, ADiskThatFillsBeforeTheMetadataIsWrittenKeepsThePreviousCheckpoint) {
  TempDir tmp;
  const fs::path disk = tmp.path() / "disk", file = disk / "checkpoint.h5";
  SmallTmpfs tmpfs(disk, 8 << 20);
  if (!tmpfs.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  write_checkpoint(file, 100);
  std::string err;
  EXPECT_EQ(
      in_child([&] { return failing_checkpoint_write(file, 1000, [&] { leave_free(disk, 0); }); },
               err, std::nullopt),
      kAsExpected)
      << err;
  expect_one_message(err, "disk filled after the data");
}

/// In the child: a snapshot that cannot be written is one netsph::Error and no file.
int failing_snapshot_write(const fs::path& dir, std::size_t n) {
  SnapshotWriter writer(dir);
  std::vector<Vec3d> position(n, Vec3d{1, 2, 3});
  std::vector<Vec3f> velocity(n);
  std::vector<float> density(n, 1000.f), pressure(n);
  std::vector<std::uint8_t> kind(n);
  std::vector<std::uint32_t> id(n);
  SnapshotFields fields{0.1, 3, position, velocity, density, pressure, kind, id};
  const int descriptors = open_descriptors();
  try {
    writer.write(fields);
    return kNoError;
  } catch (const Error& e) {
    std::fprintf(stderr, "netsph::Error: %s\n", e.what());
    if (std::string(e.what()).find("particles_000000.h5") == std::string::npos) return kBadMessage;
  }
  if (fs::exists(dir / "snapshots" / "particles_000000.h5")) return kLeftovers;
  if (H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) != 0) return kOpenObjects;
  if (open_descriptors() != descriptors) return kOpenFiles;
  return kAsExpected;
}

TEST(FullDisk, AFailedSnapshotIsOneMessageAndNoFile) {
  TempDir tmp;
  std::string err;
  constexpr std::size_t n = 50000;  // 2.2 MB of snapshot
  for (const rlim_t limit : {rlim_t{0}, rlim_t{2000}, rlim_t{500000}, rlim_t{2000000}}) {
    const std::string where = "file size limit " + std::to_string(limit);
    EXPECT_EQ(in_child([&] { return failing_snapshot_write(tmp.path() / "out", n); }, err, limit),
              kAsExpected)
        << where << ":\n"
        << err;
    expect_one_message(err, where);
  }
}

/// Appends rows to a series until a write fails; exits kAsExpected when it threw
/// netsph::Error naming the file.
int failing_series_write(const fs::path& file) {
  CsvSeries csv(file, {{"time", "s"}, {"mass", "kg"}, {"energy", "J"}, {"step", ""}});
  try {
    for (int i = 0; i < 1000000; ++i) {
      const double t = 0.001 * i;
      const std::array<double, 4> row{t, 1000.0 + 1e-7 * i, 3.14159265 * t, double(i)};
      csv.append(row);
    }
  } catch (const Error& e) {
    return std::string(e.where()) == file.string() ? kAsExpected : kBadMessage;
  }
  return kNoError;
}

// issue 46: a full disk while writing series.csv left half a row, which pandas reads as a row
// of NaN or refuses. At limits that cut the file at many points within a row, the series
// keeps whole rows only: every line ends with its newline and has all its columns.
TEST(FullDisk, AFailedSeriesRowLeavesOnlyCompleteRows) {
  TempDir tmp;
  std::string err;
  const fs::path file = tmp.path() / "series.csv";
  for (const rlim_t limit : {rlim_t{100}, rlim_t{1001}, rlim_t{4093}, rlim_t{20011}}) {
    const std::string where = "file size limit " + std::to_string(limit);
    ASSERT_EQ(in_child([&] { return failing_series_write(file); }, err, limit), kAsExpected)
        << where << ":\n"
        << err;
    const std::string text = text_of(file);
    ASSERT_FALSE(text.empty()) << where;
    EXPECT_EQ(text.back(), '\n') << where << ": the file ends in half a row";
    std::size_t rows = 0, start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = text.substr(start, end - start);
      EXPECT_EQ(std::count(line.begin(), line.end(), ','), 3) << where << ": " << line;
      ++rows;
    }
    EXPECT_GT(rows, 1u) << where;
    EXPECT_LE(text.size(), limit) << where;
  }
}

}  // namespace
}  // namespace netsph
