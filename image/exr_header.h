// The attributes of an OpenEXR file's header, checked against the file
// before OpenEXR reads it (sfrender --merge's tiles).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace image {

// OpenEXR allocates the size an attribute declares before reading it, so a
// file of 300 bytes that declares a string of 1.7 GB costs 1.7 GB. Why the
// header in `bytes` (the file's first bytes; `fileSize` the whole file's)
// declares an attribute larger than the rest of the file, or does not end
// within `bytes`, as a sentence after the file's name; nothing when every
// attribute fits, or when `bytes` do not begin as OpenEXR's (another format
// is not this check's to judge).
std::optional<std::string> exrHeaderProblem(std::string_view bytes, std::uint64_t fileSize);

// How much of a file exrHeaderProblem is given: a tile's header (sfrender's
// are under 1 KiB) must end within it.
inline constexpr std::uint64_t kExrHeaderBytes = std::uint64_t{1} << 20;

}  // namespace image
