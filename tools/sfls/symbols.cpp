// textDocument/documentSymbol and textDocument/foldingRange: the outline of
// the checked version, as the library finds it (scene::outlineOf). Both
// list at most kMaxOutlineItems items, so that they answer at once at any
// size: a million objects would be 200 MB of symbols no editor shows.
#include <algorithm>
#include <string>
#include <vector>

#include "tools/sfls/document_place.h"
#include "tools/sfls/features.h"
#include "tools/sfls/lsp_json.h"

namespace sfls {
namespace {

using scene::OutlineItem;
using scene::OutlineKind;

// The protocol's SymbolKind.
int symbolKind(OutlineKind kind) {
  switch (kind) {
    case OutlineKind::OutputFile:
      return 1;  // File
    case OutlineKind::Material:
      return 7;  // Property
    case OutlineKind::Transformation:
      return 18;  // Array: a list of operations
    default:
      return 19;  // Object
  }
}
constexpr int kNullSymbol = 21;

// The whole lines `first` to `last` (1-based, inclusive).
LspRange linesRange(const Document& document, std::uint32_t first, std::uint32_t last) {
  std::uint32_t lines = std::max(document.lineCount(), 1u);
  first = std::clamp(first, 1u, lines);
  last = std::clamp(last, first, lines);
  std::uint32_t end = static_cast<std::uint32_t>(document.lineText(last - 1).size()) + 1;
  return {document.toLsp(first, 1), document.toLsp(last, end)};
}

bool contains(const LspRange& outer, const LspRange& inner) {
  auto before = [](const LspPosition& a, const LspPosition& b) {
    return a.line < b.line || (a.line == b.line && a.character <= b.character);
  };
  return before(outer.start, inner.start) && before(inner.end, outer.end);
}

nlohmann::json symbolOf(const Document& document, const Analysis& analysis,
                        const OutlineItem& item) {
  LspRange range = linesRange(document, item.firstLine, item.lastLine);
  LspRange selection = item.name.known() ? document.toLsp(item.name) : range;
  if (!contains(range, selection)) selection = {range.start, range.start};
  // Member by member: an initializer list would copy each nested object
  // once more, and this runs for thousands of items a request.
  nlohmann::json symbol(nlohmann::json::value_t::object);
  symbol["name"] = itemName(item.kind, item.objectKind, item.number);
  symbol["kind"] = symbolKind(item.kind);
  symbol["range"] = range;
  symbol["selectionRange"] = selection;
  const scene::Scene& scene = analysis.result.scene;
  if (item.kind == OutlineKind::OutputFile && scene.outputFile &&
      scene.outputFileSpan.line == item.firstLine) {
    symbol["detail"] = *scene.outputFile;
  }
  return symbol;
}

}  // namespace

nlohmann::json documentSymbols(const Document& document, const Analysis& analysis) {
  const std::vector<OutlineItem>& items = analysis.outline.items;
  std::size_t listed = std::min(items.size(), kMaxOutlineItems);
  std::vector<nlohmann::json> symbols(listed);
  std::vector<std::vector<std::size_t>> children(listed);
  for (std::size_t i = 0; i < listed; ++i) {
    symbols[i] = symbolOf(document, analysis, items[i]);
    if (items[i].parent < i) children[items[i].parent].push_back(i);
  }
  // Each item comes after the one that holds it, so from the last to the
  // first every item's children are complete before it is moved into its own
  // parent.
  for (std::size_t i = listed; i-- > 0;) {
    if (children[i].empty()) continue;
    nlohmann::json& list = symbols[i]["children"] = nlohmann::json::array();
    for (std::size_t child : children[i]) list.push_back(std::move(symbols[child]));
  }
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < listed; ++i) {
    if (items[i].parent == scene::Outline::kNoParent) out.push_back(std::move(symbols[i]));
  }
  if (listed < items.size()) {
    // One last symbol says what was left out and where it starts.
    // The last item to start is in the last top-level item, which ends last.
    const OutlineItem* last = &items.back();
    while (last->parent != scene::Outline::kNoParent) last = &items[last->parent];
    LspRange rest = linesRange(document, items[listed].firstLine, last->lastLine);
    out.push_back({{"name", std::to_string(items.size() - listed) + " more items not listed"},
                   {"kind", kNullSymbol},
                   {"range", rest},
                   {"selectionRange", LspRange{rest.start, rest.start}}});
  }
  return out;
}

nlohmann::json foldingRanges(const Document& document, const Analysis& analysis) {
  nlohmann::json out = nlohmann::json::array();
  std::uint32_t lines = document.lineCount();
  for (const OutlineItem& item : analysis.outline.items) {
    if (out.size() == kMaxOutlineItems) break;
    if (item.lastLine <= item.firstLine || item.lastLine > lines) continue;
    out.push_back({{"startLine", item.firstLine - 1}, {"endLine", item.lastLine - 1}});
  }
  return out;
}

}  // namespace sfls
