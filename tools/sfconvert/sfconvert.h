// sfconvert: converts between the project's scene formats.
#pragma once

#include <ostream>

namespace tools {

int runSfconvert(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace tools
