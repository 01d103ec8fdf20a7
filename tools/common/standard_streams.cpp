#include "tools/common/standard_streams.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "tools/common/exit_code.h"

namespace tools {

namespace {

// Set once the failure of standard output has been told, so that main()
// does not tell it twice.
bool outputFailureReported = false;

const char* reason(int error) {
  return error != 0 ? std::strerror(error) : "the write failed";
}

int failedStatus(int status) {
  return status == toInt(ExitCode::Success) || status == toInt(ExitCode::InvalidInput)
             ? toInt(ExitCode::IoError)
             : status;
}

}  // namespace

bool flushStandardOutput(const char* tool, std::ostream& out, std::ostream& err) {
  errno = 0;
  out.flush();
  if (out) return true;
  int error = errno;
  err << tool << ": error: cannot write to standard output: " << reason(error) << "\n";
  outputFailureReported = true;
  return false;
}

int closeStandardStreams(const char* tool, int status) {
  errno = 0;
  std::cout.flush();
  bool outFailed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  int error = errno;
  // close() reports what a file system only finds out at the end (NFS);
  // the C++ streams' final flush at exit then has nothing left to write.
  if (!outFailed && ::close(STDOUT_FILENO) != 0 && errno != EBADF) {
    outFailed = true;
    error = errno;
  }
  if (outFailed && !outputFailureReported) {
    std::cerr << tool << ": error: cannot write to standard output: " << reason(error) << "\n";
    outputFailureReported = true;
  }
  if (outFailed) status = failedStatus(status);
  std::cerr.flush();
  if (!std::cerr || std::fflush(stderr) != 0 || std::ferror(stderr) != 0) {
    status = failedStatus(status);
  }
  return status;
}

}  // namespace tools
