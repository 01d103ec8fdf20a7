// Whole-file reads and writes that never leave a half-written file behind.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tools {

// The file's bytes, or nothing with the reason in `error`.
std::optional<std::string> readWholeFile(const std::filesystem::path& path, std::string& error);

// Writes `content` to a temporary file beside `path`, flushes it to disk and
// renames it over `path`: a reader sees the old file or the new one, never a
// part. False, with the reason in `error` and no file left over, on failure.
bool writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                         std::string& error);

// True when both paths name one existing file (through links too).
bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace tools
