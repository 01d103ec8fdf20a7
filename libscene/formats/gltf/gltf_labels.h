// The labels by which a message names a glTF file's nodes and meshes, since
// glTF has no lines to point at.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace scene::gltf {

// " 'name'" for a message, cut to one line's worth; "" for no name.
std::string quoted(const std::string& name);
std::string nodeLabel(const tinygltf::Model& model, int node);
std::string meshLabel(const tinygltf::Model& model, int mesh);

}  // namespace scene::gltf
