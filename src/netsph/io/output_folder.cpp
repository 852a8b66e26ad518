#include "netsph/io/output_folder.hpp"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

namespace netsph {

namespace fs = std::filesystem;

void create_output_folder(const fs::path& dir, const std::string& where) {
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

bool holds_earlier_run(const fs::path& dir) {
  constexpr std::array<std::string_view, 6> kMarks = {
      "summary.json", "checkpoint.h5", "series.csv", "log.txt", "particles.xdmf", "snapshots"};
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return false;
  for (const std::string_view mark : kMarks) {
    if (fs::exists(dir / mark, ec)) return true;
  }
  return false;
}

std::optional<fs::path> move_earlier_run_aside(const fs::path& dir, const std::string& where) {
  if (!holds_earlier_run(dir.empty() ? fs::path(".") : dir)) return std::nullopt;
  std::error_code ec;
  const fs::path whole = fs::weakly_canonical(fs::absolute(dir.empty() ? fs::path(".") : dir), ec);
  const fs::path here = fs::current_path(ec);
  const auto refuse = [&](const std::string& why) {
    throw Error(where, fmt::format("{} holds an earlier run's results, and {}: give this run "
                                   "another folder with -o, or add --overwrite to replace them",
                                   dir.string(), why));
  };
  if (whole == here || !whole.has_parent_path() || whole == whole.parent_path() ||
      (!here.empty() && here.string().starts_with(whole.string() + "/"))) {
    refuse("netsph does not move the folder it is run from (or one above it) aside");
  }
  // The folder without a trailing separator, so that out/run/ moves to out/run.1.
  const fs::path base = whole;
  for (int n = 1; n < 100000; ++n) {
    const fs::path aside = fs::path(base.string() + "." + std::to_string(n));
    if (fs::exists(fs::symlink_status(aside, ec))) continue;
    // rename(2) on a name that exists would replace an empty folder: the check above and the
    // rename race only with another netsph started in the same second into the same folder.
    if (std::rename(base.c_str(), aside.c_str()) != 0) {
      refuse(fmt::format("it cannot be renamed to {} ({})", aside.string(), std::strerror(errno)));
    }
    // Named as the user named the folder: out/run -> out/run.1.
    fs::path shown = dir.empty() ? aside : fs::path(dir.lexically_normal().string());
    std::string text = shown.string();
    while (text.size() > 1 && text.back() == '/') text.pop_back();
    return fs::path(text + "." + std::to_string(n));
  }
  refuse("it already has 99999 numbered copies beside it");
  return std::nullopt;
}

}  // namespace netsph
