#include "image/exr_header.h"

namespace image {

namespace {

std::uint32_t littleEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

// The NUL-terminated text at `at`, of at most `longest` bytes, or nothing
// when it does not end there; `at` moves past its NUL.
std::optional<std::string_view> text(std::string_view bytes, std::size_t& at, std::size_t longest) {
  std::size_t end = bytes.find('\0', at);
  if (end == std::string_view::npos || end - at > longest) return std::nullopt;
  std::string_view found = bytes.substr(at, end - at);
  at = end + 1;
  return found;
}

}  // namespace

std::optional<std::string> exrHeaderProblem(std::string_view bytes, std::uint64_t fileSize) {
  if (bytes.size() < 8 || bytes.substr(0, 4) != std::string_view("\x76\x2f\x31\x01", 4)) {
    return std::nullopt;
  }
  std::uint32_t version = littleEndian32(bytes, 4);
  bool multipart = (version & 0x1000) != 0;
  std::size_t longest = (version & 0x400) != 0 ? 255 : 31;  // long names
  const std::string cut =
      "'s OpenEXR header is cut short or longer than " + std::to_string(kExrHeaderBytes) + " bytes";
  std::size_t at = 8;
  for (;;) {  // a header a part: attributes, then an empty name
    for (;;) {
      std::optional<std::string_view> name = text(bytes, at, longest);
      if (!name) return cut;
      if (name->empty()) break;
      std::optional<std::string_view> type = text(bytes, at, longest);
      if (!type || at + 4 > bytes.size()) return cut;
      std::uint64_t size = littleEndian32(bytes, at);
      at += 4;
      if (at > fileSize || size > fileSize - at) {
        return "'s OpenEXR attribute '" + std::string(*name) + "' declares " +
               std::to_string(size) + " bytes, more than the " + std::to_string(fileSize) +
               " of the file";
      }
      if (at + size > bytes.size()) return cut;
      at += static_cast<std::size_t>(size);
    }
    // A multi-part file's headers end with an empty one.
    if (!multipart) return std::nullopt;
    if (at >= bytes.size()) return cut;
    if (bytes[at] == '\0') return std::nullopt;
  }
}

}  // namespace image
