// An allocator whose vectors leave the elements that resize() adds unset,
// for arrays of records that their builder writes in full on several
// threads: a vector that value-initialises them writes each one on the
// resizing thread first, a pass over fresh memory that cost as much as
// making the records (RenderSceneBuilder::add).
#pragma once

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace render {

template <typename T>
class UnsetAllocator : public std::allocator<T> {
 public:
  template <typename U>
  struct rebind {
    using other = UnsetAllocator<U>;
  };

  UnsetAllocator() = default;
  template <typename U>
  UnsetAllocator(const UnsetAllocator<U>&) noexcept {}

  // No initialisation: allowed for these types alone, whose objects the
  // allocated storage holds as soon as it is written (implicit lifetime).
  template <typename U>
  void construct(U*) noexcept {
    static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>);
  }
  template <typename U, typename... Args>
  void construct(U* at, Args&&... args) {
    ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
  }
};

// A vector whose resize() leaves the new elements unset: whoever resizes it
// writes every one of them before any is read.
template <typename T>
using UnsetVector = std::vector<T, UnsetAllocator<T>>;

}  // namespace render
