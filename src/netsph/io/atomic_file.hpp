#pragma once
// Writes a whole text file so that readers never see half of it: write to a temporary file
// in the same folder, then rename over the target.
#include <filesystem>
#include <string_view>

namespace netsph {

/// Throws netsph::Error (naming the path and the OS error) on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

}  // namespace netsph
