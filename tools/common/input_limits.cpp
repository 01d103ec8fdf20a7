#include "tools/common/input_limits.h"

#include <CLI/CLI.hpp>
#include <limits>

#include "scenefile/read.h"
#include "tools/common/option_checks.h"
#include "tools/common/tool_streams.h"

namespace tools {

void addReadLimitOptions(CLI::App& app, scene::ReadOptions& options) {
  app.add_option("--max-file-size", options.maxFileSize,
                 "refuse an input larger than this many bytes (suffixes such as 512MiB or 2GB "
                 "work)")
      ->option_text("SIZE")
      ->transform(sizeInBytes());
  app.add_option("--max-objects", options.maxObjects,
                 "stop reading at the first object or light past this many")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
  app.add_option("--max-vertices", options.gltf.maxVertices,
                 "glTF and OBJ: refuse a file with more mesh vertices than this")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()))
      ->each([&options](const std::string& n) { options.obj.maxVertices = std::stoull(n); });
  app.add_option("--max-nodes", options.gltf.maxNodes,
                 "glTF: refuse a file with more nodes and other objects than this (a material "
                 "counts 5, a camera or a light 2)")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
}

std::string inputDisplayName(const std::string& file) {
  return isStandardStream(file) ? kStandardInputName : file;
}

InputText readInputText(const std::string& file, const scene::ReadOptions& options,
                        std::istream* standardInput) {
  if (isStandardStream(file) && standardInput) {
    return scene::readSourceStream(*standardInput, kStandardInputName, options);
  }
  return scene::readSourceFile(file, options, inputDisplayName(file));
}

}  // namespace tools
