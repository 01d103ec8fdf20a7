// The protocol's positions and ranges as JSON, both ways (nlohmann's
// to_json/from_json, found by argument-dependent lookup).
#pragma once

#include <nlohmann/json.hpp>

#include "tools/sfls/document.h"

namespace sfls {

// Member by member, as an initializer list would copy each value once more:
// a document's symbols hold thousands of these.
inline void to_json(nlohmann::json& out, const LspPosition& position) {
  out = nlohmann::json(nlohmann::json::value_t::object);
  out["line"] = position.line;
  out["character"] = position.character;
}

inline void from_json(const nlohmann::json& in, LspPosition& position) {
  in.at("line").get_to(position.line);
  in.at("character").get_to(position.character);
}

inline void to_json(nlohmann::json& out, const LspRange& range) {
  out = nlohmann::json(nlohmann::json::value_t::object);
  out["start"] = range.start;
  out["end"] = range.end;
}

inline void from_json(const nlohmann::json& in, LspRange& range) {
  in.at("start").get_to(range.start);
  in.at("end").get_to(range.end);
}

}  // namespace sfls
