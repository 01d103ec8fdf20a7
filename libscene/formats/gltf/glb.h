// The GLB container of binary glTF: a 12-byte header, a JSON chunk and an
// optional BIN chunk, all little-endian and 4-byte aligned.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace scene {

inline constexpr std::string_view kGlbMagic = "glTF";

// The two chunks of a GLB file, pointing into the bytes they came from.
struct GlbChunks {
  std::string_view json;
  std::optional<std::string_view> bin;
};

// One GLB file: the JSON padded with spaces and the BIN chunk (left out when
// `bin` is empty) padded with zeros to a multiple of four bytes.
std::string encodeGlb(std::string_view json, std::string_view bin);

// The chunks of `bytes`, or nothing with the reason in `error`. Checks every
// length against what is there before trusting it: the header's total, each
// chunk's length and type, their alignment, and that nothing follows but
// chunks of unknown types, which the format says to skip.
std::optional<GlbChunks> decodeGlb(std::string_view bytes, std::string& error);

}  // namespace scene
