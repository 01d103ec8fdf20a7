#include "tools/sfls/lsp_diagnostics.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "scenefile/fix_its.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/sfls/lsp_json.h"
#include "tools/sfls/uri.h"

namespace sfls {
namespace {

int lspSeverity(scene::Severity severity) {
  switch (severity) {
    case scene::Severity::Error:
      return 1;
    case scene::Severity::Warning:
      return 2;
    case scene::Severity::Note:
      return 3;
  }
  return 1;
}

nlohmann::json textEdit(const Document& document, const scene::FixIt& fixIt) {
  return {{"range", document.toLsp(fixIt.span)}, {"newText", fixIt.replacement}};
}

bool meets(const LspRange& a, const LspRange& b) {
  auto before = [](LspPosition x, LspPosition y) {
    return x.line < y.line || (x.line == y.line && x.character < y.character);
  };
  return !before(a.end, b.start) && !before(b.end, a.start);
}

// "replace 'sphere' with 'SPHERE'", as clangd names its fixes by what they do.
std::string fixItTitle(const Document& document, const scene::FixIt& fixIt) {
  std::string_view line = document.lineText(fixIt.span.line - 1);
  std::size_t start = std::min<std::size_t>(fixIt.span.column - 1, line.size());
  std::string old(line.substr(start, fixIt.span.length));
  if (old.empty()) return "insert '" + fixIt.replacement + "'";
  if (fixIt.replacement.empty()) return "remove '" + old + "'";
  return "replace '" + old + "' with '" + fixIt.replacement + "'";
}

bool kindWanted(const std::optional<std::vector<std::string>>& only, std::string_view kind) {
  if (!only) return true;
  return std::any_of(only->begin(), only->end(), [&](const std::string& name) {
    // A kind asks for its sub-kinds too: "source" for "source.fixAll".
    return kind == name || (kind.substr(0, name.size()) == name && kind.size() > name.size() &&
                            kind[name.size()] == '.');
  });
}

}  // namespace

std::string diagnosticsDocUri() {
  std::error_code error;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    std::filesystem::path installed =
        exe.parent_path().parent_path() / "share/doc/scenefile/DIAGNOSTICS.md";
    if (std::filesystem::exists(installed, error)) {
      return uriOfPath(std::filesystem::weakly_canonical(installed, error));
    }
  }
  return uriOfPath(std::filesystem::path(SFLS_SOURCE_DOCS) / "DIAGNOSTICS.md");
}

nlohmann::json lspDiagnostic(const Document& document, const scene::Diagnostic& diagnostic,
                             const std::string& docUri) {
  std::string hint = tools::hintText(diagnostic);
  std::string message = diagnostic.message;
  if (!hint.empty()) message += "\nhint: " + hint;
  nlohmann::json out = {
      {"range", document.toLsp(diagnostic.span)},
      {"severity", lspSeverity(diagnostic.severity)},
      {"code", scene::codeName(diagnostic.code)},
      {"codeDescription", {{"href", docUri + "#" + std::string(scene::codeName(diagnostic.code))}}},
      {"source", "scenefile"},
      {"message", message}};
  if (!diagnostic.notes.empty()) {
    nlohmann::json related = nlohmann::json::array();
    for (const scene::DiagnosticNote& note : diagnostic.notes) {
      related.push_back(
          {{"location", {{"uri", document.uri()}, {"range", document.toLsp(note.span)}}},
           {"message", note.message}});
    }
    out["relatedInformation"] = std::move(related);
  }
  nlohmann::json data = nlohmann::json::object();
  if (!hint.empty()) data["hint"] = hint;
  if (diagnostic.fixIt) data["fixIt"] = textEdit(document, *diagnostic.fixIt);
  if (!data.empty()) out["data"] = std::move(data);
  return out;
}

nlohmann::json publishDiagnosticsParams(const Document& document, const Analysis& analysis,
                                        const std::string& docUri) {
  nlohmann::json diagnostics = nlohmann::json::array();
  for (const scene::Diagnostic& diagnostic : analysis.result.diagnostics.items()) {
    diagnostics.push_back(lspDiagnostic(document, diagnostic, docUri));
  }
  return {{"uri", document.uri()},
          {"version", analysis.version},
          {"diagnostics", std::move(diagnostics)}};
}

CodeActionQuery CodeActionQuery::fromParams(const nlohmann::json& params) {
  CodeActionQuery query;
  query.range = params.at("range").get<LspRange>();
  auto context = params.find("context");
  if (context == params.end() || !context->is_object()) return query;
  auto only = context->find("only");
  if (only == context->end() || !only->is_array()) return query;
  query.only.emplace();
  for (const nlohmann::json& kind : *only) {
    if (kind.is_string()) query.only->push_back(kind.get<std::string>());
  }
  return query;
}

nlohmann::json codeActions(const Document& document, const Analysis& analysis,
                           const CodeActionQuery& query, const std::string& docUri) {
  const LspRange& wanted = query.range;
  const auto& kinds = query.only;

  nlohmann::json actions = nlohmann::json::array();
  const scene::DiagnosticList& diagnostics = analysis.result.diagnostics;
  if (kindWanted(kinds, "quickfix")) {
    for (const scene::Diagnostic& diagnostic : diagnostics.items()) {
      if (!diagnostic.fixIt || !meets(document.toLsp(diagnostic.span), wanted)) continue;
      nlohmann::json edit = {
          {"changes",
           {{document.uri(), nlohmann::json::array({textEdit(document, *diagnostic.fixIt)})}}}};
      // A diagnostic carries one fix-it at most: it is always the one to take.
      actions.push_back(
          {{"title", fixItTitle(document, *diagnostic.fixIt)},
           {"kind", "quickfix"},
           {"diagnostics", nlohmann::json::array({lspDiagnostic(document, diagnostic, docUri)})},
           {"isPreferred", true},
           {"edit", std::move(edit)}});
    }
  }
  if (kindWanted(kinds, "source.fixAll")) {
    std::vector<scene::FixIt> fixIts = scene::applicableFixIts(diagnostics);
    if (fixIts.size() >= 2) {
      nlohmann::json edits = nlohmann::json::array();
      for (const scene::FixIt& fixIt : fixIts) edits.push_back(textEdit(document, fixIt));
      actions.push_back({{"title", "apply every fix-it (" + std::to_string(fixIts.size()) + ")"},
                         {"kind", "source.fixAll"},
                         {"edit", {{"changes", {{document.uri(), std::move(edits)}}}}}});
    }
  }
  return actions;
}

}  // namespace sfls
