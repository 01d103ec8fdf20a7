// The exit statuses every tool shares (TOOLS.md), in one place.
#pragma once

namespace tools {

enum class ExitCode : int {
  Success = 0,         // warnings allowed
  InvalidInput = 1,    // the input is invalid, or the conversion cannot be done as asked
  Usage = 2,           // the command line is wrong
  IoError = 3,         // a file could not be read or written (a standard stream included)
  OutOfResources = 4,  // memory or threads ran out: the input may be fine, the machine was not
  NoDisplay = 5,       // sfbuild: no display to open a window on (or no OpenGL 3.3 there)
};

inline int toInt(ExitCode code) {
  return static_cast<int>(code);
}

}  // namespace tools
