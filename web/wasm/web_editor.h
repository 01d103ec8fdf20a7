// The module's hover() and completion(): the language server's own answers
// (tools/sfls), for the page's editor.
#pragma once

#include <cstdint>
#include <string>

namespace web {

// textDocument/hover's and textDocument/completion's result as JSON (a
// Hover, a CompletionList whose items may be snippets, as for an editor
// that takes them; "null" when none) at `line` and `character` (from 0,
// the character in UTF-16 code units, as CodeMirror counts) of `text`,
// checked as sfls checks an open document.
std::string hoverJson(std::string text, std::uint32_t line, std::uint32_t character);
std::string completionJson(std::string text, std::uint32_t line, std::uint32_t character);

}  // namespace web
