// The language features that read a document and its latest check: each a
// function from them to the JSON of the protocol's answer. `analysis` is
// the check of the document's current version, or nullptr while that check
// runs; a feature then answers from the text alone (what stands around the
// position) and leaves out what only the scene knows.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>

#include "tools/sfls/analysis.h"
#include "tools/sfls/document.h"

namespace sfls {

// textDocument/hover: a Hover, or null.
nlohmann::json hover(const Document& document, const Analysis* analysis, LspPosition position);

// textDocument/completion: a CompletionList (snippets where the client
// takes them).
nlohmann::json completion(const Document& document, const Analysis* analysis,
                          LspPosition position, bool snippets);

// The most items documentSymbols and foldingRanges list: the first ones of
// the text, and for the symbols one more that says how many were left out.
// A million objects' symbols would be 200 MB of JSON, which no editor shows
// and no request could answer in time; 5,000 symbols take some 30 ms, and
// yaml-language-server's maxItemsComputed is the same 5,000.
inline constexpr std::size_t kMaxOutlineItems = 5'000;

// textDocument/documentSymbol: DocumentSymbol[] (nested as the blocks nest).
nlohmann::json documentSymbols(const Document& document, const Analysis& analysis);

// textDocument/foldingRange: FoldingRange[].
nlohmann::json foldingRanges(const Document& document, const Analysis& analysis);

// textDocument/formatting (no range) and rangeFormatting: TextEdit[]; none
// for a text with errors or in a format with no layout rules.
nlohmann::json formattingEdits(const Document& document, const Analysis& analysis,
                               const std::optional<LspRange>& range);

}  // namespace sfls
