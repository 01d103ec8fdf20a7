#include "renderer/huge_pages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace render {

bool adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (data == nullptr || bytes < kHugePageBytes) return false;
  // Only the huge pages wholly inside: advising past the array's ends would
  // change how memory that is not its own is backed.
  auto begin = reinterpret_cast<std::uintptr_t>(data);
  std::uintptr_t first = (begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  std::uintptr_t end = (begin + bytes) & ~(kHugePageBytes - 1);
  if (first >= end) return false;
  return madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE) == 0;
#else
  (void)data;
  (void)bytes;
  return false;
#endif
}

}  // namespace render
