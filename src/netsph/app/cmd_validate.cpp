// `netsph validate [--quick] [--only NAME,...] [--list] [--json FILE] [-o DIR]`: runs the paper's
// validation cases (validation/validation.hpp) and prints the comparison table.
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/io/atomic_file.hpp"
#include "netsph/io/output_folder.hpp"
#include "netsph/validation/validation.hpp"

namespace netsph::app {

int validate_command(const ValidateArgs& args) {
  if (args.list) {
    check_entry_names(args.only);  // --list --only a,b lists those two
    for (const ValidationEntry& e : validation_entries()) {
      if (!args.only.empty() &&
          std::find(args.only.begin(), args.only.end(), e.name) == args.only.end())
        continue;
      fmt::print("{:<22} section {:<9} {:>5.0f} min  {}{}\n", e.name, e.section, e.minutes, e.title,
                 e.quick ? "  [quick]" : "");
    }
    return 0;
  }
  apply_threads(args.threads);
  ValidationOptions o;
  o.quick = args.quick;
  o.only = args.only;
  o.out_dir = args.out_dir;
  o.progress = !args.quiet;
  o.reuse = args.reuse;
  // Before any entry runs: an unwritable folder would otherwise fail after hours of runs.
  create_output_folder(args.out_dir, "-o");
  const ValidationReport report = run_validation(o);
  const std::string table = format_validation_table(report);
  fmt::print("\n{}\n", table);
  spdlog::info("validate: {} entr{} in {:.1f} min; run folders under {}", report.entries_run.size(),
               report.entries_run.size() == 1 ? "y" : "ies", report.wall_s / 60,
               std::filesystem::absolute(args.out_dir).string());
  write_file_atomic(std::filesystem::path(args.out_dir) / "validation.md", table);
  if (!args.json_path.empty()) {
    write_file_atomic(args.json_path, validation_json(report).dump(2) + "\n");
    spdlog::info("validate: table written to {}", args.json_path);
  }
  for (const std::string& f : report.failures) spdlog::error("validate: {}", f);
  return report.failures.empty() ? 0 : 3;
}

}  // namespace netsph::app
