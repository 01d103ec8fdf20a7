#include "tools/common/resource_guard.h"

#include <filesystem>
#include <new>
#include <system_error>

#include "tools/common/diagnostic_printer.h"
#include "tools/common/exit_code.h"

namespace tools {

int runGuarded(const char* tool, std::ostream& err, const Stage& stage,
               const std::function<int()>& body) {
  // Each handler writes pieces that exist already: the memory that was
  // missing may still be missing. A message that cannot be written at all
  // leaves the exit status to tell.
  try {
    return body();
  } catch (const std::bad_alloc&) {
    try {
      err << tool << ": error: out of memory while " << stage.what() << "\n";
    } catch (...) {
    }
    return toInt(ExitCode::OutOfResources);
  } catch (const std::filesystem::filesystem_error& e) {
    try {
      err << tool << ": error: " << printableText(e.path1().string()) << ": " << e.code().message()
          << "\n";
    } catch (...) {
    }
    return toInt(ExitCode::IoError);
  } catch (const std::system_error& e) {
    try {
      err << tool << ": error: " << stage.what() << ": " << e.code().message() << "\n";
    } catch (...) {
    }
    return toInt(ExitCode::OutOfResources);
  }
}

}  // namespace tools
