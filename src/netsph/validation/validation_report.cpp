// The validation table: markdown for the terminal and docs/VALIDATION.md, JSON for scripts.
#include <cmath>

#include <fmt/format.h>

#include "netsph/validation/validation.hpp"

namespace netsph {

std::optional<double> ValidationRow::error() const {
  const std::optional<double> ref = experiment ? experiment : paper;
  if (!netsph || !ref || *ref == 0) return {};
  return (*netsph - *ref) / *ref;
}

namespace {

std::string cell(const std::optional<double>& v) {
  return v ? fmt::format("{:.4g}", *v) : std::string("-");
}

}  // namespace

std::string format_validation_table(const ValidationReport& report) {
  std::string out =
      "| entry | quantity | unit | netsph | paper | experiment | error | how |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const ValidationRow& r : report.rows) {
    const std::optional<double> e = r.error();
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.entry, r.quantity, r.unit,
                       cell(r.netsph), cell(r.paper), cell(r.experiment),
                       e ? fmt::format("{:+.1f}%", 100 * *e) : std::string("-"), r.note);
  }
  return out;
}

nlohmann::json validation_json(const ValidationReport& report) {
  nlohmann::json j;
  j["entries_run"] = report.entries_run;
  j["failures"] = report.failures;
  j["wall_s"] = report.wall_s;
  nlohmann::json rows = nlohmann::json::array();
  for (const ValidationRow& r : report.rows) {
    nlohmann::json row;
    row["entry"] = r.entry;
    row["quantity"] = r.quantity;
    row["unit"] = r.unit;
    const auto put = [&](const char* key, const std::optional<double>& v) {
      row[key] = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    put("netsph", r.netsph);
    put("paper", r.paper);
    put("experiment", r.experiment);
    put("error", r.error());
    row["note"] = r.note;
    rows.push_back(row);
  }
  j["rows"] = rows;
  return j;
}

}  // namespace netsph
