#include "web/wasm/js_values.h"

namespace web {

std::string bytesOf(const emscripten::val& input) {
  if (input.isString()) return input.as<std::string>();
  std::string bytes(input["length"].as<std::size_t>(), '\0');
  // A view of the string's memory, filled by Uint8Array.set in one copy.
  emscripten::val view(emscripten::typed_memory_view(bytes.size(), bytes.data()));
  view.call<void>("set", input);
  return bytes;
}

emscripten::val uint8ArrayOf(std::string_view bytes) {
  emscripten::val view(emscripten::typed_memory_view(bytes.size(), bytes.data()));
  // slice() copies: the view would move with the module's memory.
  return view.call<emscripten::val>("slice");
}

}  // namespace web
