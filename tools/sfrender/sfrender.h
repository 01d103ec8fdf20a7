// sfrender: ray traces a scene file, an instruction file or the default scene.
#pragma once

#include <ostream>

namespace tools {

// `errIsTerminal` says whether `err` is a terminal, for the progress bar.
int runSfrender(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                bool errIsTerminal = false);

}  // namespace tools
