#pragma once
// Log set-up: messages go to stderr and, for runs, also to <out>/log.txt so that the record of
// a run stays next to its results.
#include <filesystem>

namespace netsph::app {

void log_to_console(bool quiet);
/// append: keep what the file holds (a restart adds to the log of the run it continues). The
/// file's folder must exist (create_output_folder).
void log_also_to_file(const std::filesystem::path& file, bool append = false);

}  // namespace netsph::app
