#include "tools/common/resource_guard.h"

#include <sys/mman.h>

#include <array>
#include <exception>
#include <filesystem>
#include <new>
#include <system_error>

#include "tools/common/diagnostic_printer.h"
#include "tools/common/exit_code.h"

namespace tools {

namespace {

// Memory kept back for the way out. Destructors that run while a
// std::bad_alloc unwinds may allocate themselves (nlohmann::json frees a
// large document through a stack it reserves first), and an exception from
// a destructor then is std::terminate. So an allocation that fails while an
// exception is in flight releases a part of this reserve and is tried
// again; one that fails otherwise throws at once and leaves the reserve
// whole (a library may catch that std::bad_alloc and go on: tinygltf does).
// Only address space until then (it is never touched): 8 parts of 16 MiB;
// a million-node JSON array's stack is 16 MB. Mapped, not allocated: a
// sanitizer's allocator would poison and fill 128 MiB of it at every start
// and end of a tool, which was most of a sanitized tool's start-up.
constexpr std::size_t kReserveParts = 8;
constexpr std::size_t kReservePartBytes = std::size_t{16} << 20;
std::array<void*, kReserveParts> reserve{};

void unmapReservePart(void*& part) {
  ::munmap(part, kReservePartBytes);
  part = nullptr;
}

void releaseReserveOrThrow() {
  if (std::uncaught_exceptions() > 0) {
    for (void*& part : reserve) {
      if (part) {
        unmapReservePart(part);
        return;  // operator new tries again
      }
    }
  }
  throw std::bad_alloc();
}

// Holds the reserve and the handler for the length of one run.
class MemoryReserve {
 public:
  MemoryReserve() {
    for (void*& part : reserve) {
      if (part) continue;
      void* mapped = ::mmap(nullptr, kReservePartBytes, PROT_READ | PROT_WRITE,
                            MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
      part = mapped == MAP_FAILED ? nullptr : mapped;
    }
    previous_ = std::set_new_handler(&releaseReserveOrThrow);
  }
  ~MemoryReserve() {
    std::set_new_handler(previous_);
    for (void*& part : reserve) {
      if (part) unmapReservePart(part);
    }
  }
  MemoryReserve(const MemoryReserve&) = delete;
  MemoryReserve& operator=(const MemoryReserve&) = delete;

 private:
  std::new_handler previous_ = nullptr;
};

}  // namespace

int runGuarded(const char* tool, std::ostream& err, const Stage& stage,
               const std::function<int()>& body) {
  MemoryReserve kept;
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
