// Whether the threads a render asks for can be started. The renderer starts
// its own (renderer/cpu_render.cpp) and has no way back from one that fails:
// std::thread's constructor throws, and the threads already running, still
// joinable, end the program in std::terminate. sfrender therefore starts
// the same number first, all alive at once, and ends them before rendering.
#pragma once

#include <optional>
#include <string>

#include "tools/common/tool_failure.h"

namespace tools {

// The threads a render with --threads `requested` uses: that many, or for 0
// one per core, as the renderer counts them.
int renderThreadCount(int requested);

// Starts `threads` - 1 threads (the calling thread is the last), waits
// until all have started, and ends them. Nothing when all started; else
// a failure for want of resources, with the reason the first that could not
// start gave ("Resource temporarily unavailable").
MaybeFailure threadStartFailure(int threads);

}  // namespace tools
