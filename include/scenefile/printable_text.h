/// @file
/// Text from a file as it is safe to show on a terminal or in JSON.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace scene {

/// The text as it is safe to show: a message may quote bytes from a file, and
/// a control byte (a terminal's escape sequence) or a byte that is not UTF-8
/// is written as \\xNN instead, so that printing cannot drive the terminal and
/// JSON output stays valid UTF-8.
std::string printableText(std::string_view text);

/// The length of the well-formed UTF-8 character at the start of `text`
/// (RFC 3629: no overlong forms, no surrogates, nothing past U+10FFFF), or 0.
std::size_t utf8CharacterLength(std::string_view text);

/// Whether printableText shows the character at the start of `text`, of
/// utf8CharacterLength `length`, as it is (not as \\xNN).
bool showsAsItIs(std::string_view text, std::size_t length);

}  // namespace scene
