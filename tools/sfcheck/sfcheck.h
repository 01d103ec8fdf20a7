// sfcheck: validates scene files and instruction files.
#pragma once

#include <ostream>

namespace tools {

// The whole tool, with its streams passed in so that tests can run it.
int runSfcheck(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace tools
