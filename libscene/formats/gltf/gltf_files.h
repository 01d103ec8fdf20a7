// What the glTF reader may read besides the file: only regular files
// inside the glTF's own folder, named by a relative URI (docs/GLTF.md,
// "Hostile files"); and tinygltf's file callbacks, which hold to the same
// when it loads the buffers.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
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

// Every buffer of `doc` whose URI names a file: an error for each URI that
// may not be followed (uriProblem) and each file above options.maxFileSize,
// found before tinygltf, which would read the file whole.
void checkBufferFiles(const nlohmann::json& doc, const std::filesystem::path& folder,
                      const ReadOptions& options, DiagnosticList& out);

// The model of `json` (the document as tinygltf is to see it) and, for a
// GLB, its BIN chunk, read by tinygltf with its file system confined to
// `folder` and no image decoded; false, with the error in `out`, when
// tinygltf cannot read it. Out of memory is thrown, not reported: it is no
// fault of the file.
bool loadModel(const std::string& json, std::optional<std::string_view> bin, bool binary,
               const std::filesystem::path& folder, std::uint64_t maxFileSize,
               tinygltf::Model& model, DiagnosticList& out);

}  // namespace scene::gltf
