#include "libscene/formats/gltf/glb.h"

#include <cstdint>

namespace scene {

namespace {

constexpr std::uint32_t kVersion = 2;
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

void appendU32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFF);
}

std::uint32_t readU32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) {
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  }
  return value;
}

std::size_t padded(std::size_t size) {
  return (size + 3) & ~std::size_t{3};
}

}  // namespace

std::string encodeGlb(std::string_view json, std::string_view bin) {
  std::size_t jsonLength = padded(json.size());
  std::size_t binLength = padded(bin.size());
  std::size_t total = 12 + 8 + jsonLength + (bin.empty() ? 0 : 8 + binLength);
  std::string out;
  out.reserve(total);
  out += kGlbMagic;
  appendU32(out, kVersion);
  appendU32(out, static_cast<std::uint32_t>(total));
  appendU32(out, static_cast<std::uint32_t>(jsonLength));
  appendU32(out, kJsonChunk);
  out += json;
  out.append(jsonLength - json.size(), ' ');
  if (!bin.empty()) {
    appendU32(out, static_cast<std::uint32_t>(binLength));
    appendU32(out, kBinChunk);
    out += bin;
    out.append(binLength - bin.size(), '\0');
  }
  return out;
}

std::optional<GlbChunks> decodeGlb(std::string_view bytes, std::string& error) {
  if (bytes.size() < 12 || bytes.substr(0, 4) != kGlbMagic) {
    error = "the file is too short for a GLB header (12 bytes)";
    return std::nullopt;
  }
  std::uint32_t version = readU32(bytes, 4);
  if (version != kVersion) {
    error = "GLB version " + std::to_string(version) + " is not 2";
    return std::nullopt;
  }
  std::uint32_t length = readU32(bytes, 8);
  if (length != bytes.size()) {
    error = "the GLB header gives a length of " + std::to_string(length) +
            " bytes, but the file has " + std::to_string(bytes.size());
    return std::nullopt;
  }
  GlbChunks chunks;
  std::size_t at = 12;
  bool first = true;
  while (at < bytes.size()) {
    if (bytes.size() - at < 8) {
      error = "a chunk header at byte " + std::to_string(at) + " is cut short";
      return std::nullopt;
    }
    std::uint32_t chunkLength = readU32(bytes, at);
    std::uint32_t type = readU32(bytes, at + 4);
    at += 8;
    if (chunkLength > bytes.size() - at) {
      error = "a chunk at byte " + std::to_string(at - 8) + " claims " +
              std::to_string(chunkLength) + " bytes, but only " +
              std::to_string(bytes.size() - at) + " follow";
      return std::nullopt;
    }
    if (chunkLength % 4 != 0) {
      error = "a chunk at byte " + std::to_string(at - 8) + " has a length of " +
              std::to_string(chunkLength) + ", not a multiple of 4";
      return std::nullopt;
    }
    std::string_view data = bytes.substr(at, chunkLength);
    if (first) {
      if (type != kJsonChunk) {
        error = "the first chunk is not the JSON chunk";
        return std::nullopt;
      }
      chunks.json = data;
      first = false;
    } else if (type == kJsonChunk) {
      error = "a second JSON chunk at byte " + std::to_string(at - 8);
      return std::nullopt;
    } else if (type == kBinChunk) {
      if (chunks.bin) {
        error = "a second BIN chunk at byte " + std::to_string(at - 8);
        return std::nullopt;
      }
      chunks.bin = data;
    }
    at += chunkLength;
  }
  if (first) {
    error = "the file has no JSON chunk";
    return std::nullopt;
  }
  return chunks;
}

}  // namespace scene
