// sfrender: ray traces a scene file, an instruction file or the default scene.
#pragma once

#include <ostream>

#include "renderer/render_memory.h"

namespace tools {

// The memory check is the renderer's (renderer/render_memory.h).
using render::AvailableMemoryProbe;

// `errIsTerminal` says whether `err` is a terminal, for the progress bar;
// `availableMemory` says how much memory a render may take (tests pass their
// own figure).
int runSfrender(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                bool errIsTerminal = false,
                const AvailableMemoryProbe& availableMemory = render::readAvailableMemory);

}  // namespace tools
