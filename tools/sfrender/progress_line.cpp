#include "tools/sfrender/progress_line.h"

#include <cmath>
#include <cstdio>

namespace tools {

std::string clockText(double seconds) {
  // A non-finite or negative figure (no estimate yet) reads as none.
  long long whole = std::isfinite(seconds) && seconds > 0 ? static_cast<long long>(seconds) : 0;
  long long hours = whole / 3600, minutes = whole / 60 % 60, rest = whole % 60;
  char text[48];
  if (hours > 0) {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", hours, minutes, rest);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld", minutes, rest);
  }
  return text;
}

std::string progressText(int done, int total, double elapsedSeconds) {
  int percent = total > 0 ? static_cast<int>(100LL * done / total) : 100;
  char share[8];
  std::snprintf(share, sizeof share, "%3d%%", percent);
  std::string text =
      "sfrender: rendering " + std::string(share) + ", " + clockText(elapsedSeconds) + " elapsed";
  // Before a second has passed the rate is mostly the start's noise.
  if (done > 0 && done < total && elapsedSeconds >= 1.0) {
    double left = elapsedSeconds * (total - done) / done;
    text += ", " + clockText(left) + " left";
  }
  return text;
}

void ProgressLine::update(int done, int total, double elapsedSeconds) {
  // The render's threads may report their parts a little out of order.
  if (done < mostDone_) return;
  mostDone_ = done;
  std::string text = progressText(done, total, elapsedSeconds);
  bool finished = done >= total;
  if (text == last_ && !finished) return;
  std::size_t blanks = last_.size() > text.size() ? last_.size() - text.size() : 0;
  out_ << '\r' << text << std::string(blanks, ' ') << (finished ? "\n" : "") << std::flush;
  last_ = finished ? std::string() : text;
}

}  // namespace tools
