#include "netsph/io/output_folder.hpp"

#include <system_error>

#include "netsph/core/error.hpp"

namespace netsph {

void create_output_folder(const std::filesystem::path& dir, const std::string& where) {
  namespace fs = std::filesystem;
  if (dir.empty()) return;  // the working folder
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw Error(where, dir.string() + " is a file, not a folder: give a folder for the outputs");
  }
  fs::create_directories(dir, ec);
  if (ec) {
    throw Error(where, "cannot create the output folder " + dir.string() + ": " + ec.message() +
                           "; give a folder you can write to");
  }
}

}  // namespace netsph
