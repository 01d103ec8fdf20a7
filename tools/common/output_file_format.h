// The image formats sfrender writes, by the output's extension, as a fixed
// list: sfcheck warns of an OUTPUT_FILE that names none, and sfrender
// refuses one, before it asks OpenImageIO (which sfcheck must not load) at
// run time what it writes (image/image_formats.h); a test holds
// the two lists together.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace tools {

// The extensions, lower case with their dot: ".ppm", ".png", ... (those of
// sfrender's --help with Debian 12's OpenImageIO).
std::span<const std::string_view> imageExtensions();

// Whether the name ends in one of them, in any case (".PNG" too).
bool hasImageExtension(const std::filesystem::path& path);

// Reports an OUTPUT_FILE with no image extension at its span
// [output-file-format], with the given severity (a warning for sfcheck;
// sfrender refuses to render what it could not write).
void checkOutputFileFormat(const scene::Scene& scene, scene::Severity severity,
                           scene::DiagnosticList& out);

}  // namespace tools
