// The builder's Dear ImGui windows: the key list, the scene (camera, lights,
// objects, with selection), the selection's properties as exact numbers,
// and a status line. Every edit goes through builder_state's setters, so
// that it is a step of the undo history. Needs a current ImGui frame.
#pragma once

#include <array>

#include "tools/sfbuild/builder_state.h"

namespace sfbuild {

class Panels {
 public:
  // `files` serves the file name prompt of Ctrl+S and Ctrl+O.
  void draw(BuilderState& state, const FileSystem& files);

 private:
  void drawScene(BuilderState& state, float top);
  void drawProperties(BuilderState& state, float top);
  void drawHelp(BuilderState& state);
  void drawStatus(const BuilderState& state);
  void drawFilePrompt(BuilderState& state, const FileSystem& files);
  // The camera has no place in BuilderState::selection (it cannot be moved
  // with G or deleted), so whether its properties show is the panel's.
  bool cameraShown_ = false;
  // The name typed into the prompt; each prompt starts empty.
  std::array<char, 1024> fileName_{};
  bool promptFocused_ = false;
};

}  // namespace sfbuild
