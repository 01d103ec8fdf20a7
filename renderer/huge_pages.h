// Large arrays on 2 MiB pages (Linux transparent huge pages), for the
// arrays that rays read at random: the objects' records, the BVH and the
// direction grids. Over tens of megabytes, 4 KiB pages miss the TLB on most
// reads, and each miss costs a page walk (a walk of two page tables, the
// guest's and the host's, under a virtual machine); 2 MiB pages also take a
// 512th of the page faults to fill.
//
// Where the kernel gives huge pages only to memory that asks for them
// (transparent_hugepage "madvise", as on the Debian machines here), the
// arrays ask with madvise(MADV_HUGEPAGE) before their first write. Nothing
// else changes: where the kernel says no, or on another system, the pages
// stay small and the contents are the same.
#pragma once

#include <cstddef>
#include <vector>

namespace render {

/// The size of a huge page, and the least array worth advising.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Asks the kernel for huge pages for the whole 2 MiB pages within
/// [data, data + bytes); true where it agreed to (which does not promise
/// that every page will be huge). Does nothing, and answers false, for
/// fewer than kHugePageBytes bytes or where the system has no such advice.
bool adviseHugePages(void* data, std::size_t bytes);

/// Reserves room for `capacity` elements in `v`, that storage advised onto
/// huge pages before anything is written to it. Only an empty vector's new
/// storage is advised: one already holding elements is reserved as it is.
template <class T>
void reserveOnHugePages(std::vector<T>& v, std::size_t capacity) {
  bool fresh = v.empty() && v.capacity() < capacity;
  v.reserve(capacity);
  if (fresh) adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

/// Sizes `v` to `count` value-initialized elements, on storage reserved by
/// reserveOnHugePages.
template <class T>
void resizeOnHugePages(std::vector<T>& v, std::size_t count) {
  reserveOnHugePages(v, count);
  v.resize(count);
}

}  // namespace render
