#pragma once
// Creating the folders a run writes into, with a message that says which and why when the
// system refuses (a file in the way, no permission, a read-only or missing mount), instead of
// the standard library's bare filesystem_error; and keeping an earlier run's results when a
// new run is given its folder.
#include <filesystem>
#include <optional>
#include <string>

namespace netsph {

/// Creates `dir` and its parents if missing. Throws netsph::Error at `where` (the option or
/// output that named it, e.g. "-o") naming the folder and the reason.
void create_output_folder(const std::filesystem::path& dir, const std::string& where);

/// Whether `dir` holds what a netsph run writes (summary.json, checkpoint.h5, series.csv,
/// log.txt, particles.xdmf or a snapshots/ folder): an earlier run's results, whole or not.
bool holds_earlier_run(const std::filesystem::path& dir);

/// A run never destroys an earlier run's results unasked (issue 46): when `dir` holds an
/// earlier run, the whole folder is renamed to `<dir>.<n>` (n = 1, 2, ...: the first number
/// free, so the numbers count up with age) and the new run gets `dir` afresh. Returns the
/// folder the earlier run now lies in, or nothing when `dir` held no run. A rename moves
/// nothing on disk and keeps every file of the folder, hand-made ones included. Throws
/// netsph::Error at `where` when the folder cannot be renamed (the working folder itself, a
/// mount point, no permission on its parent), saying how to go on (-o, or --overwrite).
std::optional<std::filesystem::path> move_earlier_run_aside(const std::filesystem::path& dir,
                                                            const std::string& where);

}  // namespace netsph
