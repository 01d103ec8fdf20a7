// What the glTF reader may read besides the file: only regular files
// inside the glTF's own folder, named by a relative URI (docs/GLTF.md,
// "Hostile files"); and tinygltf's file callbacks, which hold to the same.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/read.h"

namespace scene::gltf {

// Why a buffer's URI may not be followed, or nothing when it may: only a
// relative path to a regular file inside the glTF's own folder is read.
// `target` is then the file it names.
std::optional<std::string> uriProblem(const std::string& uri, const std::filesystem::path& folder,
                                      std::filesystem::path& target);

// tinygltf's file system, kept inside the folder: it can neither read
// elsewhere, nor expand `~` or `$VAR`, nor write. `user` is a Confinement.
struct Confinement {
  std::filesystem::path folder;
  std::uint64_t maxFileSize = kDefaultMaxFileSize;
};
bool confinedExists(const std::string& path, void* user);
std::string unexpandedPath(const std::string& path, void* user);
bool confinedRead(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void* user);
bool noWrite(std::string* err, const std::string& path, const std::vector<unsigned char>& data,
             void* user);

}  // namespace scene::gltf
