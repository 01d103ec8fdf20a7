#include "libscene/formats/gltf/gltf_json_scan.h"

namespace scene::gltf {

std::size_t objectWeight(std::string_view topLevelArray) {
  if (topLevelArray == "materials") return 5;
  if (topLevelArray == "cameras" || topLevelArray == "lights") return 2;
  return 1;
}

JsonScan scanJson(std::string_view json, int maxDepth) {
  JsonScan scan;
  // Two depths, which differ only in text that is not JSON: `depth` counts
  // every bracket, so that a stray closer takes it below 0, while `open`
  // counts the containers around the byte and never falls below 0. The
  // limit reads the first and the count the second: which one refuses a
  // malformed file (too deep, too many nodes, or the parser's invalid JSON)
  // is part of what the reader reports for it, and stays as it was.
  int depth = 0;
  std::size_t open = 0;
  char second = 0;         // the container at level 2: '[' inside a top-level array
  std::size_t weight = 0;  // of the top-level array being read
  std::size_t keyStart = 0;
  std::string_view lastKey;  // the last string closed at level 1
  bool inString = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    char c = json[i];
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
        if (open == 1) lastKey = json.substr(keyStart, i - keyStart);
      }
    } else if (c == '"') {
      inString = true;
      keyStart = i + 1;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) {
        scan.tooDeepAt = i;
        return scan;
      }
      if (c == '[' && open == 1) weight = objectWeight(lastKey);
      if (c == '{' && open == 2 && second == '[') scan.objects += weight;
      if (open == 1) second = c;
      ++open;
    } else if (c == ']' || c == '}') {
      --depth;
      if (open > 0) --open;
    }
  }
  return scan;
}

}  // namespace scene::gltf
