#include "web/wasm/web_editor.h"

#include <memory>

#include "tools/sfls/analysis.h"
#include "tools/sfls/document.h"
#include "tools/sfls/features.h"
#include "web/wasm/json_text.h"
#include "web/wasm/module_threads.h"

namespace web {
namespace {

// The page's one document, as the server holds an open one: the text and
// its analysis.
struct OpenDocument {
  sfls::Document document;
  std::shared_ptr<sfls::Analysis> analysis;
};

OpenDocument open(std::string text) {
  auto shared = std::make_shared<const std::string>(text);
  return {sfls::Document("untitled:scene", 1, std::move(text)),
          sfls::analyseText(shared, 1, "<stdin>", {}, moduleReadOptions())};
}

}  // namespace

std::string hoverJson(std::string text, std::uint32_t line, std::uint32_t character) {
  OpenDocument opened = open(std::move(text));
  return jsonText(sfls::hover(opened.document, opened.analysis.get(), {line, character}));
}

std::string completionJson(std::string text, std::uint32_t line, std::uint32_t character) {
  OpenDocument opened = open(std::move(text));
  return jsonText(
      sfls::completion(opened.document, opened.analysis.get(), {line, character}, true));
}

}  // namespace web
