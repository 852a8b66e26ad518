#include "netsph/io/snapshot_writer.hpp"

#include <fmt/format.h>

#include <array>
#include <numeric>
#include <optional>
#include <sstream>
#include <system_error>
#include <type_traits>

#include "netsph/core/error.hpp"
#include "netsph/io/atomic_file.hpp"
#include "netsph/io/hdf5_handle.hpp"
#include "netsph/io/hdf5_layout.hpp"
#include "netsph/io/hdf5_output_file.hpp"
#include "netsph/io/output_folder.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

// The vector fields are written straight from the caller's memory as N x 3 datasets.
static_assert(std::is_standard_layout_v<Vec3d> && sizeof(Vec3d) == 3 * sizeof(double));
static_assert(std::is_standard_layout_v<Vec3f> && sizeof(Vec3f) == 3 * sizeof(float));

// One dataset of a snapshot file, described once for both the HDF5 writer and the XDMF
// text, so that the declared types and shapes cannot drift from what is on disk.
struct FieldSpec {
  const char* name;         // dataset name at the file root, and XDMF attribute name
  const char* number_type;  // XDMF NumberType
  int precision;            // XDMF Precision (bytes)
  int components;           // 1 (N) or 3 (N x 3)
  const char* role;         // "Topology", "Geometry", or an XDMF AttributeType
};

constexpr std::array<FieldSpec, 7> kFields = {{
    {"connectivity", "Int", 8, 1, "Topology"},
    {"position", "Float", 8, 3, "Geometry"},
    {"velocity", "Float", 4, 3, "Vector"},
    {"density", "Float", 4, 1, "Scalar"},
    {"pressure", "Float", 4, 1, "Scalar"},
    {"kind", "UChar", 1, 1, "Scalar"},
    {"id", "UInt", 4, 1, "Scalar"},
}};

// HDF5 types for a FieldSpec: little-endian in the file (what every reader expects), native
// in memory (identical on x86 and ARM, so HDF5 writes the caller's bytes without converting).
hid_t file_type(const FieldSpec& f) {
  const std::string_view t = f.number_type;
  if (t == "Float") return f.precision == 8 ? H5T_IEEE_F64LE : H5T_IEEE_F32LE;
  if (t == "Int") return H5T_STD_I64LE;
  if (t == "UChar") return H5T_STD_U8LE;
  return H5T_STD_U32LE;  // "UInt"
}

hid_t memory_type(const FieldSpec& f) {
  const std::string_view t = f.number_type;
  if (t == "Float") return f.precision == 8 ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT;
  if (t == "Int") return H5T_NATIVE_INT64;
  if (t == "UChar") return H5T_NATIVE_UINT8;
  return H5T_NATIVE_UINT32;  // "UInt"
}

using h5::check_id;
using h5::check_status;
using h5::fail;

// Creates dataset `f` for n particles (written in pieces by write_rows), kept by `file`:
// chunked with a checksum per chunk (hdf5_layout.hpp), which ParaView and h5py verify as they
// read; rows unlimited only so that a snapshot of no particle can be chunked too.
hid_t create_dataset(h5::OutputFile& file, const FieldSpec& f, std::size_t n) {
  const fs::path& path = file.path();
  const std::string what = std::string("cannot create dataset /") + f.name;
  const hsize_t width = static_cast<hsize_t>(f.components);
  const std::array<hsize_t, 2> dims = {n, width}, most = {H5S_UNLIMITED, width};
  const int rank = f.components == 1 ? 1 : 2;
  const h5::Handle space(check_id(H5Screate_simple(rank, dims.data(), most.data()), path, what),
                         H5Sclose);
  const h5::Handle dcpl = h5::checksummed_layout(h5::chunk_rows(n, width), width, path);
  const h5::Handle dapl = h5::uncached_access(path);
  return file.keep(h5::Handle(check_id(H5Dcreate2(file.get(), f.name, file_type(f), space.get(),
                                                  H5P_DEFAULT, dcpl.get(), dapl.get()),
                                       path, what),
                              H5Dclose));
}

// Writes rows [at, at + m) of dataset `f` from `data` (m rows of the caller's memory).
void write_rows(hid_t dset, const FieldSpec& f, std::size_t at, std::size_t m, const void* data,
                const fs::path& path) {
  // An empty span may have a null data(), which H5Dwrite rejects; nothing to write anyway.
  if (m == 0) return;
  const std::string what = std::string("cannot write dataset /") + f.name;
  const int rank = f.components == 1 ? 1 : 2;
  const std::array<hsize_t, 2> start = {at, 0}, count = {m, static_cast<hsize_t>(f.components)};
  h5::Handle file_space(check_id(H5Dget_space(dset), path, what), H5Sclose);
  check_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                   count.data(), nullptr),
               path, what);
  h5::Handle memory_space(check_id(H5Screate_simple(rank, count.data(), nullptr), path, what),
                          H5Sclose);
  check_status(
      H5Dwrite(dset, memory_type(f), memory_space.get(), file_space.get(), H5P_DEFAULT, data), path,
      what);
}

