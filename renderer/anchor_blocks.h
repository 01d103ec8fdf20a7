// Which bounded objects may show between adaptive sampling's anchors
// (CornerInterpolation): for each block of span x span pixels whose corners
// are anchors (span 2), or coarse anchors (span 4), the objects whose world
// boxes, seen from the eye, reach it. A corner between anchors that saw one
// object is their mean only where no other object reaches its block, so
// that an object narrower than the anchors' spacing is traced, not lost.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/camera.h"
#include "renderer/huge_pages.h"
#include "renderer/render_scene.h"

namespace render {

class AnchorBlocks {
 public:
  // The blocks of `span` x `span` pixels (span 2 or more) of a fullWidth x
  // fullHeight image seen through `camera`.
  AnchorBlocks(const RenderScene& scene, const PinholeCamera& camera, int fullWidth, int fullHeight,
               int span = 2);

  // Whether no bounded object but `object` (RaySource::kNone: none at all)
  // reaches the square or side between the anchors of corner (x, y), a
  // corner inside the image with a coordinate off the span's multiples.
  bool onlyShows(int x, int y, std::uint32_t object) const {
    int i = x / span_, j = y / span_;
    // A corner on a block's side: the block below or right of that side
    // holds the side whole, the last block of the image its far side.
    i = i < columns_ ? i : columns_ - 1;
    j = j < rows_ ? j : rows_ - 1;
    const Block& block = blocks_[static_cast<std::size_t>(j) * columns_ + i];
    return block.count == 0 || (block.count == 1 && block.object == object);
  }

  // What the blocks of span x span pixels of a fullWidth x fullHeight image
  // take, in bytes.
  static std::uint64_t bytesFor(int fullWidth, int fullHeight, int span = 2);

 private:
  // How many objects reach a block (2: two or more), and the least.
  struct Block {
    std::uint32_t count = 0;
    std::uint32_t object = RaySource::kNone;
  };
  int span_;
  int columns_, rows_;
  std::vector<Block, HugePageAllocator<Block>> blocks_;

  void mark(int i0, int i1, int j0, int j1, std::uint32_t object);
};

}  // namespace render
