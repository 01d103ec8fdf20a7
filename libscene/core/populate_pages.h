// Pages of a big array faulted in ahead of its first writes, for the
// readers' parts.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace scene {

// Faults in, for writing, the whole pages within [begin, end) without
// writing a byte, where Linux offers MADV_POPULATE_WRITE (5.14 on): one
// call maps them all, at two thirds of the cost of faulting them in at
// their first writes on the machine measured (docs/history/PERFORMANCE.md,
// "Big scenes: bins, planes and pages"). Elsewhere, or where the call fails, it
// does nothing, and the writes fault the pages in as before.
inline void populatePagesForWriting(const void* begin, const void* end) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) & ~(page - 1);
  std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) & ~(page - 1);
  if (to > from) ::madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace scene
