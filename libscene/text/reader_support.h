// What the line-based readers (scene files and instruction files) share
// beyond tokens: numbers on a line, comments, invalid bytes and unknown
// keywords, each reported the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "libscene/text/text_lines.h"
#include "scenefile/diagnostic.h"

namespace scene {

// Reports the first invalid byte on the cursor's line; true if there was one.
bool reportInvalidByte(const LineCursor& cursor, DiagnosticList& out);

// Reports a line that starts like a comment; true if it does (the line is
// then skipped: it holds nothing either format can read).
bool reportComment(const LineCursor& cursor, DiagnosticList& out);

// Reads exactly `count` numbers from the tokens starting at `first`; `what`
// names them for the diagnostics ("the colour", "LOCATION"). Every bad token
// is reported; false if any was.
bool readNumbers(const LineCursor& cursor, std::size_t first, std::size_t count, double* values,
                 std::string_view what, DiagnosticList& out);

// readNumbers for the common line, in one pass over its text and with no
// tokens: true when the cursor's next line is exactly `count` numbers that
// read cleanly; each value and span is then stored and the cursor moved to
// that line (LineCursor::passLine). False says only that the line needs the
// careful path (nextLine, its tokens and readNumbers), which finds and
// reports whatever is wrong with it; nothing is reported here, and the
// cursor stays where it was.
bool readPlainNumberLine(LineCursor& cursor, std::size_t count, double* values, SourceSpan* spans);

// The closest candidate to `word`: the same word in another case, or one at
// a small edit distance.
std::optional<std::string_view> suggestKeyword(std::string_view word,
                                               std::span<const std::string_view> candidates);

// The candidate that `word` spells in another case ("sphere" -> "SPHERE"):
// the reader reports the word and then reads on as if it were the keyword.
std::optional<std::string_view> keywordInOtherCase(std::string_view word,
                                                   std::span<const std::string_view> candidates);

// "unknown keyword 'sphere'" with a did-you-mean hint and fix-it when one of
// `candidates` is close; `expected` describes what may stand there.
void reportUnknownKeyword(const LineCursor& cursor, std::size_t tokenIndex,
                          std::span<const std::string_view> candidates, std::string_view expected,
                          DiagnosticList& out);

// too-many-objects at `span`, the first object or light past `maxObjects`;
// every reader words it the same way and then stops reading.
Diagnostic& reportTooManyObjects(SourceSpan span, std::size_t maxObjects, DiagnosticList& out);

}  // namespace scene
