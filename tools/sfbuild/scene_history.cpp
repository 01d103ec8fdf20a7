#include "tools/sfbuild/scene_history.h"

namespace sfbuild {
namespace {

bool differsInCameraOnly(const scene::Scene& a, const scene::Scene& b) {
  scene::Scene withCamera = a;
  withCamera.camera = b.camera;
  return withCamera == b;
}

}  // namespace

void SceneHistory::record(const scene::Scene& current) {
  if (current == committed_) return;
  bool cameraOnly = differsInCameraOnly(current, committed_);
  if (!(cameraOnly && lastWasCameraOnly_)) {
    undo_.push_back(std::move(committed_));
    if (undo_.size() > kHistoryLength) undo_.erase(undo_.begin());
  }
  lastWasCameraOnly_ = cameraOnly;
  redo_.clear();
  committed_ = current;
}

const scene::Scene* SceneHistory::undo() {
  if (undo_.empty()) return nullptr;
  redo_.push_back(std::move(committed_));
  committed_ = std::move(undo_.back());
  undo_.pop_back();
  lastWasCameraOnly_ = false;
  return &committed_;
}

const scene::Scene* SceneHistory::redo() {
  if (redo_.empty()) return nullptr;
  undo_.push_back(std::move(committed_));
  committed_ = std::move(redo_.back());
  redo_.pop_back();
  lastWasCameraOnly_ = false;
  return &committed_;
}

}  // namespace sfbuild
