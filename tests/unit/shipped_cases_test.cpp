// The case files shipped under cases/ (paper cases included) must all be valid: a user
// running one must never meet a reader error.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "netsph/case/case_reader.hpp"

namespace netsph {
namespace {

TEST(ShippedCases, EveryCaseFileUnderCasesIsValid) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(NETSPH_CASES_DIR))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  ASSERT_GE(files.size(), 20u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    EXPECT_NO_THROW((void)read_case_file(f.string()));
  }
}

}  // namespace
}  // namespace netsph
