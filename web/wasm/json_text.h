// The module's JSON answers as text, as sfcheck and sfls write theirs: a
// byte that is not UTF-8 (a hostile file's, quoted in a message) becomes
// U+FFFD rather than an exception.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace web {

inline std::string jsonText(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace web
