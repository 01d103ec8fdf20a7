#include "libscene/formats/gltf/gltf_import_context.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "libscene/formats/gltf/gltf_extras.h"

namespace scene::gltf {

int nodeLight(const tinygltf::Model& model, int node) {
  nlohmann::json ext = parseOrNull(model.nodes[node].extensions_json_string);
  if (!ext.is_object()) return -1;
  auto it = ext.find("KHR_lights_punctual");
  if (it == ext.end() || !it->is_object()) return -1;
  auto light = it->find("light");
  if (light == it->end() || !light->is_number_integer()) return -2;
  long long value = light->get<long long>();
  return value < 0 || value > std::numeric_limits<int>::max() ? -2 : static_cast<int>(value);
}

// A sum of products with 0 is 0 only when every entry is finite.
bool finite(const glm::dmat4& m) {
  double sum = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) sum += m[c][r] * 0.0;
  }
  return sum == 0.0;
}

}  // namespace scene::gltf
