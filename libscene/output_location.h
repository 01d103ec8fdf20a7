// Where an instruction file's OUTPUT_FILE would write.
#pragma once

#include <filesystem>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

// True when `name`, taken relative to `folder`, stays inside it: no absolute
// path, no '..' that climbs out, and no symbolic link leading out of it.
bool outputStaysInFolder(const std::filesystem::path& folder, const std::string& name);

// Reports an OUTPUT_FILE that would leave the instruction file's folder, with
// the given severity (a warning for sfcheck; sfrender refuses to write).
void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder,
                         Severity severity, DiagnosticList& out);

}  // namespace scene
