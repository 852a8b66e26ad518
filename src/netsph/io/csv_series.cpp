#include "netsph/io/csv_series.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <utility>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

namespace netsph {
namespace {

// RFC 4180 quoting, only when a header cell needs it: plain names stay readable and
// pandas / ParaView still split a name such as "force, x" correctly.
std::string csv_cell(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string header_row(const std::vector<CsvColumn>& columns) {
  std::string row;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) row += ',';
    const CsvColumn& c = columns[i];
    row += csv_cell(c.unit.empty() ? c.name : c.name + " [" + c.unit + "]");
  }
  row += '\n';
  return row;
}

// Counts (steps, ids, particle numbers) are stored as doubles but read best as integers;
// 2^53 is where doubles stop representing every integer, so larger values keep %.9g.
void append_value(std::string& row, double v) {
  // Spelled out because glibc prints "-nan" for some NaNs, and readers expect "nan".
  if (std::isnan(v)) {
    row += "nan";
    return;
  }
  if (std::isinf(v)) {
    row += v > 0 ? "inf" : "-inf";
    return;
  }
  char buf[40];
  int len;
  if (std::fabs(v) < 9007199254740992.0 && v == std::floor(v)) {
    len = std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
  } else {
    len = std::snprintf(buf, sizeof buf, "%.9g", v);
  }
  row.append(buf, static_cast<std::size_t>(len));
}

// Units whose label changed while the numbers did not: {label now, label before}. A file
// written under the old label continues under the new one. 2026-12-03: a 2D case's forces
// and moments, always per metre of depth, were labelled N and N m; now N/m and N.
constexpr std::pair<std::string_view, std::string_view> kRelabelledUnits[] = {{"N/m", "N"},
                                                                              {"N", "N m"}};

/// The header `columns` had under the old unit labels.
std::string header_before_relabelling(std::vector<CsvColumn> columns) {
  for (CsvColumn& c : columns) {
    for (const auto& [now, before] : kRelabelledUnits) {
      if (c.unit == now) {
        c.unit = before;
        break;
      }
    }
  }
  return header_row(columns);
}

}  // namespace

namespace {
int create_file(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw Error(file.string(), std::string("cannot create the CSV file: ") + std::strerror(errno));
  }
  return fd;
}
}  // namespace

void CsvSeries::write_whole(const std::string& text, const char* what) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      // Cut the part written off again: the file ends after its last complete row.
      const bool cut = ::ftruncate(fd_, static_cast<off_t>(complete_)) == 0 &&
                       ::lseek(fd_, static_cast<off_t>(complete_), SEEK_SET) >= 0;
      throw Error(file_.string(),
                  fmt::format("cannot write {}: {}{}", what, std::strerror(err),
                              cut ? " (the file keeps its complete rows)"
                                  : " (and the part written could not be cut off)"));
    }
    done += static_cast<std::size_t>(n);
  }
  complete_ += text.size();
}

CsvSeries::CsvSeries(std::filesystem::path file, std::vector<CsvColumn> columns)
    : file_(std::move(file)), columns_(std::move(columns)) {
  fd_ = create_file(file_);
  write_whole(header_row(columns_), "the CSV header");
}

CsvSeries::CsvSeries(std::filesystem::path file, std::vector<CsvColumn> columns, double resume_time)
    : file_(std::move(file)), columns_(std::move(columns)) {
  std::ifstream in(file_);
  if (!in) {
    *this = CsvSeries(file_, columns_);  // nothing to resume: a new file
    return;
  }
  std::string line, kept;
  std::getline(in, line);
  const std::string header = header_row(columns_);
  if (line + "\n" != header && line + "\n" != header_before_relabelling(columns_)) {
    throw Error(file_.string(),
                "cannot continue this CSV file: its columns differ from the "
                "run's (was it written by another case?)");
  }
  kept = header;  // an old file's labels are brought up to date
  // Times are printed with 9 significant digits, so a row written at the checkpoint's own
  // time may read a little later than it: 1e-8 relative keeps it. A last line without its
  // newline (a row cut short by a version that left half rows) is dropped.
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (in.eof()) break;  // no newline after it: not a complete row
    const double t = std::strtod(line.c_str(), nullptr);
    if (t <= resume_time * (1 + 1e-8)) kept += line + "\n";
  }
  in.close();
  fd_ = create_file(file_);
  write_whole(kept, "the CSV file's kept rows");
}

CsvSeries& CsvSeries::operator=(CsvSeries&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    file_ = std::move(o.file_);
    columns_ = std::move(o.columns_);
    fd_ = std::exchange(o.fd_, -1);
    complete_ = o.complete_;
  }
  return *this;
}

CsvSeries::~CsvSeries() {
  if (fd_ >= 0) ::close(fd_);
}

void CsvSeries::append(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw Error(file_.string(), "a CSV row has " + std::to_string(values.size()) +
                                    " values but the file has " + std::to_string(columns_.size()) +
                                    " columns");
  }
  // One write per row, unbuffered: the row reaches the OS whole, so a run that dies (or a
  // reader that tails the file) never sees a partial row; one the OS takes only in part is
  // cut off again (write_whole).
  std::string row;
  row.reserve(values.size() * 16);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) row += ',';
    append_value(row, values[i]);
  }
  row += '\n';
  write_whole(row, "a CSV row");
}

}  // namespace netsph
