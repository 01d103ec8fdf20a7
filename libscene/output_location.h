// Where an instruction file's OUTPUT_FILE would write.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

// True when `name`, taken relative to `folder`, stays inside it: no absolute
// path, no '..' that climbs out, and no symbolic link leading out of it (a
// link to a file that does not exist yet included, since a write follows it).
bool outputStaysInFolder(const std::filesystem::path& folder, const std::string& name);

// Where writing `path` lands when its last component is a symbolic link:
// the end of the chain of links, whether that file exists or not (a write
// creates it, as the shell's `>` does), absolute and without links in its
// folders. `path` itself, absolute, when it is no link; nothing for a chain
// of more than 40 links (a loop).
std::optional<std::filesystem::path> followLinks(const std::filesystem::path& path);

// Reports an OUTPUT_FILE that would leave the instruction file's folder, with
// the given severity (a warning for sfcheck; sfrender refuses to write).
void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder,
                         Severity severity, DiagnosticList& out);

}  // namespace scene
