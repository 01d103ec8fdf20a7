// The glTF's JSON text, scanned once before anything parses it: how deep it
// nests and how many objects its top-level arrays hold. Both are settled
// from the bytes alone, since nlohmann and tinygltf recurse as deep as the
// text nests and spend hundreds of bytes on every object: a file of a
// million levels or millions of objects is refused before either sees it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace scene::gltf {

// What one glTF object costs against ReadOptions::maxGltfNodes: a node, a
// scene, a mesh, a primitive, an accessor... counts 1; a camera or a light
// 2, a material 5, as tinygltf's structs for them are that many times a
// node's (456 bytes; a material's is 2,144).
std::size_t objectWeight(std::string_view topLevelArray);

struct JsonScan {
  // The byte at which the text first nests deeper than the limit, if it
  // does; the scan stops there, and `objects` is then incomplete.
  std::optional<std::size_t> tooDeepAt;
  // The weighted count (objectWeight) of the objects in the top-level
  // arrays: `{"nodes": [{}, {}]}` holds 2.
  std::size_t objects = 0;
};

// One pass over `json`, strings skipped (with their escapes), whether or
// not the text is valid JSON: that is for the parser to say afterwards.
JsonScan scanJson(std::string_view json, int maxDepth);

}  // namespace scene::gltf
