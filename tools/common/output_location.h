// Where an instruction file's OUTPUT_FILE would write.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

// Where `name`, taken relative to `folder`, lands.
enum class OutputPlace {
  Inside,    // no absolute path, no '..' that climbs out, no link out
  Outside,   // one of those (a link to a file not there yet included: a write follows it)
  LinkLoop,  // every link it follows stays inside, but they never end (a loop, or over 40)
};
OutputPlace outputPlace(const std::filesystem::path& folder, const std::string& name);

// True when `name`, taken relative to `folder`, stays inside it.
inline bool outputStaysInFolder(const std::filesystem::path& folder, const std::string& name) {
  return outputPlace(folder, name) == OutputPlace::Inside;
}

// Where writing `path` lands when its last component is a symbolic link:
// the end of the chain of links, whether that file exists or not (a write
// creates it, as the shell's `>` does), absolute and without links in its
// folders. `path` itself, absolute, when it is no link; nothing for a chain
// of more than 40 links (a loop) or one that cannot be read. `visited`, when
// given, gets each place the chain passes through, in order, the end too.
std::optional<std::filesystem::path> followLinks(
    const std::filesystem::path& path, std::vector<std::filesystem::path>* visited = nullptr);

// Reports an OUTPUT_FILE that would leave the instruction file's folder
// [output-file-escapes], or that leads into a loop of links inside it
// [output-file-link-loop], with the given severity (a warning for sfcheck;
// sfrender refuses to write).
void checkOutputLocation(const Scene& scene, const std::filesystem::path& folder, Severity severity,
                         DiagnosticList& out);

}  // namespace scene
