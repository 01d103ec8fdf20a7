// The progress of a render on a terminal, as POV-Ray shows it: one line,
// rewritten in place, with the share done, the time taken and the time
// left:
//
//   sfrender: rendering  43%, 0:01 elapsed, 0:02 left
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

namespace tools {

// Seconds as a clock shows them: "0:07", "12:34", "1:02:03" (rounded down).
std::string clockText(double seconds);

// The line for `done` of `total` parts after `elapsedSeconds`. The time left
// is the elapsed time scaled by the share left over the share done: the
// parts are taken as equal in cost, so where they are not (adaptive
// sampling's cheap first pass, an object that fills one corner) the figure
// moves as the render goes. It shows once a second has passed; done, the
// line says the time taken alone.
std::string progressText(int done, int total, double elapsedSeconds);

// Writes each new progressText to `out` over the last one ("\r", then blanks
// over what a longer line left), and a newline once done. A line that
// would say the same, or a count lower than one shown (the threads report
// out of order), is not written.
class ProgressLine {
 public:
  explicit ProgressLine(std::ostream& out) : out_(out) {}

  void update(int done, int total, double elapsedSeconds);

 private:
  std::ostream& out_;
  std::string last_;
  int mostDone_ = 0;
};

}  // namespace tools
