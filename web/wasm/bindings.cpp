// The module's JavaScript API (embind): what the page and its render worker
// call (docs/WEB.md).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <exception>
#include <string>

#include "web/wasm/js_values.h"
#include "web/wasm/web_check.h"
#include "web/wasm/web_convert.h"
#include "web/wasm/web_editor.h"
#include "web/wasm/web_render.h"

namespace web {
namespace {

// `work`'s result; a C++ exception that escapes it (none should) becomes a
// JavaScript Error with its message, which the page can show, rather than
// an opaque WebAssembly.Exception.
template <typename Work>
auto guarded(Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const std::exception& e) {
    emscripten::val::global("Error").new_(std::string(e.what())).throw_();
  }
}

std::string check(const emscripten::val& input, const std::string& name) {
  return guarded([&] { return checkJson(bytesOf(input), name); });
}

// {output, materialLibrary, diagnostics}: output a string, a Uint8Array for
// a binary format, or null where sfconvert would refuse; materialLibrary an
// .obj's MTL file when `materialLibrary` names it ("": none, as on standard
// output).
emscripten::val convert(const emscripten::val& input, const std::string& name,
                        const std::string& to, const std::string& materialLibrary) {
  WebConversion conversion =
      guarded([&] { return convertText(bytesOf(input), name, to, materialLibrary); });
  emscripten::val answer = emscripten::val::object();
  answer.set("materialLibrary", conversion.materialLibrary);
  if (!conversion.output) {
    answer.set("output", emscripten::val::null());
  } else if (conversion.binary) {
    answer.set("output", uint8ArrayOf(*conversion.output));
  } else {
    answer.set("output", *conversion.output);
  }
  answer.set("diagnostics", conversion.diagnostics);
  return answer;
}

std::string hover(const std::string& text, std::uint32_t line, std::uint32_t character) {
  return guarded([&] { return hoverJson(text, line, character); });
}

std::string completion(const std::string& text, std::uint32_t line, std::uint32_t character) {
  return guarded([&] { return completionJson(text, line, character); });
}

// RenderSession as JavaScript sees it: the input a string or bytes, the
// band a Uint8Array (null when it cannot be rendered: status() says why).
class JsRenderSession {
 public:
  JsRenderSession(const emscripten::val& input, const std::string& name,
                  const std::string& optionsJson)
      : session_(guarded([&] { return RenderSession(bytesOf(input), name, optionsJson); })) {}

  std::string status() const { return session_.statusJson(); }

  emscripten::val renderRows(int y0, int y1, const std::string& overridesJson) {
    std::optional<std::vector<unsigned char>> rows =
        guarded([&] { return session_.renderRows(y0, y1, overridesJson); });
    if (!rows) return emscripten::val::null();
    return uint8ArrayOf(
        std::string_view(reinterpret_cast<const char*>(rows->data()), rows->size()));
  }

 private:
  RenderSession session_;
};

}  // namespace
}  // namespace web

EMSCRIPTEN_BINDINGS(scenefile) {
  emscripten::function("check", &web::check);
  emscripten::function("convert", &web::convert);
  emscripten::function("formats", &web::formatsJson);
  emscripten::function("defaultScene", &web::defaultSceneText);
  emscripten::function("defaultSceneName", &web::defaultSceneName);
  emscripten::function("hover", &web::hover);
  emscripten::function("completion", &web::completion);
  emscripten::class_<web::JsRenderSession>("RenderSession")
      .constructor<const emscripten::val&, const std::string&, const std::string&>()
      .function("status", &web::JsRenderSession::status)
      .function("renderRows", &web::JsRenderSession::renderRows);
}
