// Big arrays on 2 MiB pages where Linux offers them, for the passes of the
// build that read them out of order.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace render {

// The size of a transparent huge page on x86-64 and most arm64 kernels.
inline constexpr std::uintptr_t kHugePageBytes = std::uintptr_t{1} << 21;

// Asks that the whole 2 MiB pages within [begin, end) be huge pages
// (MADV_HUGEPAGE, which Linux heeds where transparent huge pages are set to
// "madvise" or "always"): room not yet written then faults in a huge page at
// a time (a 512th of the faults), and a read anywhere in it takes one TLB
// entry rather than 512. Pages already written stay as they are: moving
// them (MADV_COLLAPSE) took seconds for a gigabyte. Elsewhere, or where the
// call fails, it does nothing.
// (libscene's readers have their own copy, in libscene/core/populate_pages.h,
// a header private to the library that the renderer does not include.)
inline void adviseHugePages(const void* begin, const void* end) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  std::uintptr_t from =
      (reinterpret_cast<std::uintptr_t>(begin) + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) & ~(kHugePageBytes - 1);
  if (to <= from) return;
  ::madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace render
