// Where a scene's image goes when -o does not say, for one scene and, read
// ahead, for every scene of a batch.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/read.h"

namespace tools {

struct ImageTarget {
  std::filesystem::path path;
  bool fromOutputFile = false;  // the scene's OUTPUT_FILE, taken in its folder
};

// The OUTPUT_FILE of `input`'s scene taken in the input's folder (standard
// input's: the current folder), else the input's stem with .png in the
// current folder. `input` empty is the default scene, whose OUTPUT_FILE is
// taken as it is.
ImageTarget defaultImageTarget(const std::string& input,
                               const std::optional<std::string>& outputFile);

// defaultImageTarget of each input of a batch without -o, found before the
// first render so that the batch's outputs can be checked together
// (output_plan.h). Each file is read once more for it, and parsed only when
// its format can hold an OUTPUT_FILE (instruction files, glTF, POV-Ray).
// Nothing for an input whose render writes nothing: one that cannot be read
// or parsed, or whose OUTPUT_FILE its render refuses (out of its folder, no
// image format); that render says why.
std::vector<std::optional<std::filesystem::path>> readAheadImageTargets(
    const std::vector<std::string>& inputs, const scene::ReadOptions& options);

}  // namespace tools
