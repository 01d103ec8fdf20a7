// The canonical layout of a scene file (scenefile/layout.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace scene {

// The records as the writer lays them out: each line's words joined by one
// space, record names in upper case, blank lines dropped but one before
// each record after the first. Nothing for a line of more words than any
// record has room for.
std::optional<std::string> sceneFileLayout(std::string_view text);

}  // namespace scene
