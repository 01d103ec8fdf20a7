// A text's change as a unified diff, as `diff -u` prints it, for a change
// shown rather than made (sfcheck --fix --dry-run): `patch -p1` and
// `git apply` apply it.
#pragma once

#include <string>
#include <string_view>

namespace tools {

// The lines that differ between `before` and `after`, in hunks with
// `context` unchanged lines around each, under the headers `--- a/NAME` and
// `+++ b/NAME`; a last line without a newline is marked "\ No newline at
// end of file". Empty when the texts are equal. Made for fixes, which
// replace words within lines: lines are paired by their place, so each run
// of changed lines is a hunk of its own. Texts whose line counts differ are
// one hunk from their first to their last difference.
std::string unifiedDiff(std::string_view before, std::string_view after, std::string_view name,
                        int context = 3);

}  // namespace tools
