#pragma once
// Putting a finished file in place of another so that a crash of the machine (power, kernel)
// leaves one of the two whole: the new file's data is synced to the disk before the rename,
// and the folder after it, so that the rename itself is on the disk.
#include <filesystem>

namespace netsph {

/// Syncs `file` to the disk (fsync). Throws netsph::Error naming it and the OS's reason.
void sync_file(const std::filesystem::path& file);

/// Syncs `from`, renames it to `to` (replacing it), syncs their folder. Throws netsph::Error
/// naming `to` when the sync or the rename fails; `from` is then removed, `to` unchanged.
void replace_file_durably(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace netsph
