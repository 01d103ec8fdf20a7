// The module's JavaScript API (embind): what the page and its render worker
// call (docs/WEB.md).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>

#include "web/wasm/js_values.h"
#include "web/wasm/web_check.h"
#include "web/wasm/web_convert.h"

namespace web {
namespace {

std::string check(const emscripten::val& input, const std::string& name) {
  return checkJson(bytesOf(input), name);
}

// {output, diagnostics}: output a string, a Uint8Array for a binary format,
// or null where sfconvert would refuse.
emscripten::val convert(const emscripten::val& input, const std::string& name,
                        const std::string& to) {
  WebConversion conversion = convertText(bytesOf(input), name, to);
  emscripten::val answer = emscripten::val::object();
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

}  // namespace
}  // namespace web

EMSCRIPTEN_BINDINGS(scenefile) {
  emscripten::function("check", &web::check);
  emscripten::function("convert", &web::convert);
  emscripten::function("formats", &web::formatsJson);
}
