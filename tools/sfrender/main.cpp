#include <malloc.h>

#include "tools/common/standard_streams.h"
#include "tools/common/tool_streams.h"
#include "tools/sfrender/sfrender.h"

int main(int argc, char** argv) {
  // Freed memory stays with the process for the next allocation. By
  // default glibc gives every allocation over 32 MiB pages of its own and
  // hands them back when it is freed, so each big array of a large scene
  // (the file's text, the parts' objects, the records, the BVH's build list)
  // paid a first touch on every page, although the one before it had just
  // freed as much: 60,000 of 280,000 page faults at 1,000,000 objects
  // (docs/history/PERFORMANCE.md, "Big scenes: memory kept, and fewer
  // passes").
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  int status = tools::runSfrender(argc, argv, tools::processStreams());
  return tools::closeStandardStreams("sfrender", status);
}
