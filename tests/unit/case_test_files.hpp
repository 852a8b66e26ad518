#pragma once
// What the case-reader tests share: the folder of test case files, the smallest valid case
// (which tests extend with the keys they check), and a vector comparison.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "netsph/core/vec3.hpp"

namespace netsph::case_test {

/// tests/cases. NETSPH_TEST_CASES_DIR should name it; when it does not exist (the macro is
/// built from the CMake folder the test is registered in), use the folder beside this file's.
inline std::filesystem::path cases_dir() {
  const std::filesystem::path configured = NETSPH_TEST_CASES_DIR;
  std::error_code ec;
  if (std::filesystem::is_directory(configured / "bad", ec)) return configured;
  return std::filesystem::path(__FILE__).parent_path().parent_path() / "cases";
}

inline const std::filesystem::path kCasesDir = cases_dir();

/// The smallest valid case: a 1 m fluid cube at dp = 0.02 m for 1 s, defaults elsewhere.
inline const std::string kMinimal = R"(
[simulation]
dp = 0.02
end_time = 1.0

[[fill]]
min = [0, 0, 0]
max = [1, 1, 1]
)";

/// Component-wise equality to 1e-12 (exact arithmetic up to round-off), naming `what`.
inline void expect_near(const Vec3d& actual, const Vec3d& expected, const std::string& what) {
  constexpr double tol = 1e-12;
  EXPECT_NEAR(actual.x, expected.x, tol) << what;
  EXPECT_NEAR(actual.y, expected.y, tol) << what;
  EXPECT_NEAR(actual.z, expected.z, tol) << what;
}

}  // namespace netsph::case_test