void write_scalar_attribute(hid_t file, const char* name, hid_t ftype, hid_t mtype,
                            const void* value, const fs::path& path) {
  const std::string what = std::string("cannot write attribute ") + name;
  h5::Handle space(check_id(H5Screate(H5S_SCALAR), path, what), H5Sclose);
  h5::Handle attr(
      check_id(H5Acreate2(file, name, ftype, space.get(), H5P_DEFAULT, H5P_DEFAULT), path, what),
      H5Aclose);
  check_status(H5Awrite(attr.get(), mtype, value), path, what);
  check_status(attr.close(), path, what);
}

std::size_t particle_count(const SnapshotFields& s, const fs::path& dir) {
  const std::size_t n = s.position.size();
  if (s.velocity.size() != n || s.density.size() != n || s.pressure.size() != n ||
      s.kind.size() != n || s.id.size() != n) {
    throw Error(dir.string(),
                fmt::format("snapshot fields differ in length: position {}, velocity {}, "
                            "density {}, pressure {}, kind {}, id {}",
                            n, s.velocity.size(), s.density.size(), s.pressure.size(),
                            s.kind.size(), s.id.size()));
  }
  return n;
}

// The base name becomes part of file names and of "file.h5:/dataset" references in the
// XDMF, where a '/' or ':' would change the meaning.
void check_base_name(const std::string& base, const fs::path& dir) {
  if (base.empty() || base.find_first_of("/\\:") != std::string::npos ||
      base.find('\0') != std::string::npos) {
    throw Error(dir.string(),
                "invalid snapshot base name '" + base + "' (must be non-empty, without / \\ :)");
  }
}

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// One <DataItem> pointing at dataset `f` of `h5` (a path relative to the .xdmf file).
void append_data_item(fmt::memory_buffer& out, const FieldSpec& f, std::size_t n,
                      std::string_view h5, int indent) {
  const std::string dims =
      f.components == 1 ? fmt::format("{}", n) : fmt::format("{} {}", n, f.components);
  fmt::format_to(std::back_inserter(out),
                 "{:{}}<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" "
                 "Format=\"HDF\">{}:/{}</DataItem>\n",
                 "", indent, dims, f.number_type, f.precision, h5, f.name);
}

}  // namespace

SnapshotWriter::SnapshotWriter(std::filesystem::path dir, std::string base, bool resume)
    : dir_(std::move(dir)), base_(std::move(base)) {
  check_base_name(base_, dir_);
  const fs::path snapshots = dir_ / "snapshots";
  create_output_folder(snapshots, "snapshots");
  // A new run into the same folder replaces the previous run's snapshots: stale files with
  // higher numbers would otherwise sit next to the new ones and mislead anyone globbing them.
  // (A restart keeps them: resume() sorts out which.)
  if (resume) return;
  const std::string prefix = base_ + "_";
  std::error_code ec;  // a stale file that cannot be listed or removed is left
  for (const auto& entry : fs::directory_iterator(snapshots, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.starts_with(prefix) && name.ends_with(".h5")) {
      fs::remove(entry.path(), ec);
    }
  }
}

std::string SnapshotWriter::entries_text() const {
  std::string out;
  for (const Entry& e : entries_)
    out += fmt::format("{} {:.17g} {} {}\n", e.h5_relative, e.time, e.step, e.n);
  return out;
}

void SnapshotWriter::resume(const std::string& entries) {
  // The constructor removed every snapshot file; a restart keeps the ones its checkpoint
  // lists, so the constructor's sweep must not have run: see RunOutputs, which builds the
  // writer with resume = true.
  entries_.clear();
  std::istringstream in(entries);
  Entry e;
  while (in >> e.h5_relative >> e.time >> e.step >> e.n) entries_.push_back(e);
  std::error_code ec;
  const std::string prefix = base_ + "_";
  for (const auto& entry : fs::directory_iterator(dir_ / "snapshots", ec)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !name.starts_with(prefix) || !name.ends_with(".h5")) continue;
    bool listed = false;
    for (const Entry& k : entries_) listed = listed || fs::path(k.h5_relative).filename() == name;
    if (!listed) fs::remove(entry.path(), ec);
  }
  rewrite_xdmf();
}

std::size_t SnapshotWriter::bytes_per_particle() {
  std::size_t b = 0;
  for (const FieldSpec& f : kFields) b += static_cast<std::size_t>(f.precision * f.components);
  return b;
}

std::filesystem::path SnapshotWriter::xdmf_path() const {
  return dir_ / (base_ + ".xdmf");
}

std::filesystem::path SnapshotWriter::write(const SnapshotFields& fields) {
  SnapshotPieces pieces = begin(fields.time, fields.step, particle_count(fields, dir_));
  pieces.append(fields);
  return pieces.finish();
}

