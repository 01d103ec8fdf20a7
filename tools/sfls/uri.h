// file: URIs as editors send them, and the paths they name.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace sfls {

// The path of a file: URI ("file:///a%20b/c.sf" -> "/a b/c.sf"); nothing
// for another scheme (untitled:, a remote one) or a malformed escape.
std::optional<std::filesystem::path> pathOfUri(std::string_view uri);

// The file: URI of an absolute path, with what RFC 3986 reserves escaped.
std::string uriOfPath(const std::filesystem::path& path);

}  // namespace sfls
