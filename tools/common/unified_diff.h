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
// end of file". Empty when the texts are equal. The lines are matched
// greedily, not by a shortest edit script (Myers's): after a difference the
// texts meet again at the nearest lines where three in a row agree. A fix
// changes a few lines here and there, which this finds in time linear in
// the text; a shortest script costs time and memory that grow with the
// product of the text and the changes, too much for a file of a million
// objects.
std::string unifiedDiff(std::string_view before, std::string_view after, std::string_view name,
                        int context = 3);

}  // namespace tools
