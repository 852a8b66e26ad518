#include "netsph/io/csv_series.hpp"

#include <fstream>
#include <utility>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <string_view>

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

CsvSeries::CsvSeries(std::filesystem::path file, std::vector<CsvColumn> columns)
    : file_(std::move(file)), columns_(std::move(columns)) {
  fp_ = std::fopen(file_.c_str(), "w");
  if (fp_ == nullptr) {
    throw Error(file_.string(), std::string("cannot create the CSV file: ") + std::strerror(errno));
  }
  const std::string header = header_row(columns_);
  if (std::fwrite(header.data(), 1, header.size(), fp_) != header.size() || std::fflush(fp_) != 0) {
    const int err = errno;
    std::fclose(fp_);
    fp_ = nullptr;
    throw Error(file_.string(), std::string("cannot write the CSV header: ") + std::strerror(err));
  }
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
  // time may read a little later than it: 1e-8 relative keeps it.
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const double t = std::strtod(line.c_str(), nullptr);
    if (t <= resume_time * (1 + 1e-8)) kept += line + "\n";
  }
  in.close();
  fp_ = std::fopen(file_.c_str(), "w");
  if (fp_ == nullptr || std::fwrite(kept.data(), 1, kept.size(), fp_) != kept.size() ||
      std::fflush(fp_) != 0) {
    throw Error(file_.string(),
                std::string("cannot rewrite the CSV file: ") + std::strerror(errno));
  }
}

CsvSeries& CsvSeries::operator=(CsvSeries&& o) noexcept {
  if (this != &o) {
    if (fp_ != nullptr) std::fclose(fp_);
    file_ = std::move(o.file_);
    columns_ = std::move(o.columns_);
    fp_ = std::exchange(o.fp_, nullptr);
  }
  return *this;
}

CsvSeries::~CsvSeries() {
  if (fp_ != nullptr) std::fclose(fp_);
}

void CsvSeries::append(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw Error(file_.string(), "a CSV row has " + std::to_string(values.size()) +
                                    " values but the file has " + std::to_string(columns_.size()) +
                                    " columns");
  }
  // One fwrite + fflush per row: the row reaches the OS whole, so a run that dies (or a
  // reader that tails the file) never sees a partial row.
  std::string row;
  row.reserve(values.size() * 16);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) row += ',';
    append_value(row, values[i]);
  }
  row += '\n';
  if (std::fwrite(row.data(), 1, row.size(), fp_) != row.size() || std::fflush(fp_) != 0) {
    throw Error(file_.string(), std::string("cannot write a CSV row: ") + std::strerror(errno));
  }
}

}  // namespace netsph
