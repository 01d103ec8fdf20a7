#include "libscene/formats/gltf/gltf_labels.h"

#include <algorithm>

namespace scene::gltf {

// Names come from the file: a long one is cut, so that a message stays one
// line. Control bytes stay as they are; the tools print every message
// through tools::printableText, which shows them as \xNN.
std::string quoted(const std::string& name) {
  if (name.empty()) return "";
  constexpr std::size_t kMaxShown = 80;
  // The cut falls between UTF-8 characters, not inside one.
  std::size_t end = std::min(name.size(), kMaxShown);
  while (end < name.size() && end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) {
    --end;
  }
  return " '" + name.substr(0, end) + (end < name.size() ? "..." : "") + "'";
}

std::string nodeLabel(const tinygltf::Model& model, int node) {
  return "node " + std::to_string(node) + quoted(model.nodes[node].name);
}

std::string meshLabel(const tinygltf::Model& model, int mesh) {
  return "mesh " + std::to_string(mesh) + quoted(model.meshes[mesh].name);
}

}  // namespace scene::gltf
