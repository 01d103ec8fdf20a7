// Big arrays on 2 MiB pages where Linux offers them: for the passes of the
// build that read them out of order, and for a render's buffers, whose
// first writes then fault in a 512th of the pages.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace render {

// The size of a transparent huge page on x86-64 and most arm64 kernels.
inline constexpr std::uintptr_t kHugePageBytes = std::uintptr_t{1} << 21;

// Whether adviseHugePages can ask for huge pages here.
#if defined(__linux__) && defined(MADV_HUGEPAGE)
inline constexpr bool kHugePagesAdvised = true;
#else
inline constexpr bool kHugePagesAdvised = false;
#endif

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

// An allocator for big arrays written once, such as a render's sample
// buffers: from half a huge page on, the room is whole huge pages from a
// huge page's boundary, and those the array fills at least half of are
// advised (adviseHugePages). An array of 1.8 MB then faults in one 2 MiB
// page where an allocation anywhere would fault in 450 small ones (on a
// guest whose host maps its memory in a shadow page table, each costs
// microseconds), and a last page less than half used stays small pages,
// so no more than half a huge page is ever cleared for nothing. Smaller
// arrays, and every array where huge pages cannot be asked for (the web
// page's WebAssembly, whose memory an alignment would only waste), are
// std::allocator's.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  explicit HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (!onHugePages(bytes)) return std::allocator<T>().allocate(n);
    char* room = static_cast<char*>(::operator new(roomFor(bytes), kAlignment));
    adviseHugePages(room, room + (bytes + kHugePageBytes / 2) / kHugePageBytes * kHugePageBytes);
    return reinterpret_cast<T*>(room);
  }
  void deallocate(T* room, std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (!onHugePages(bytes)) {
      std::allocator<T>().deallocate(room, n);
      return;
    }
    ::operator delete(room, kAlignment);
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }

 private:
  static constexpr std::align_val_t kAlignment{kHugePageBytes};
  static bool onHugePages(std::size_t bytes) {
    return kHugePagesAdvised && bytes >= kHugePageBytes / 2;
  }
  static std::size_t roomFor(std::size_t bytes) {
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  }
};

}  // namespace render
