// The reader's entry points. The work is in layers, each over the one
// before: pov_lexer.h (characters to tokens), pov_token_stream.h
// (lookahead, brace depth, skipping and recovery), pov_evaluator.h
// (directives, declared names, expressions), pov_modifiers.h (transforms
// and textures), pov_statements.h (camera, lights, objects), and then
// pov_scene_builder.h, which builds the scene from what they gathered.
#include "libscene/formats/pov/pov_reader.h"

#include <utility>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/formats/pov/pov_scene_builder.h"
#include "libscene/formats/pov/pov_statements.h"

namespace scene {

PovImport importPov(std::string_view text, std::string fileName, const ReadOptions& options) {
  PovImport result{
      ReadResult{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)}, {}, {}};
  if (text.size() > kMaxPovBytes) {
    result.read.diagnostics.error(
        DiagnosticCode::PovLimit, SourceSpan{1, 1, 0},
        "the file is larger than " + std::to_string(kMaxPovBytes >> 20) + " MiB: refused");
    return result;
  }
  PovStatementReader reader(text, options, result.read.diagnostics);
  if (reader.run()) {
    buildPovScene(reader.parts(), reader.defaults(), reader.lexer().exactComments(), options,
                  result);
  }
  return result;
}

bool looksLikePov(std::string_view text) {
  std::size_t i = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  auto isWordChar = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  // Blanks and // comments first, which say nothing (the other formats'
  // readers report them as errors).
  for (;;) {
    while (i < text.size() && isSpace(text[i])) ++i;
    if (text.compare(i, 2, "//") != 0) break;
    while (i < text.size() && text[i] != '\n') ++i;
  }
  if (text.compare(i, 2, "/*") == 0) return true;
  if (i < text.size() && text[i] == '#') {
    std::size_t j = i + 1;
    while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
    std::size_t start = j;
    while (j < text.size() && isWordChar(text[j])) ++j;
    return isPovDirectiveName(text.substr(start, j - start));
  }
  std::size_t start = i;
  while (i < text.size() && isWordChar(text[i])) ++i;
  std::string_view word = text.substr(start, i - start);
  if (!isPovStatement(word) && !isPovUnsupportedStatement(word)) return false;
  // The brace may follow on a later line, after comments.
  for (;;) {
    while (i < text.size() && isSpace(text[i])) ++i;
    if (text.compare(i, 2, "//") != 0) break;
    while (i < text.size() && text[i] != '\n') ++i;
  }
  return i < text.size() && text[i] == '{';
}

}  // namespace scene
