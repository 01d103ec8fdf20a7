#include "tools/common/resource_guard.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <sstream>
#include <system_error>

#include "tools/common/exit_code.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

TEST(ResourceGuard, OutOfMemoryAndThreadsAreMessagesAndAnExitCode) {
  std::ostringstream err;
  Stage stage;
  stage.set("reading big.txt");
  EXPECT_EQ(runGuarded("sfcheck", err, stage, []() -> int { throw std::bad_alloc(); }),
            toInt(ExitCode::OutOfResources));
  EXPECT_EQ(err.str(), "sfcheck: error: out of memory while reading big.txt\n");
  err.str("");
  stage.set("starting 1024 threads");
  EXPECT_EQ(runGuarded("sfrender", err, stage,
                       []() -> int {
                         throw std::system_error(
                             std::make_error_code(std::errc::resource_unavailable_try_again));
                       }),
            toInt(ExitCode::OutOfResources));
  EXPECT_EQ(err.str(),
            "sfrender: error: starting 1024 threads: Resource temporarily unavailable\n");
  err.str("");
  EXPECT_EQ(runGuarded("sfconvert", err, stage,
                       []() -> int {
                         throw fs::filesystem_error(
                             "x", "/some/file", std::make_error_code(std::errc::permission_denied));
                       }),
            toInt(ExitCode::IoError));
  EXPECT_EQ(err.str(), "sfconvert: error: /some/file: Permission denied\n");
  EXPECT_EQ(runGuarded("sfcheck", err, stage, [] { return 1; }), 1);
}

}  // namespace
}  // namespace tools
