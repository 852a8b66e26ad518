// Tests of the output module: HDF5 + XDMF snapshots (read back with the HDF5 C API and,
// where Debian's h5py is installed, with tools/check_snapshot.py), CSV series, atomic file
// replacement and the progress reporter.
#include <fcntl.h>
#include <hdf5.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/io/atomic_file.hpp"
#include "netsph/io/csv_series.hpp"
#include "netsph/io/progress.hpp"
#include "netsph/io/snapshot_writer.hpp"

namespace {

namespace fs = std::filesystem;
using netsph::Vec3d;
using netsph::Vec3f;

// ---- helpers ------------------------------------------------------------------------------

// A fresh folder under the system temp dir, removed again when the test ends.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("netsph_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) +
             "_" + (info != nullptr ? info->name() : "x"));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// prefix + index with 6 digits + suffix, like the writer's file and grid names.
std::string numbered(const std::string& prefix, std::size_t index, const std::string& suffix) {
  std::ostringstream s;
  s << prefix << std::setw(6) << std::setfill('0') << index << suffix;
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Particle fields with values that differ per particle and per snapshot, including values
// that a float conversion or an off-by-one would change.
struct Particles {
  double time = 0;
  std::int64_t step = 0;
  std::vector<Vec3d> position;
  std::vector<Vec3f> velocity;
  std::vector<float> density, pressure;
  std::vector<std::uint8_t> kind;
  std::vector<std::uint32_t> id;

  netsph::SnapshotFields fields() const {
    netsph::SnapshotFields f;
    f.time = time;
    f.step = step;
    f.position = position;
    f.velocity = velocity;
    f.density = density;
    f.pressure = pressure;
    f.kind = kind;
    f.id = id;
    return f;
  }
};

Particles make_particles(std::size_t n, int snapshot) {
  Particles p;
  p.time = 0.01 * (snapshot + 1) + 1e-17;  // not a short decimal: the XDMF must keep it
  p.step = 1000 * snapshot + 7;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) + snapshot;
    p.position.push_back({x / 3.0, -x * 1e-7, 1.0 + 1.0 / (x + 1.0)});
    p.velocity.push_back({static_cast<float>(0.1 * x), static_cast<float>(-x / 7), 1e-30f});
    p.density.push_back(static_cast<float>(1000.0 + x / 9.0));
    p.pressure.push_back(static_cast<float>(-5.0 + x * 0.33));
    p.kind.push_back(static_cast<std::uint8_t>((i + static_cast<std::size_t>(snapshot)) % 3));
    p.id.push_back(static_cast<std::uint32_t>(4000000000u - i));
  }
  return p;
}

// ---- HDF5 reading (the test's own code, independent of the writer's helpers) ---------------

struct H5Closer {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Closer() {
    if (id >= 0) close(id);
  }
};

