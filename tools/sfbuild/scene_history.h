// The builder's undo and redo: whole scenes kept as values. A snapshot is
// cheap next to a person's pace (a scene is a few vectors), and a value
// cannot go stale the way a list of inverse operations can.
#pragma once

#include <cstddef>
#include <vector>

#include "scenefile/scene.h"

namespace sfbuild {

// The most changes that can be undone; older ones are forgotten.
inline constexpr std::size_t kHistoryLength = 100;

class SceneHistory {
 public:
  SceneHistory() = default;
  explicit SceneHistory(scene::Scene committed) : committed_(std::move(committed)) {}

  // Takes `current` as the next step when it differs from the last one.
  // Changes of the camera alone that follow each other (a look around with
  // the mouse, the wheel) make one step, so that undo does not walk back
  // through every pixel of a drag.
  void record(const scene::Scene& current);
  // The scene before the last step (the one after it for redo), or nothing
  // when there is none; `current` is what the builder shows now.
  const scene::Scene* undo();
  const scene::Scene* redo();

  const scene::Scene& committed() const { return committed_; }

 private:
  std::vector<scene::Scene> undo_, redo_;
  scene::Scene committed_;
  bool lastWasCameraOnly_ = false;
};

}  // namespace sfbuild
