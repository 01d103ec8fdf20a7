// The rows of glTF 2.0 in the format registry: JSON text (.gltf) and binary
// (.glb), one reader for both and one writer.
#include <filesystem>
#include <string_view>

#include "libscene/formats/format_rows.h"
#include "libscene/formats/gltf/gltf_reader.h"
#include "libscene/formats/gltf/gltf_writer.h"
#include "scenefile/convert.h"

namespace scene {
namespace {

constexpr std::string_view kGltfExtensions[] = {".gltf"};
constexpr std::string_view kGlbExtensions[] = {".glb"};
// glTF holds the Phong values in its materials' extensions and extras, and
// the camera's field of view and aspect ratio.
constexpr FormatHolds kHolds{
    .materials = true, .transformLists = true, .outputFile = true, .view = true};

Recognition recogniseGltf(std::string_view bytes) {
  return looksLikeGltfJson(bytes) ? Recognition::Certain : Recognition::None;
}

Recognition recogniseGlb(std::string_view bytes) {
  return looksLikeGlb(bytes) ? Recognition::Certain : Recognition::None;
}

// Either container: the reader tells them apart by their bytes. External
// buffers are looked for in the file's own folder.
ReadResult readGltfFormat(std::string_view bytes, std::string fileName,
                          const ReadOptions& options) {
  std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
  return parseGltf(bytes, std::move(fileName), folder, options);
}

std::optional<ConvertedFiles> writeGltfFiles(const Scene& scene, const ConversionOptions& options,
                                             bool binary, DiagnosticList& out) {
  std::optional<GltfFiles> files = writeGltf(scene, options, binary, out);
  if (!files) return std::nullopt;
  return ConvertedFiles{std::move(files->main), std::move(files->buffer)};
}

std::optional<ConvertedFiles> writeGltfFormat(const Scene& scene, const ConversionOptions& options,
                                              DiagnosticList& out) {
  return writeGltfFiles(scene, options, false, out);
}

std::optional<ConvertedFiles> writeGlbFormat(const Scene& scene, const ConversionOptions& options,
                                             DiagnosticList& out) {
  return writeGltfFiles(scene, options, true, out);
}

}  // namespace

FormatInfo gltfFormat() {
  FormatInfo row;
  row.format = Format::Gltf;
  row.name = "gltf";
  row.singular = "a glTF 2.0 file";
  row.plural = "glTF 2.0";
  row.extensions = kGltfExtensions;
  row.startsWith = "'{'";
  row.holds = kHolds;
  row.recognise = recogniseGltf;
  row.read = readGltfFormat;
  row.write = writeGltfFormat;
  return row;
}

FormatInfo glbFormat() {
  FormatInfo row;
  row.format = Format::Glb;
  row.name = "glb";
  row.singular = "a binary glTF 2.0 file";
  row.plural = "binary glTF 2.0";
  row.extensions = kGlbExtensions;
  row.startsWith = "the bytes 'glTF'";
  row.binary = true;
  row.holds = kHolds;
  row.recognise = recogniseGlb;
  row.read = readGltfFormat;
  row.write = writeGlbFormat;
  return row;
}

}  // namespace scene
