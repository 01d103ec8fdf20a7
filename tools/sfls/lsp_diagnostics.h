// sfcheck's diagnostics as the protocol's Diagnostic and the fix-its as its
// code actions: the same spans, codes, messages and hints, in ranges of
// UTF-16 positions.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/diagnostic.h"
#include "tools/sfls/analysis.h"
#include "tools/sfls/document.h"

namespace sfls {

// Where a diagnostic's code is explained: the DIAGNOSTICS.md installed
// beside the program (PREFIX/share/doc/scenefile), else the source tree's.
// Each code's row of its table carries an anchor of the code's name, which
// a diagnostic's link adds (DIAGNOSTICS.md#unknown-keyword).
std::string diagnosticsDocUri();

// One diagnostic: range, severity (error 1, warning 2, note 3), code,
// codeDescription, source "scenefile", the message with the hint as its
// second line (the hint also in data.hint), the notes as relatedInformation,
// and the fix-it as data.fixIt (a TextEdit).
nlohmann::json lspDiagnostic(const Document& document, const scene::Diagnostic& diagnostic,
                             const std::string& docUri);

// textDocument/publishDiagnostics' params for `analysis` of `document`.
nlohmann::json publishDiagnosticsParams(const Document& document, const Analysis& analysis,
                                        const std::string& docUri);

// What a textDocument/codeAction request asks, read from its params (and
// only that kept: the params may nest a client's JSON arbitrarily deep).
struct CodeActionQuery {
  LspRange range;
  // context.only: the kinds wanted; nothing for every kind.
  std::optional<std::vector<std::string>> only;

  static CodeActionQuery fromParams(const nlohmann::json& params);
};

// textDocument/codeAction: a quickfix for each fix-it whose range meets the
// query's, and one source.fixAll with every fix-it that applies together
// (scene::applicableFixIts, as sfcheck --fix) where there are two or more.
nlohmann::json codeActions(const Document& document, const Analysis& analysis,
                           const CodeActionQuery& query, const std::string& docUri);

}  // namespace sfls
