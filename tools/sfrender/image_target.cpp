#include "tools/sfrender/image_target.h"

#include "tools/common/input_limits.h"
#include "tools/common/output_file_format.h"
#include "tools/common/output_location.h"
#include "tools/common/tool_streams.h"

namespace tools {

namespace {

namespace fs = std::filesystem;

fs::path inputFolder(const std::string& input) {
  return isStandardStream(input) ? fs::path() : fs::path(input).parent_path();
}

std::optional<fs::path> readAheadImageTarget(const std::string& input,
                                             const scene::ReadOptions& options) {
  InputText text = readInputText(input, options);
  if (!text.text) return std::nullopt;
  std::optional<scene::Format> format = scene::detectFormat(*text.text, input);
  if (!format) return std::nullopt;
  if (*format != scene::Format::InstructionFile) return defaultImageTarget(input, {}).path;
  scene::ReadResult result = scene::parseScene(*text.text, input, options);
  if (!result.ok()) return std::nullopt;
  const std::optional<std::string>& name = result.scene.outputFile;
  if (name &&
      (!scene::outputStaysInFolder(inputFolder(input), *name) || !hasImageExtension(*name))) {
    return std::nullopt;
  }
  return defaultImageTarget(input, name).path;
}

}  // namespace

ImageTarget defaultImageTarget(const std::string& input,
                               const std::optional<std::string>& outputFile) {
  if (input.empty()) return {*outputFile, false};
  if (outputFile) return {inputFolder(input) / *outputFile, true};
  return {fs::path(input).stem().string() + ".png", false};
}

std::vector<std::optional<fs::path>> readAheadImageTargets(const std::vector<std::string>& inputs,
                                                           const scene::ReadOptions& options) {
  std::vector<std::optional<fs::path>> targets;
  targets.reserve(inputs.size());
  for (const std::string& input : inputs) targets.push_back(readAheadImageTarget(input, options));
  return targets;
}

}  // namespace tools
