// What a run will write, checked before anything is written or rendered:
// no output is one of the run's inputs, and no two outputs are one file
// (docs/SECURITY.md, "What each tool writes"). Files are compared by what
// they are, not by how they are spelled: a file that exists by its device
// and inode (through symbolic links, and hard links name one inode), a file
// not there yet by the nearest of its folders that exists and the rest of
// its path. So `x/a`, `x/./a`, `x//a`, `x/../x/a`, `/abs/x/a` and a linked
// folder's `l/a` are all one file.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tools {

// What a path names, as a read or a write through it reaches it (the links
// of its last component followed, as open() and file_io.h's writes do).
struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t inode = 0;
  std::string below;  // for a file not there yet: its path below that folder

  auto operator<=>(const FileIdentity&) const = default;
};

FileIdentity fileIdentity(const std::filesystem::path& path);

// An output that may not be written: it is an input (`other` indexes the
// inputs), or an earlier output is the same file (`other` indexes the
// outputs).
struct OutputClash {
  bool overInput = false;
  std::size_t output = 0;
  std::size_t other = 0;
};

class OutputPlan {
 public:
  // A file the run reads; "-" (standard input) is no file and is skipped.
  void addInput(const std::string& path);
  // A file the run writes, made from the input `from` (for messages);
  // `role`, when given, says what it is ("its buffer"). "-" is skipped.
  void addOutput(const std::string& path, const std::string& from, const std::string& role = {});

  // The first output, in the order added, that is an input or an earlier
  // output; every identity is taken at this one moment.
  std::optional<OutputClash> firstClash() const;
  // "'p.sf' would write 'px.txt', which is the input 'px.txt'", or "'a.sf'
  // and 'b.sf' would both write 'a.png'" (each spelling and role given where
  // they differ).
  std::string describe(const OutputClash& clash) const;

  const std::string& input(std::size_t i) const { return inputs_[i]; }
  const std::string& output(std::size_t i) const { return outputs_[i].path; }

 private:
  struct Output {
    std::string path;
    std::string from;
    std::string role;
  };
  std::string wouldWrite(const Output& output) const;

  std::vector<std::string> inputs_;
  std::vector<Output> outputs_;
};

// Whether writing `output` would write over `input` (a plan of one of
// each); false for no input ("", the default scene) or standard input.
bool writesOverInput(const std::string& input, const std::string& output);

}  // namespace tools
