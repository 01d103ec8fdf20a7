// The module's values crossing to JavaScript: an input that is a string
// (UTF-8 encoded by embind) or a Uint8Array of raw bytes, and bytes handed
// back as a Uint8Array of their own.
#pragma once

#include <emscripten/val.h>

#include <string>
#include <string_view>

namespace web {

// The bytes of a JavaScript string (UTF-8) or Uint8Array.
std::string bytesOf(const emscripten::val& input);

// A new Uint8Array holding a copy of `bytes`.
emscripten::val uint8ArrayOf(std::string_view bytes);

}  // namespace web
