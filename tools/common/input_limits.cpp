#include "tools/common/input_limits.h"

#include <sys/stat.h>

#include "scenefile/read.h"
#include "tools/common/file_io.h"

namespace tools {

void addReadLimitOptions(CLI::App& app, scene::ReadOptions& options) {
  app.add_option("--max-file-size", options.maxFileSize,
                 "refuse an input larger than this many bytes (suffixes such as 512MiB or 2GB "
                 "work)")
      ->transform(CLI::AsSizeValue(true))
      // CLI11 reads "-5" as a huge unsigned number: the sign is refused
      // first (a transform added later runs earlier).
      ->transform(CLI::Validator(
          [](std::string& value) {
            return value.find('-') == std::string::npos ? std::string()
                                                        : std::string("a size is not negative");
          },
          ""))
      ->capture_default_str();
  app.add_option("--max-objects", options.maxObjects,
                 "stop reading at the first object or light past this many")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-vertices", options.gltf.maxVertices,
                 "glTF: refuse a file with more mesh vertices than this")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-nodes", options.gltf.maxNodes,
                 "glTF: refuse a file with more nodes and other objects than this (a material "
                 "counts 5, a camera or a light 2)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

InputText readInputText(const std::string& file, const scene::ReadOptions& options) {
  InputText input{std::nullopt, {}, scene::DiagnosticList(file, options.errorLimit)};
  struct stat info {};
  if (::stat(file.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    if (!scene::checkFileSize(static_cast<std::uint64_t>(info.st_size), options, input.refused)) {
      return input;
    }
  }
  std::optional<std::string> text = readWholeFile(file, input.readError, options.maxFileSize);
  if (!text) return input;
  if (text->size() > options.maxFileSize) {
    // Not a regular file, or one that grew: its whole size is unknown.
    input.refused
        .error(
            scene::DiagnosticCode::FileTooLarge, {},
            "the input is more than the limit of " + std::to_string(options.maxFileSize) + " bytes")
        .hint = "raise the limit with --max-file-size if the input is meant to be this large";
    return input;
  }
  input.text = std::move(text);
  return input;
}

}  // namespace tools
