#include "renderer/bvh_node.h"

#include <cstdlib>
#include <cstring>
#include <new>

namespace render {

BvhNodes::BvhNodes(std::size_t room) {
  if (room == 0) return;
  data_ = static_cast<BvhNode*>(std::malloc(room * sizeof(BvhNode)));
  if (!data_) throw std::bad_alloc();
  size_ = room;
}

BvhNodes::BvhNodes(const BvhNodes& other) : BvhNodes(other.size_) {
  if (size_ > 0) std::memcpy(data_, other.data_, size_ * sizeof(BvhNode));
}

BvhNodes& BvhNodes::operator=(const BvhNodes& other) {
  if (this != &other) *this = BvhNodes(other);
  return *this;
}

BvhNodes& BvhNodes::operator=(BvhNodes&& other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  return *this;
}

BvhNodes::~BvhNodes() {
  std::free(data_);
}

void BvhNodes::shrink(std::size_t size) {
  if (size >= size_) return;
  if (size == 0) {
    *this = BvhNodes();
    return;
  }
  // Smaller: realloc cannot fail, and where the room was mapped apart
  // (a large one) it unmaps the rest rather than copying.
  if (void* smaller = std::realloc(data_, size * sizeof(BvhNode))) {
    data_ = static_cast<BvhNode*>(smaller);
  }
  size_ = size;
}

}  // namespace render
