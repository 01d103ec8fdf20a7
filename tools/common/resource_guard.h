// What a tool does when memory or threads run out: a message naming what it
// was doing and ExitCode::OutOfResources, never std::terminate (SIGABRT),
// and, since the exception unwinds the stack, every StagedFile's temporary
// removed on the way out.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace tools {

// What the tool is doing now, in the words of the message: "reading
// scene.sf", "converting", "rendering", "writing out.png". Set before each
// stage, so that the message costs no allocation once memory is out.
class Stage {
 public:
  void set(std::string what) { what_ = std::move(what); }
  const std::string& what() const { return what_; }

 private:
  std::string what_ = "starting";
};

// Runs `body` and returns its exit status; std::bad_alloc becomes
// "TOOL: error: out of memory while STAGE", std::system_error (a thread that
// cannot start, a lock that cannot be taken) "TOOL: error: STAGE: REASON",
// both ExitCode::OutOfResources, and std::filesystem::filesystem_error
// "TOOL: error: PATH: REASON", ExitCode::IoError.
int runGuarded(const char* tool, std::ostream& err, const Stage& stage,
               const std::function<int()>& body);

}  // namespace tools
