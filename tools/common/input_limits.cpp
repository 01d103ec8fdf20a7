#include "tools/common/input_limits.h"

#include <sys/stat.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>

#include "scenefile/read.h"
#include "tools/common/file_io.h"
#include "tools/common/option_checks.h"
#include "tools/common/tool_streams.h"

namespace tools {

namespace {

// Standard input up to one byte past `maxBytes`, as readWholeFile reads a file.
Outcome<std::string> readStream(std::istream& in, std::uint64_t maxBytes) {
  std::string text;
  char chunk[1 << 16];
  int readError = 0;
  while (text.size() <= maxBytes) {
    std::uint64_t room = maxBytes + 1 - text.size();
    errno = 0;
    in.read(chunk, static_cast<std::streamsize>(std::min<std::uint64_t>(sizeof chunk, room)));
    readError = errno;
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  // std::cin takes a read that failed (standard input a folder, EISDIR, or
  // a failing disk, EIO) for the end of the input: the C stream under it
  // keeps the error, which an empty input would otherwise hide.
  if (in.bad() || (&in == &std::cin && std::ferror(stdin))) {
    return fileFailure(ExitCode::IoError, kStandardInputName,
                       readError != 0 ? std::strerror(readError) : "the read failed");
  }
  return text;
}

}  // namespace

void addReadLimitOptions(CLI::App& app, scene::ReadOptions& options) {
  app.add_option("--max-file-size", options.maxFileSize,
                 "refuse an input larger than this many bytes (suffixes such as 512MiB or 2GB "
                 "work)")
      ->option_text("SIZE")
      ->transform(sizeInBytes());
  app.add_option("--max-objects", options.maxObjects,
                 "stop reading at the first object or light past this many")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
  app.add_option("--max-vertices", options.gltf.maxVertices,
                 "glTF: refuse a file with more mesh vertices than this")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
  app.add_option("--max-nodes", options.gltf.maxNodes,
                 "glTF: refuse a file with more nodes and other objects than this (a material "
                 "counts 5, a camera or a light 2)")
      ->transform(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
}

std::string inputDisplayName(const std::string& file) {
  return isStandardStream(file) ? kStandardInputName : file;
}

InputText readInputText(const std::string& file, const scene::ReadOptions& options,
                        std::istream* standardInput) {
  InputText input{
      std::nullopt, {}, scene::DiagnosticList(inputDisplayName(file), options.errorLimit)};
  bool fromStream = isStandardStream(file) && standardInput;
  struct stat info {};
  if (!fromStream && ::stat(file.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    if (!scene::checkFileSize(static_cast<std::uint64_t>(info.st_size), options, input.refused)) {
      return input;
    }
  }
  Outcome<std::string> text = fromStream ? readStream(*standardInput, options.maxFileSize)
                                         : readWholeFile(file, options.maxFileSize);
  if (!text) {
    input.readError = text.failure().message;
    return input;
  }
  // Not a regular file, or one that grew: its whole size is unknown.
  if (!scene::checkFileSize(text->size(), options, input.refused, "the input", false)) {
    return input;
  }
  input.text = std::move(*text);
  return input;
}

}  // namespace tools
