/// @file
/// Applying the fix-its of diagnostics to the text they were found in: the
/// one piece of code behind every front end's "fix" (a tool writing a file,
/// an editor's code action).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/diagnostic.h"

namespace scene {

/// The fix-its of `diagnostics` that apply together: in the order of the
/// text, each dropped that overlaps one before it.
std::vector<FixIt> applicableFixIts(const DiagnosticList& diagnostics);

/// `text` with `fixIts` applied; they are in the order of the text and do
/// not overlap (applicableFixIts). A span past the end of its line or of
/// the text is left out, so that a fix-it from another version of a text
/// cannot write out of place.
std::string applyFixIts(std::string_view text, std::span<const FixIt> fixIts);

}  // namespace scene
