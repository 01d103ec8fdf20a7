// The image formats sfrender writes, by the output's extension: one list,
// shared by sfrender (which writes them, through OpenImageIO but for .ppm)
// and sfcheck (which warns of an OUTPUT_FILE that names none), so that
// sfcheck needs no OpenImageIO to tell.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace tools {

// The extensions, lower case with their dot: ".ppm", ".png", ...
std::span<const std::string_view> imageExtensions();

// Whether the name ends in one of them, in any case (".PNG" too).
bool hasImageExtension(const std::filesystem::path& path);

// The list for a message: ".ppm, .pnm, .png, ... or .hdr".
std::string imageExtensionList();

// Reports an OUTPUT_FILE with no image extension at its span
// [output-file-format], with the given severity (a warning for sfcheck;
// sfrender refuses to render what it could not write).
void checkOutputFileFormat(const scene::Scene& scene, scene::Severity severity,
                           scene::DiagnosticList& out);

}  // namespace tools
