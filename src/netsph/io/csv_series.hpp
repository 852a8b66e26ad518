#pragma once
// A time series written as CSV: a header row "name [unit],..." and one row per append().
// Each row is written at once, whole, so that a run that dies keeps every row written before;
// a row that cannot be written whole (a full disk, a quota, a file size limit) is cut off
// again, so the file never ends in half a row.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace netsph {

struct CsvColumn {
  std::string name;  ///< e.g. "time"
  std::string unit;  ///< e.g. "s"; empty for dimensionless counts -> header "step"
};

class CsvSeries {
 public:
  /// Creates (truncates) the file and writes the header. Throws netsph::Error on failure.
  CsvSeries(std::filesystem::path file, std::vector<CsvColumn> columns);
  /// A restarted run: keeps the existing file's rows whose first value (the time) is at most
  /// `resume_time` (rows a run wrote after its last checkpoint are dropped) and appends after
  /// them. The header must be the one `columns` makes (or had before a unit was relabelled:
  /// the file then gets the new labels); a missing file starts a new one.
  CsvSeries(std::filesystem::path file, std::vector<CsvColumn> columns, double resume_time);
  ~CsvSeries();
  CsvSeries(const CsvSeries&) = delete;
  CsvSeries& operator=(const CsvSeries&) = delete;
  CsvSeries& operator=(CsvSeries&& o) noexcept;

  /// One row; values.size() must equal the column count (netsph::Error otherwise).
  /// Integers are printed without a decimal point, others with 9 significant digits. A row
  /// the system does not take whole is truncated away (the file keeps its complete rows) and
  /// throws netsph::Error naming the file and the reason.
  void append(std::span<const double> values);

  const std::filesystem::path& path() const { return file_; }

 private:
  /// Writes `text` at the end of the file, whole or not at all (truncating back on failure).
  void write_whole(const std::string& text, const char* what);

  std::filesystem::path file_;
  std::vector<CsvColumn> columns_;
  int fd_ = -1;
  std::uintmax_t complete_ = 0;  ///< bytes of the file up to its last complete row
};

}  // namespace netsph