template <typename T>
std::vector<T> read_dataset(hid_t file, const char* name, hid_t mem_type, hid_t expected_file_type,
                            std::vector<hsize_t> expected_dims) {
  H5Closer dset{H5Dopen2(file, name, H5P_DEFAULT), H5Dclose};
  EXPECT_GE(dset.id, 0) << name;
  if (dset.id < 0) return {};
  H5Closer type{H5Dget_type(dset.id), H5Tclose};
  EXPECT_GT(H5Tequal(type.id, expected_file_type), 0) << name << ": unexpected file type";
  H5Closer space{H5Dget_space(dset.id), H5Sclose};
  const int rank = H5Sget_simple_extent_ndims(space.id);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  EXPECT_EQ(dims, expected_dims) << name;
  H5Closer dcpl{H5Dget_create_plist(dset.id), H5Pclose};
  // Chunked, each chunk with a checksum that every reader verifies.
  EXPECT_EQ(H5Pget_layout(dcpl.id), H5D_CHUNKED) << name;
  unsigned flags = 0;
  std::size_t values = 0;
  EXPECT_GE(H5Pget_filter_by_id2(dcpl.id, H5Z_FILTER_FLETCHER32, &flags, &values, nullptr, 0,
                                 nullptr, nullptr),
            0)
      << name << ": no checksum";

  hsize_t count = 1;
  for (hsize_t d : dims) count *= d;
  // T may hold several values (Vec3d holds 3 doubles).
  std::vector<T> data(static_cast<std::size_t>(count) * H5Tget_size(mem_type) / sizeof(T));
  if (count > 0 && !data.empty()) {
    EXPECT_GE(H5Dread(dset.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0) << name;
  }
  return data;
}

template <typename T>
T read_root_attribute(hid_t file, const char* name, hid_t mem_type) {
  T value{};
  H5Closer attr{H5Aopen(file, name, H5P_DEFAULT), H5Aclose};
  EXPECT_GE(attr.id, 0) << name;
  if (attr.id >= 0) {
    EXPECT_GE(H5Aread(attr.id, mem_type, &value), 0) << name;
  }
  return value;
}

// Compares every field of an .h5 snapshot with what was written, bit for bit.
void expect_snapshot_file(const fs::path& file, const Particles& p) {
  H5Closer f{H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  ASSERT_GE(f.id, 0) << file;
  const hsize_t n = p.position.size();

  // Vec3 is three plain members, so an N x 3 dataset reads straight into it.
  const auto position =
      read_dataset<Vec3d>(f.id, "position", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, {n, 3});
  const auto velocity =
      read_dataset<Vec3f>(f.id, "velocity", H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, {n, 3});
  const auto density = read_dataset<float>(f.id, "density", H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, {n});
  const auto pressure =
      read_dataset<float>(f.id, "pressure", H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, {n});
  const auto kind = read_dataset<std::uint8_t>(f.id, "kind", H5T_NATIVE_UINT8, H5T_STD_U8LE, {n});
  const auto id = read_dataset<std::uint32_t>(f.id, "id", H5T_NATIVE_UINT32, H5T_STD_U32LE, {n});
  const auto connectivity =
      read_dataset<std::int64_t>(f.id, "connectivity", H5T_NATIVE_INT64, H5T_STD_I64LE, {n});

  EXPECT_EQ(position, p.position);
  EXPECT_EQ(velocity, p.velocity);
  EXPECT_EQ(density, p.density);
  EXPECT_EQ(pressure, p.pressure);
  EXPECT_EQ(kind, p.kind);
  EXPECT_EQ(id, p.id);
  ASSERT_EQ(connectivity.size(), n);
  for (std::size_t i = 0; i < connectivity.size(); ++i) {
    ASSERT_EQ(connectivity[i], static_cast<std::int64_t>(i));
  }
  EXPECT_EQ(read_root_attribute<double>(f.id, "time", H5T_NATIVE_DOUBLE), p.time);
  EXPECT_EQ(read_root_attribute<std::int64_t>(f.id, "step", H5T_NATIVE_INT64), p.step);
}

// ---- XDMF parsing -----------------------------------------------------------------------------

struct XdmfItem {
  std::string dims, number_type, precision, file, dataset;
};
struct XdmfGrid {
  std::string name;
  double time = 0;
  std::string topology_elements;
  std::vector<XdmfItem> items;  // in document order: connectivity, position, then attributes
};

// Enough of a parser for the writer's fixed layout; check_snapshot.py does a real XML parse.
std::vector<XdmfGrid> parse_xdmf(const std::string& text) {
  std::vector<XdmfGrid> grids;
  const std::regex grid_re(R"re(<Grid Name="([^"]+)" GridType="Uniform">([\s\S]*?)</Grid>)re");
  const std::regex time_re(R"re(<Time Value="([^"]+)"/>)re");
  const std::regex topo_re(R"re(<Topology TopologyType="Polyvertex" NumberOfElements="(\d+)")re");
  const std::regex item_re(
      R"re(<DataItem Dimensions="([^"]+)" NumberType="(\w+)" Precision="(\d)" Format="HDF">([^:<]+):/(\w+)</DataItem>)re");
  for (std::sregex_iterator g(text.begin(), text.end(), grid_re), end; g != end; ++g) {
    XdmfGrid grid;
    grid.name = (*g)[1];
    const std::string body = (*g)[2];
    std::smatch m;
    if (std::regex_search(body, m, time_re)) grid.time = std::stod(m[1]);
    if (std::regex_search(body, m, topo_re)) grid.topology_elements = m[1];
    for (std::sregex_iterator i(body.begin(), body.end(), item_re); i != end; ++i) {
      grid.items.push_back({(*i)[1], (*i)[2], (*i)[3], (*i)[4], (*i)[5]});
    }
    grids.push_back(grid);
  }
  return grids;
}

void expect_xdmf_lists(const fs::path& xdmf, const std::vector<Particles>& written) {
  const std::string text = read_text(xdmf);
  EXPECT_NE(text.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  EXPECT_NE(text.find("CollectionType=\"Temporal\""), std::string::npos);
  const std::vector<XdmfGrid> grids = parse_xdmf(text);
  ASSERT_EQ(grids.size(), written.size()) << text;

  struct Expected {
    const char* dataset;
    const char* number_type;
    const char* precision;
    bool vector;
  };
  const std::array<Expected, 7> expected = {{{"connectivity", "Int", "8", false},
                                             {"position", "Float", "8", true},
                                             {"velocity", "Float", "4", true},
                                             {"density", "Float", "4", false},
                                             {"pressure", "Float", "4", false},
                                             {"kind", "UChar", "1", false},
                                             {"id", "UInt", "4", false}}};
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const XdmfGrid& grid = grids[g];
    const std::string n = std::to_string(written[g].position.size());
    EXPECT_EQ(grid.name, numbered("snapshot_", g, ""));
    EXPECT_EQ(grid.time, written[g].time) << "the time must round-trip exactly";
    EXPECT_EQ(grid.topology_elements, n);
    ASSERT_EQ(grid.items.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const XdmfItem& item = grid.items[i];
      EXPECT_EQ(item.dataset, expected[i].dataset);
      EXPECT_EQ(item.number_type, expected[i].number_type) << item.dataset;
      EXPECT_EQ(item.precision, expected[i].precision) << item.dataset;
      EXPECT_EQ(item.dims, expected[i].vector ? n + " 3" : n) << item.dataset;
      EXPECT_EQ(item.file, numbered("snapshots/particles_", g, ".h5"));
      EXPECT_TRUE(fs::exists(xdmf.parent_path() / item.file)) << item.file;
    }
  }
}

// tools/check_snapshot.py; this file is tests/unit/io_test.cpp, the script is in tools/.
fs::path check_script() {
  return fs::path(__FILE__).parent_path() / ".." / ".." / "tools" / "check_snapshot.py";
}

// Why the script cannot run here, or "" when it can: it needs Debian's python with h5py.
std::string check_script_unavailable() {
  if (!fs::exists("/usr/bin/python3")) return "/usr/bin/python3 not found";
  if (std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") != 0) {
    return "h5py is not importable by /usr/bin/python3 (apt-get install python3-h5py)";
  }
  if (!fs::exists(check_script())) {
    return check_script().string() + " not found (__FILE__ is not an absolute path?)";
  }
  return "";
}

// The script's exit status (-1 if it did not exit normally).
int run_check_script(const fs::path& out_dir, bool quiet = false) {
  const std::string command = "/usr/bin/python3 '" + check_script().string() + "' '" +
                              out_dir.string() + "'" + (quiet ? " >/dev/null" : "");
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// ---- snapshots ------------------------------------------------------------------------------

TEST(SnapshotWriter, WritesSnapshotsThatReadBackExactly) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path() / "out");
  EXPECT_EQ(writer.xdmf_path(), tmp.path() / "out" / "particles.xdmf");

  std::vector<Particles> written;
  const std::array<std::size_t, 3> counts = {300, 257, 300};
  for (int s = 0; s < 3; ++s) {
    written.push_back(make_particles(counts[static_cast<std::size_t>(s)], s));
    const fs::path h5 = writer.write(written.back().fields());
    EXPECT_EQ(h5, tmp.path() / "out" / "snapshots" /
                      numbered("particles_", static_cast<std::size_t>(s), ".h5"));
    EXPECT_EQ(writer.count(), s + 1);
    // The XDMF is complete after every snapshot, not only at the end.
    expect_xdmf_lists(writer.xdmf_path(), written);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0) << "the writer leaked HDF5 handles";

  for (std::size_t s = 0; s < written.size(); ++s) {
    expect_snapshot_file(tmp.path() / "out" / "snapshots" / numbered("particles_", s, ".h5"),
                         written[s]);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0) << "the test leaked HDF5 handles";

  // Only the final files are left: no temporary XDMF files.
  for (const auto& e : fs::directory_iterator(tmp.path() / "out")) {
    EXPECT_TRUE(e.path().filename() == "particles.xdmf" || e.path().filename() == "snapshots")
        << e.path();
  }
  if (const std::string why = check_script_unavailable(); !why.empty()) GTEST_SKIP() << why;
  EXPECT_EQ(run_check_script(tmp.path() / "out"), 0);
}

TEST(SnapshotWriter, ZeroParticles) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path(), "empty");
  Particles none = make_particles(0, 0);
  const fs::path h5 = writer.write(none.fields());
  EXPECT_EQ(h5, tmp.path() / "snapshots" / "empty_000000.h5");
  expect_snapshot_file(h5, none);
  const std::string xdmf = read_text(tmp.path() / "empty.xdmf");
  EXPECT_NE(xdmf.find("NumberOfElements=\"0\""), std::string::npos) << xdmf;
  EXPECT_NE(xdmf.find("Dimensions=\"0 3\""), std::string::npos) << xdmf;
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(SnapshotWriter, EmptyThenNonEmptyPassesTheCheckScript) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path());
  writer.write(make_particles(0, 0).fields());
  writer.write(make_particles(5, 1).fields());
  if (const std::string why = check_script_unavailable(); !why.empty()) GTEST_SKIP() << why;
  EXPECT_EQ(run_check_script(tmp.path()), 0);
}

TEST(SnapshotWriter, CheckScriptNoticesAMissingSnapshotFile) {
  if (const std::string why = check_script_unavailable(); !why.empty()) GTEST_SKIP() << why;
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path());
  writer.write(make_particles(4, 0).fields());
  const fs::path second = writer.write(make_particles(4, 1).fields());
  ASSERT_EQ(run_check_script(tmp.path(), true), 0);
  fs::remove(second);
  EXPECT_EQ(run_check_script(tmp.path(), true), 1);
}

TEST(SnapshotWriter, MismatchedSpanLengthsThrow) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path());
  Particles p = make_particles(10, 0);
  p.density.pop_back();
  EXPECT_THROW(writer.write(p.fields()), netsph::Error);
  EXPECT_EQ(writer.count(), 0);
  EXPECT_FALSE(fs::exists(writer.xdmf_path()));
}

TEST(SnapshotWriter, FolderThatCannotBeCreatedNamesThePath) {
  TempDir tmp;
  const fs::path blocker = tmp.path() / "a_file";
  std::ofstream(blocker) << "x";
  try {
    netsph::SnapshotWriter writer(blocker / "out");
    FAIL() << "expected netsph::Error";
  } catch (const netsph::Error& e) {
    EXPECT_NE(std::string(e.what()).find((blocker / "out").string()), std::string::npos)
        << e.what();
  }
}

TEST(SnapshotWriter, Hdf5FailureGivesOneMessageNamingTheFile) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path());
  // A folder where the first snapshot file should go makes H5Fcreate fail.
  const fs::path in_the_way = tmp.path() / "snapshots" / "particles_000000.h5";
  fs::create_directories(in_the_way);
  testing::internal::CaptureStderr();
  try {
    writer.write(make_particles(3, 0).fields());
    ADD_FAILURE() << "expected netsph::Error";
  } catch (const netsph::Error& e) {
    EXPECT_EQ(e.where(), in_the_way.string());
    EXPECT_NE(e.message().find("cannot create the HDF5 file"), std::string::npos) << e.what();
  }
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find("HDF5-DIAG"), std::string::npos) << "HDF5 printed its error stack:\n" << err;
  EXPECT_TRUE(fs::is_directory(in_the_way)) << "only a partial file of ours may be removed";
  EXPECT_EQ(writer.count(), 0);
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(SnapshotWriter, ADamagedSnapshotFailsToReadInsteadOfShowingOtherValues) {
  TempDir tmp;
  netsph::SnapshotWriter writer(tmp.path());
  const Particles p = make_particles(1000, 0);
  const fs::path h5 = writer.write(p.fields());
  // One byte of the densities, found by their values, changed.
  std::string bytes = read_text(h5);
  const std::string density(reinterpret_cast<const char*>(p.density.data()),
                            p.density.size() * sizeof(float));
  const std::size_t at = bytes.find(density.substr(0, 64));
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(bytes.find(density.substr(0, 64), at + 1), std::string::npos);
  bytes[at + 100] = static_cast<char>(bytes[at + 100] ^ 0x10);
  write_text(h5, bytes);
  H5E_auto2_t print = nullptr;
  void* print_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &print, &print_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the failure expected is no news
  {
    H5Closer file{H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(file.id, 0);
    H5Closer dset{H5Dopen2(file.id, "density", H5P_DEFAULT), H5Dclose};
    std::vector<float> density_read(p.density.size());
    EXPECT_LT(
        H5Dread(dset.id, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, density_read.data()), 0)
        << "a damaged snapshot was read";
  }
  H5Eclear2(H5E_DEFAULT);
  H5Eset_auto2(H5E_DEFAULT, print, print_data);
}

TEST(SnapshotWriter, RejectsBaseNamesThatBreakPaths) {
  TempDir tmp;
  EXPECT_THROW(netsph::SnapshotWriter(tmp.path(), ""), netsph::Error);
  EXPECT_THROW(netsph::SnapshotWriter(tmp.path(), "a/b"), netsph::Error);
  EXPECT_THROW(netsph::SnapshotWriter(tmp.path(), "a:b"), netsph::Error);
}

// ---- CSV ----------------------------------------------------------------------------------

TEST(CsvSeries, HeaderAndValueFormatting) {
  TempDir tmp;
  const fs::path file = tmp.path() / "forces.csv";
  {
    netsph::CsvSeries csv(file, {{"time", "s"}, {"step", ""}, {"Fx", "N"}, {"a, b", ""}});
    EXPECT_EQ(csv.path(), file);
    const double two53 = 9007199254740992.0;
    csv.append(std::vector<double>{0.0, 1.0, -3.0, 1.5});
    csv.append(std::vector<double>{1.0 / 3.0, 1e20, two53 - 1, two53});
    csv.append(std::vector<double>{std::nan(""), std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(), -0.0});
    csv.append(std::vector<double>{-std::nan(""), 2.5e-12, -1234567.0, 0.1});
  }
  EXPECT_EQ(read_text(file),
            "time [s],step,Fx [N],\"a, b\"\n"
            "0,1,-3,1.5\n"
            "0.333333333,1e+20,9007199254740991,9.00719925e+15\n"
            "nan,inf,-inf,0\n"
            "nan,2.5e-12,-1234567,0.1\n");
}

TEST(CsvSeries, WrongValueCountThrows) {
  TempDir tmp;
  netsph::CsvSeries csv(tmp.path() / "a.csv", {{"a", ""}, {"b", ""}});
  EXPECT_THROW(csv.append(std::vector<double>{1.0}), netsph::Error);
  EXPECT_THROW(csv.append(std::vector<double>{1.0, 2.0, 3.0}), netsph::Error);
  csv.append(std::vector<double>{1.0, 2.0});  // still usable after a rejected row
  EXPECT_EQ(read_text(csv.path()), "a,b\n1,2\n");
}

TEST(CsvSeries, RowsAreFlushedAtOnce) {
  TempDir tmp;
  netsph::CsvSeries csv(tmp.path() / "probe.csv", {{"t", "s"}});
  EXPECT_EQ(read_text(csv.path()), "t [s]\n");  // header visible before any row
  csv.append(std::vector<double>{0.25});
  EXPECT_EQ(read_text(csv.path()), "t [s]\n0.25\n");
  csv.append(std::vector<double>{0.5});
  EXPECT_EQ(read_text(csv.path()), "t [s]\n0.25\n0.5\n");
}

TEST(CsvSeries, ResumeKeepsTheRowsUpToTheCheckpointAndRefusesOtherColumns) {
  TempDir tmp;
  const fs::path file = tmp.path() / "series.csv";
  const std::vector<netsph::CsvColumn> cols = {{"time", "s"}, {"Fx", "N/m"}, {"My", "N"}};
  write_text(file, "time [s],Fx [N/m],My [N]\n0.1,1,2\n0.2,3,4\n0.30000000001,5,6\n");
  {
    netsph::CsvSeries csv(file, cols, 0.3);
    csv.append(std::vector<double>{0.35, 7, 8});
  }
  // 0.30000000001 is 0.3 within the 9 printed digits' round-off: kept.
  EXPECT_EQ(read_text(file),
            "time [s],Fx [N/m],My [N]\n0.1,1,2\n0.2,3,4\n0.30000000001,5,6\n"
            "0.35,7,8\n");
  { netsph::CsvSeries csv(file, cols, 0.15); }
  EXPECT_EQ(read_text(file), "time [s],Fx [N/m],My [N]\n0.1,1,2\n");
  // Other columns: refused, the file untouched.
  EXPECT_THROW(netsph::CsvSeries(file, {{"time", "s"}, {"Fz", "N/m"}, {"My", "N"}}, 0.2),
               netsph::Error);
  EXPECT_THROW(netsph::CsvSeries(file, {{"time", "s"}, {"Fx", "N/m"}}, 0.2), netsph::Error);
  EXPECT_EQ(read_text(file), "time [s],Fx [N/m],My [N]\n0.1,1,2\n");
}

TEST(CsvSeries, ResumeAcceptsTheUnitLabelsBeforeTheirRelabelling) {
  // A 2D run checkpointed before 2026-12-03 labelled its forces per metre N and its moments
  // N m; the numbers are the same quantities, so the restart continues and relabels.
  TempDir tmp;
  const fs::path file = tmp.path() / "bodies.csv";
  write_text(file, "time [s],step,Fx [N],My [N m]\n0.1,5,1,2\n0.2,9,3,4\n");
  {
    netsph::CsvSeries csv(file, {{"time", "s"}, {"step", ""}, {"Fx", "N/m"}, {"My", "N"}}, 0.1);
    csv.append(std::vector<double>{0.15, 7, 5, 6});
  }
  EXPECT_EQ(read_text(file), "time [s],step,Fx [N/m],My [N]\n0.1,5,1,2\n0.15,7,5,6\n");
  // Only the old labels of the same columns: other names, or another unit, are still refused.
  write_text(file, "time [s],Fx [N],My [N m]\n0.1,1,2\n");
  EXPECT_THROW(netsph::CsvSeries(file, {{"time", "s"}, {"Fz", "N/m"}, {"My", "N"}}, 0.1),
               netsph::Error);
  EXPECT_THROW(netsph::CsvSeries(file, {{"time", "s"}, {"Fx", "N/m"}, {"My", "m"}}, 0.1),
               netsph::Error);
}

TEST(CsvSeries, UncreatableFileNamesThePath) {
  TempDir tmp;
  const fs::path file = tmp.path() / "missing" / "a.csv";
  try {
    netsph::CsvSeries csv(file, {{"a", ""}});
    FAIL() << "expected netsph::Error";
  } catch (const netsph::Error& e) {
    EXPECT_EQ(e.where(), file.string());
    EXPECT_NE(e.message().find("No such file or directory"), std::string::npos) << e.what();
  }
}

// ---- atomic file ----------------------------------------------------------------------------

TEST(AtomicFile, ReplacesContentAndLeavesNoTemporaryFile) {
  TempDir tmp;
  const fs::path file = tmp.path() / "summary.json";
  netsph::write_file_atomic(file, "first version, longer than the second\n");
  EXPECT_EQ(read_text(file), "first version, longer than the second\n");
  netsph::write_file_atomic(file, "second\n");
  EXPECT_EQ(read_text(file), "second\n");
  netsph::write_file_atomic(file, "");
  EXPECT_EQ(read_text(file), "");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(AtomicFile, MissingFolderNamesThePath) {
  TempDir tmp;
  const fs::path file = tmp.path() / "no_such_dir" / "a.txt";
  try {
    netsph::write_file_atomic(file, "x");
    FAIL() << "expected netsph::Error";
  } catch (const netsph::Error& e) {
    EXPECT_EQ(e.where(), file.string());
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
    EXPECT_NE(e.message().find("No such file or directory"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(tmp.path() / "no_such_dir"));
}

TEST(AtomicFile, RenameFailureRemovesTheTemporaryFile) {
  TempDir tmp;
  // A non-empty folder cannot be replaced by a file: the rename fails after the write.
  const fs::path target = tmp.path() / "dir";
  fs::create_directories(target / "child");
  EXPECT_THROW(netsph::write_file_atomic(target, "x"), netsph::Error);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

// ---- progress -------------------------------------------------------------------------------

TEST(Progress, StatusLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  const netsph::ProgressReporter p(2.0, f, true);
  EXPECT_EQ(p.status_line(0.5, 1000, 1000, 10.0),
            "t = 0.500 / 2.000 s (25.0%)  step 1000  100 steps/s  1.00e+05 particle-steps/s  "
            "ETA 0:00:30");
  EXPECT_EQ(p.status_line(0.512, 1234, 2400, 0.8125),
            "t = 0.512 / 2.000 s (25.6%)  step 1234  1519 steps/s  3.65e+06 particle-steps/s  "
            "ETA 0:00:02");
  // Hours as h:mm:ss: 0.001 s of 2 s took 10 s -> 19990 s left.
  EXPECT_EQ(p.status_line(0.001, 10, 1, 10.0),
            "t = 0.001 / 2.000 s (0.1%)  step 10  1 steps/s  1.00e+00 particle-steps/s  "
            "ETA 5:33:10");
  // Nothing measured yet: unknown rates and ETA.
  EXPECT_EQ(p.status_line(0.0, 0, 100, 0.0),
            "t = 0.000 / 2.000 s (0.0%)  step 0  -- steps/s  -- particle-steps/s  ETA --");
  // Done.
  EXPECT_EQ(p.status_line(2.0, 400, 10, 4.0),
            "t = 2.000 / 2.000 s (100.0%)  step 400  100 steps/s  1.00e+03 particle-steps/s  "
            "ETA 0:00:00");
  std::fclose(f);
}

TEST(Progress, ShortRunsShowMoreDecimals) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  const netsph::ProgressReporter p(0.05, f, true);
  EXPECT_EQ(p.status_line(0.0125, 50, 10, 2.0).substr(0, 31), "t = 0.01250 / 0.05000 s (25.0%)");
  std::fclose(f);
}

std::string read_all(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
  return text;
}

TEST(Progress, PlainModePrintsTheFirstUpdateThenEveryInterval) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  netsph::ProgressReporter p(1.0, f, true, 3600.0);
  for (int i = 0; i < 100; ++i) p.update(0.01 * i, i, 50);
  p.finish(1.0, 100, 50);
  const std::vector<std::string> lines = lines_of(read_all(f));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("t = 0.000 / 1.000 s (0.0%)  step 0", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("t = 1.000 / 1.000 s (100.0%)  step 100", 0), 0u) << lines[1];
  for (const std::string& l : lines) EXPECT_EQ(l.find('\r'), std::string::npos);
  std::fclose(f);

  // With a zero interval every update prints.
  f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  netsph::ProgressReporter every(1.0, f, true, 0.0);
  for (int i = 0; i < 5; ++i) every.update(0.1 * i, i, 50);
  EXPECT_EQ(lines_of(read_all(f)).size(), 5u);
  std::fclose(f);
}

TEST(Progress, NonTerminalStreamIsPlainEvenIfNotAsked) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  netsph::ProgressReporter p(1.0, f, false, 3600.0);
  p.update(0.5, 10, 5);
  p.finish(1.0, 20, 5);
  const std::string text = read_all(f);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(text.find('['), std::string::npos);
  EXPECT_EQ(lines_of(text).size(), 2u);
  std::fclose(f);
}

// Terminal mode, on a pseudo-terminal: a bar redrawn in place, rate-limited, and one final
// newline from finish().
TEST(Progress, TerminalModeRedrawsOneLine) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
    if (master >= 0) ::close(master);
    GTEST_SKIP() << "no pseudo-terminal available";
  }
  // A new pty reports 0 columns; give it a wide window so that the bar fits.
  winsize ws{};
  ws.ws_col = 200;
  ws.ws_row = 24;
  ::ioctl(master, TIOCSWINSZ, &ws);
  std::FILE* term = std::fopen(::ptsname(master), "w");
  ASSERT_NE(term, nullptr);
  {
    netsph::ProgressReporter p(2.0, term);
    for (int i = 0; i < 50; ++i) p.update(0.01 * i, i, 10);  // well under 200 ms: one draw
    p.finish(1.0, 50, 10);
  }
  std::fclose(term);

  std::string out;
  char buf[4096];
  pollfd pfd{master, POLLIN, 0};
  while (::poll(&pfd, 1, 200) > 0 && (pfd.revents & POLLIN) != 0) {
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(master);

  // The tty turns "\n" into "\r\n"; two draws: the first update and finish().
  std::size_t draws = 0;
  for (std::size_t pos = 0; (pos = out.find("\r[", pos)) != std::string::npos; ++pos) ++draws;
  EXPECT_EQ(draws, 2u) << out;
  EXPECT_NE(out.find("[###############---------------] t = 1.000 / 2.000 s (50.0%)  step 50"),
            std::string::npos)
      << out;
  EXPECT_EQ(out.back(), '\n');
}

}  // namespace
