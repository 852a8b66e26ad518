#pragma once
// Creating the folders a run writes into, with a message that says which and why when the
// system refuses (a file in the way, no permission, a read-only or missing mount), instead of
// the standard library's bare filesystem_error.
#include <filesystem>
#include <string>

namespace netsph {

/// Creates `dir` and its parents if missing. Throws netsph::Error at `where` (the option or
/// output that named it, e.g. "-o") naming the folder and the reason.
void create_output_folder(const std::filesystem::path& dir, const std::string& where);

}  // namespace netsph
