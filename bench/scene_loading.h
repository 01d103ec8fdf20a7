// Reading a scene file for the benchmark programs: the whole file into
// memory, then the project's reader (scene::parseScene), as sfrender does.
#pragma once

#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "scenefile/read.h"

namespace bench {

// The scene in `path`, or nothing after a "TOOL: error: ..." line on stderr.
inline std::optional<scene::Scene> loadScene(const std::string& path, const char* tool) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << tool << ": error: cannot read " << path << "\n";
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  scene::ReadResult result = scene::parseScene(buffer.str(), path);
  if (!result.ok()) {
    std::cerr << tool << ": error: " << path << " has errors\n";
    return std::nullopt;
  }
  return std::move(result.scene);
}

}  // namespace bench
