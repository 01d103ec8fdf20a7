// Standard output and standard error are outputs like any file: a write, a
// flush or a close that fails (a full disk, /dev/full, a closed pipe) must
// not pass for success.
#pragma once

#include <ostream>

namespace tools {

// Flushes `out`, the tool's standard output, and says whether all that was
// written reached it; if not, prints "TOOL: error: cannot write to standard
// output: REASON" on `err`.
bool flushStandardOutput(const char* tool, std::ostream& out, std::ostream& err);

// For main(), after the tool ran: flushes standard output and standard
// error, C's and C++'s, and closes standard output. A failure the tool has
// not reported turns an exit status of 0 or 1 into ExitCode::IoError, with
// the message on standard error when it was standard output that failed
// (when standard error fails, the status alone can tell). Returns the exit
// status to end with.
int closeStandardStreams(const char* tool, int status);

}  // namespace tools
