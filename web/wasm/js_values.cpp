#include "web/wasm/js_values.h"

namespace web {
namespace {

// A Uint8Array over `size` bytes of the module's memory at `data` (a view
// of char would be an Int8Array).
emscripten::val byteView(std::size_t size, const char* data) {
  return emscripten::val(
      emscripten::typed_memory_view(size, reinterpret_cast<const unsigned char*>(data)));
}

}  // namespace

std::string bytesOf(const emscripten::val& input) {
  if (input.isString()) return input.as<std::string>();
  std::string bytes(input["length"].as<std::size_t>(), '\0');
  // Filled by Uint8Array.set, in one copy.
  byteView(bytes.size(), bytes.data()).call<void>("set", input);
  return bytes;
}

emscripten::val uint8ArrayOf(std::string_view bytes) {
  // slice() copies: the view would move with the module's memory.
  return byteView(bytes.size(), bytes.data()).call<emscripten::val>("slice");
}

}  // namespace web
