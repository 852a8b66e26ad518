#pragma once
// `netsph validate`: the paper's validation cases (Shi et al. 2024, sections 3.1-3.4) run at the
// resolutions a CPU affords, compared with the paper's data and the experiments it cites
// (validation/reference_data.hpp), as a table of quantity, netsph, paper, experiment, error.
// Each entry is a small set of runs; --quick runs the subset that finishes in a few minutes
// (the net generator against the paper's stated sizes, the standalone net model against
// Table 3, and a coarse coupled run of the default net as a check of the whole chain).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace netsph {

struct ValidationRow {
  std::string entry;     ///< the entry that measured it
  std::string quantity;  ///< what, e.g. "drag at 0.226 m/s"
  std::string unit;      ///< "" for ratios and coefficients
  std::optional<double> netsph, paper, experiment;
  std::string note;  ///< how it was measured (resolution, window), or why it is missing
  /// (netsph - reference) / reference, the reference being the experiment when there is one,
  /// else the paper.
  std::optional<double> error() const;
};

struct ValidationOptions {
  bool quick = false;
  std::vector<std::string> only;  ///< entry names; empty: all (or all quick ones)
  std::filesystem::path out_dir = "out/validate";
  bool progress = true;
  /// Keep a run whose folder already holds a completed summary.json of the same built-in case
  /// and overrides (an interrupted `validate` picks up where it stopped). The case text is not
  /// compared: after changing a built-in case, run without --reuse.
  bool reuse = false;
};

/// What an entry's runs need: where to write, and whether to show progress.
struct ValidationContext {
  std::filesystem::path out_dir;  ///< the entry's own folder
  bool progress = true;
  bool reuse = false;  ///< see ValidationOptions::reuse
  /// Runs a built-in case (a cases/ path without .toml) with overrides into out_dir/<subdir>;
  /// returns its summary.json. Throws netsph::Error when the run does not complete.
  nlohmann::json run_case(const std::string& builtin, const std::vector<std::string>& overrides,
                          const std::string& subdir) const;
};

struct ValidationEntry {
  std::string name;
  std::string section;  ///< of the paper
  std::string title;
  bool quick = false;  ///< part of --quick
  double minutes = 0;  ///< wall time on a 2-core machine, about
  std::function<std::vector<ValidationRow>(const ValidationContext&)> run;
};

const std::vector<ValidationEntry>& validation_entries();

struct ValidationReport {
  std::vector<ValidationRow> rows;
  std::vector<std::string> entries_run;
  std::vector<std::string> failures;  ///< "entry: message" for entries whose runs failed
  double wall_s = 0;
};

/// Throws an Error naming --only and every entry when a name is not an entry's.
void check_entry_names(const std::vector<std::string>& only);

/// Throws netsph::Error for an unknown entry name in options.only.
ValidationReport run_validation(const ValidationOptions& options);

/// Markdown table (docs/VALIDATION.md uses the same).
std::string format_validation_table(const ValidationReport& report);
nlohmann::json validation_json(const ValidationReport& report);

}  // namespace netsph
