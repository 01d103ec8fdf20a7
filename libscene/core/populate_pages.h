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

// Asks that the whole 2 MiB pages within [begin, end) be huge pages
// (MADV_HUGEPAGE, heeded where transparent huge pages are set to "madvise"
// or "always"), for a big array not yet written: it then faults in a huge
// page at a time, and a pass over it takes a 512th of the TLB entries. On a
// guest whose host maps its memory in a shadow page table, each 4 KiB page
// first written costs microseconds. Elsewhere, or where the call fails, it
// does nothing.
// (The renderer, which includes only the public headers, has its own
// copy: renderer/huge_pages.h.)
inline void adviseHugePages(const void* begin, const void* end) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(begin) + kHuge - 1) & ~(kHuge - 1);
  std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) & ~(kHuge - 1);
  if (to > from) ::madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace scene
