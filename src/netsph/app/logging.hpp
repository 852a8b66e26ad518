#pragma once
// Log set-up: messages go to stderr and, for runs, also to <out>/log.txt so that the record of
// a run stays next to its results.
#include <filesystem>

namespace netsph::app {

void log_to_console(bool quiet);
void log_also_to_file(const std::filesystem::path& file);

}  // namespace netsph::app