struct SnapshotPieces::Impl {
  SnapshotWriter* writer = nullptr;
  std::string relative;  // of the .h5 file, from the writer's folder
  fs::path path;
  double time = 0;
  std::int64_t step = 0;
  std::size_t n = 0, at = 0;  // particles in all, and written so far
  // Unfinished when destroyed (an error on the way), the file removes itself: a half-written
  // one would only mislead whoever opens the folder later.
  std::optional<h5::OutputFile> file;
  std::array<hid_t, kFields.size()> datasets{};  // kept by the file
};

SnapshotPieces::SnapshotPieces(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SnapshotPieces::SnapshotPieces(SnapshotPieces&&) noexcept = default;
SnapshotPieces::~SnapshotPieces() = default;

SnapshotPieces SnapshotWriter::begin(double time, std::int64_t step, std::size_t n) {
  const h5::SilenceErrors silence;
  auto impl = std::make_unique<SnapshotPieces::Impl>();
  impl->writer = this;
  impl->relative = fmt::format("snapshots/{}_{:06d}.h5", base_, entries_.size());
  impl->path = dir_ / impl->relative;
  impl->time = time, impl->step = step, impl->n = n;
  const fs::path& path = impl->path;
  h5::OutputFile& file = impl->file.emplace(path, "cannot create the HDF5 file");
  for (std::size_t i = 0; i < kFields.size(); ++i)
    impl->datasets[i] = create_dataset(file, kFields[i], n);
  write_scalar_attribute(file.get(), "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time, path);
  write_scalar_attribute(file.get(), "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &step, path);
  return SnapshotPieces(std::move(impl));
}

void SnapshotPieces::append(const SnapshotFields& s) {
  Impl& w = *impl_;
  const std::size_t m = particle_count(s, w.path);
  if (w.at + m > w.n) {
    throw Error(w.path.string(), fmt::format("snapshot pieces hold more than the {} particles "
                                             "announced",
                                             w.n));
  }
  const h5::SilenceErrors silence;
  // ParaView needs explicit Polyvertex connectivity (see the header); it is the one field
  // that is not in the caller's memory already.
  std::vector<std::int64_t> connectivity(m);
  std::iota(connectivity.begin(), connectivity.end(), static_cast<std::int64_t>(w.at));
  const std::array<const void*, kFields.size()> data = {
      connectivity.data(), s.position.data(), s.velocity.data(), s.density.data(),
      s.pressure.data(),   s.kind.data(),     s.id.data()};
  for (std::size_t i = 0; i < kFields.size(); ++i)
    write_rows(w.datasets[i], kFields[i], w.at, m, data[i], w.path);
  w.at += m;
}

std::filesystem::path SnapshotPieces::finish() {
  Impl& w = *impl_;
  if (w.at != w.n) {
    throw Error(w.path.string(),
                fmt::format("snapshot pieces hold {} particles, {} were announced", w.at, w.n));
  }
  // Closing writes the metadata: a full disk may show up here (the file is then removed).
  w.file->finish();
  // The snapshot is complete on disk, so it is listed even if the XDMF rewrite below fails:
  // the next successful rewrite then includes it.
  w.writer->entries_.push_back({w.relative, w.time, w.step, w.n});
  w.writer->rewrite_xdmf();
  return w.path;
}

void SnapshotWriter::rewrite_xdmf() const {
  fmt::memory_buffer out;
  auto it = std::back_inserter(out);
  fmt::format_to(it,
                 "<?xml version=\"1.0\" ?>\n"
                 "<Xdmf Version=\"3.0\">\n"
                 " <Domain>\n"
                 "  <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                 xml_escape(base_));
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    const std::string h5 = xml_escape(e.h5_relative);
    // Named after the snapshot index (unique even if a step number repeats); "{}" prints
    // the shortest text that reads back as the same double.
    fmt::format_to(it,
                   "   <Grid Name=\"snapshot_{:06d}\" GridType=\"Uniform\">\n"
                   "    <Time Value=\"{}\"/>\n",
                   i, e.time);
    for (const FieldSpec& f : kFields) {
      const std::string_view role = f.role;
      if (role == "Topology") {
        fmt::format_to(it,
                       "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" "
                       "NodesPerElement=\"1\">\n",
                       e.n);
      } else if (role == "Geometry") {
        fmt::format_to(it, "    <Geometry GeometryType=\"XYZ\">\n");
      } else {
        fmt::format_to(it, "    <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n",
                       f.name, f.role);
      }
      append_data_item(out, f, e.n, h5, 5);
      const char* close = role == "Topology"   ? "Topology"
                          : role == "Geometry" ? "Geometry"
                                               : "Attribute";
      fmt::format_to(it, "    </{}>\n", close);
    }
    fmt::format_to(it, "   </Grid>\n");
  }
  fmt::format_to(it,
                 "  </Grid>\n"
                 " </Domain>\n"
                 "</Xdmf>\n");
  write_file_atomic(xdmf_path(), std::string_view(out.data(), out.size()));
}

}  // namespace netsph
