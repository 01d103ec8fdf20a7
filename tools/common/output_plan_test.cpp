#include "tools/common/output_plan.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tools/sfconvert/sfconvert.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Runs in `folder` while it lives, then back where it was.
class InFolder {
 public:
  explicit InFolder(const fs::path& folder) : back_(fs::current_path()) {
    fs::current_path(folder);
  }
  ~InFolder() { fs::current_path(back_); }
  InFolder(const InFolder&) = delete;
  InFolder& operator=(const InFolder&) = delete;

 private:
  fs::path back_;
};

TEST(FileIdentity, OneFileHoweverSpelled) {
  fs::path root = freshTestFolder("output-plan");
  InFolder here(root);
  fs::create_directories("x/y");
  writeText("x/a", "a");
  fs::create_directory_symlink("x", "l");
  fs::create_hard_link("x/a", "h");
  fs::create_symlink("a", "x/s");
  fs::create_symlink("n", "x/dangling");
  for (const char* spelling : {"x/./a", "x//a", "x/../x/a", "l/a", "h", "x/s", "x/y/../a"}) {
    EXPECT_EQ(fileIdentity(spelling), fileIdentity("x/a")) << spelling;
  }
  EXPECT_EQ(fileIdentity(root / "x/a"), fileIdentity("x/a"));
  // Files not there yet: their folder and name.
  for (const char* spelling : {"x/./n", "x//n", "x/../x/n", "l/n", "x/dangling", "x/y/../n"}) {
    EXPECT_EQ(fileIdentity(spelling), fileIdentity("x/n")) << spelling;
  }
  EXPECT_EQ(fileIdentity(root / "l/n"), fileIdentity("x/n"));
  EXPECT_EQ(fileIdentity("x/new/deeper/n"), fileIdentity("l/new/./deeper/n"));
  EXPECT_NE(fileIdentity("x/n"), fileIdentity("x/m"));
  EXPECT_NE(fileIdentity("x/n"), fileIdentity("x/a"));
  EXPECT_NE(fileIdentity("x/y/a"), fileIdentity("x/a"));
}

TEST(OutputPlan, FindsTheFirstClashAndSaysIt) {
  fs::path root = freshTestFolder("output-plan");
  InFolder here(root);
  fs::create_directory("x");
  writeText("x/a.sf", "a");
  writeText("px.txt", "p");
  OutputPlan none;
  none.addInput("x/a.sf");
  none.addInput("-");
  none.addOutput("x/a.png", "x/a.sf");
  none.addOutput("-", "x/a.sf");
  EXPECT_FALSE(none.firstClash());

  OutputPlan overInput;
  overInput.addInput("p.sf");
  overInput.addInput("px.txt");
  overInput.addOutput("./px.txt", "p.sf");
  std::optional<OutputClash> clash = overInput.firstClash();
  ASSERT_TRUE(clash);
  EXPECT_TRUE(clash->overInput);
  EXPECT_EQ(overInput.describe(*clash),
            "'p.sf' would write './px.txt', which is the input 'px.txt'");

  OutputPlan shared;
  shared.addInput("x/a.sf");
  shared.addInput("x/./a.txt");
  shared.addOutput("x/a.png", "x/a.sf");
  shared.addOutput("x/./a.png", "x/./a.txt");
  shared.addOutput("x/b.bin", "x/./a.txt", "its buffer");
  shared.addOutput("x/b.bin", "x/a.sf", "its buffer");
  clash = shared.firstClash();
  ASSERT_TRUE(clash);
  EXPECT_FALSE(clash->overInput);
  EXPECT_EQ(shared.describe(*clash),
            "'x/a.sf' would write 'x/a.png' and 'x/./a.txt' would write 'x/./a.png', which is the "
            "same file");
  EXPECT_EQ(shared.describe(OutputClash{false, 3, 2}),
            "'x/./a.txt' would write 'x/b.bin' (its buffer) and 'x/a.sf' would write 'x/b.bin' "
            "(its buffer)");
}

// The property: random batches of sfconvert (random names: dots, `...sf`,
// newlines, 255 bytes, UTF-8; random folders, linked and hard-linked
// inputs, the same input spelled otherwise; random patterns) either are
// refused with nothing written, or write only inside the pattern's folder,
// each output once, and no input.

// Every entry under `root`: its inode and content (a link's target).
using Snapshot = std::map<std::string, std::pair<ino_t, std::string>>;

Snapshot snapshot(const fs::path& root) {
  Snapshot files;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path& path = it->path();
    struct stat info {};
    ::lstat(path.c_str(), &info);
    std::string content;
    if (it->is_symlink()) {
      content = "-> " + fs::read_symlink(path).string();
    } else if (it->is_regular_file()) {
      std::ifstream in(path, std::ios::binary);
      content.assign(std::istreambuf_iterator<char>(in), {});
    } else {
      content = "(folder)";
    }
    files[fs::relative(path, root).string()] = {info.st_ino, content};
  }
  return files;
}

class RandomBatch {
 public:
  explicit RandomBatch(unsigned seed) : random_(seed) {}

  // Lays out the inputs in the current folder; returns the command line's
  // inputs.
  std::vector<std::string> makeInputs(const fs::path& root) {
    for (const char* folder : {"in", "in/sub", "other", "out", "out/sub"}) {
      fs::create_directories(folder);
    }
    fs::create_directory_symlink("in", "ln");
    std::vector<std::string> inputs;
    int count = 1 + pick(4);
    for (int i = 0; i < count; ++i) {
      int kind = pick(10);
      if (kind == 0 && !inputs.empty()) {
        inputs.push_back(respell(inputs[pick(inputs.size())], root));
        continue;
      }
      if (kind == 1) {
        inputs.push_back("-");
        continue;
      }
      std::string path = folder() + name();
      if (fs::exists(fs::symlink_status(path))) continue;
      if (kind == 2 && !inputs.empty() && inputs.back() != "-" && fs::exists(inputs.back())) {
        fs::create_hard_link(inputs.back(), path);
      } else if (kind == 3 && !inputs.empty() && inputs.back() != "-" &&
                 fs::exists(inputs.back())) {
        fs::create_symlink(fs::absolute(inputs.back()), path);
      } else {
        writeText(path, kValidScene);
      }
      inputs.push_back(path);
    }
    // Folders for patterns that mirror the inputs' folders.
    for (const std::string& input : inputs) {
      std::string folder = fs::path(input).parent_path().string();
      if (!folder.empty() && fs::path(folder).is_relative()) {
        std::error_code ec;
        fs::create_directories("out" / fs::path(folder).lexically_normal(), ec);
      }
    }
    return inputs;
  }

  std::string pattern() {
    static const char* kPrefixes[] = {"", "out/", "out/sub/", "in/", "{dir}/", "out/{dir}/"};
    static const char* kNames[] = {"{stem}",   "{name}",   "x{stem}",     "{stem}/x",
                                   "{stem}.y", "{name}-c", "{stem}{stem}"};
    static const char* kExtensions[] = {".sf", ".txt", ".pov", ".sf"};
    return std::string(kPrefixes[pick(std::size(kPrefixes))]) + kNames[pick(std::size(kNames))] +
           kExtensions[pick(std::size(kExtensions))];
  }

 private:
  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }

  std::string folder() {
    static const char* kFolders[] = {"", "in/", "in/sub/", "other/", "ln/", "./in/"};
    return kFolders[pick(std::size(kFolders))];
  }

  std::string name() {
    static const char* kNames[] = {"a.sf",
                                   "a.txt",
                                   "...sf",
                                   "..sf",
                                   ".sf",
                                   "...",
                                   "a.",
                                   "a..sf",
                                   "b.sf",
                                   "b.pov",
                                   "new\nline.sf",
                                   "caf\xc3\xa9.sf",
                                   "\xe6\x97\xa5.sf",
                                   "x.sf.sf",
                                   "in.sf",
                                   "a.b.sf"};
    std::size_t which = pick(std::size(kNames) + 2);
    if (which == std::size(kNames)) return std::string(252, 'n') + ".sf";  // 255 bytes
    if (which == std::size(kNames) + 1) {
      std::string random;
      for (std::size_t i = 0, n = 1 + pick(6); i < n; ++i) random += "ab.\n"[pick(4)];
      return random;
    }
    return kNames[which];
  }

  // The same file spelled otherwise.
  std::string respell(const std::string& input, const fs::path& root) {
    if (input == "-") return input;
    fs::path path(input);
    switch (pick(4)) {
      case 0:
        return (path.parent_path() / "." / path.filename()).string();
      case 1:
        return (root / path).string();
      case 2:
        return path.parent_path().string() + "//" + path.filename().string();
      default:
        return input;
    }
  }

  std::mt19937 random_;
};

// The folder that `pattern` names before its first placeholder; empty when
// it begins with {dir} (the input's own folder then).
std::string fixedFolder(const std::string& pattern) {
  std::string fixed = pattern.substr(0, pattern.find('{'));
  return fixed.substr(0, fixed.rfind('/') == std::string::npos ? 0 : fixed.rfind('/'));
}

bool within(const fs::path& folder, const fs::path& path) {
  fs::path base = fs::weakly_canonical(folder);
  fs::path where = fs::weakly_canonical(path.parent_path());
  auto [end, ignored] = std::mismatch(base.begin(), base.end(), where.begin(), where.end());
  return end == base.end();
}

// What a batch did to the files under `root`, held to the promises: a
// refusal (exit 2) changed nothing; otherwise no input changed, every file
// written is one that `allowed` allows and no temporary, and each input done
// wrote a file of its own (`done`: how many, from the summary). Gives the
// number of files written, or -1 for a refusal.
int checkOutcome(const fs::path& root, const std::vector<std::string>& inputs,
                 const Snapshot& before, const Snapshot& after, int status, const std::string& err,
                 const std::string& tool, const std::function<bool(const fs::path&)>& allowed) {
  if (status == 2) {
    EXPECT_EQ(after, before) << "refused, yet something changed: " << err;
    return -1;
  }
  int written = 0;
  for (const auto& [path, entry] : after) {
    auto old = before.find(path);
    if (old != before.end() && old->second == entry) continue;
    ++written;
    EXPECT_EQ(path.find(".tmp-"), std::string::npos) << "a temporary stayed: " << path;
    EXPECT_TRUE(allowed(root / path)) << "'" << path << "' lies outside; " << err;
  }
  for (const auto& [path, entry] : before) {
    EXPECT_TRUE(after.count(path)) << "'" << path << "' went away";
  }
  // Each input untouched: the same file (inode) with the same bytes.
  for (const std::string& input : inputs) {
    if (input == "-") continue;
    std::string key = fs::relative(fs::weakly_canonical(input), fs::canonical(root)).string();
    if (before.count(key)) {
      EXPECT_EQ(after.at(key), before.at(key)) << "input '" << input << "' changed";
    }
  }
  // (-q: the summary only when one failed.)
  std::size_t done = status == 0 ? inputs.size() : 0;
  if (std::size_t at = err.rfind(tool + ": ");
      status != 0 && at != std::string::npos && err.find(" of ", at) != std::string::npos) {
    done = std::stoul(err.substr(at + tool.size() + 2));
  }
  EXPECT_EQ(static_cast<std::size_t>(written), done) << err;
  return written;
}

// A fixed seed: a failure names the batch, and the same one comes back.
constexpr unsigned kSeed = 20261206;

TEST(OutputPlanProperty, RandomBatchesKeepEveryPromise) {
  constexpr int kBatches = 250;
  std::mt19937 seeds(kSeed);
  int accepted = 0, refused = 0, files = 0;
  for (int batch = 0; batch < kBatches; ++batch) {
    fs::path root = freshTestFolder("output-plan-property");
    InFolder here(root);
    RandomBatch random(seeds());
    std::vector<std::string> inputs = random.makeInputs(root);
    std::string pattern = random.pattern();
    std::vector<std::string> args = {"sfconvert", "-q"};
    args.insert(args.end(), inputs.begin(), inputs.end());
    args.insert(args.end(), {"-o", pattern});
    std::string shown = "batch " + std::to_string(batch) + ": -o '" + pattern + "'";
    for (const std::string& input : inputs) shown += " '" + input + "'";
    SCOPED_TRACE(shown);

    Snapshot before = snapshot(root);
    std::ostringstream out, err;
    int status = runTool(runSfconvert, args, out, err, kValidScene);
    fs::path folder = root / fixedFolder(pattern);
    int written = checkOutcome(root, inputs, before, snapshot(root), status, err.str(), "sfconvert",
                               [&](const fs::path& path) { return within(folder, path); });
    written < 0 ? ++refused : ++accepted;
    files += std::max(written, 0);
  }
  std::cout << "[ property ] " << accepted << " batches accepted, " << refused << " refused, "
            << files << " files written\n";
  // Both kinds occur, or the property says little.
  EXPECT_GT(accepted, kBatches / 10);
  EXPECT_GT(refused, kBatches / 10);
  EXPECT_GT(files, kBatches / 2);
}

// sfrender without -o: each scene's own image (OUTPUT_FILE in its folder,
// else NAME.ppm here), read ahead; the same promises, the images only here
// or in an instruction file's folder.
TEST(OutputPlanProperty, RandomRenderBatchesWithoutOutputKeepEveryPromise) {
  constexpr int kBatches = 60;
  static const char* kFolders[] = {"", "in/", "in/sub/", "ln/", "other/", "./in/"};
  static const char* kNames[] = {"s", "t", "pic", "p.png"};
  static const char* kOutputFiles[] = {"pic.png", "sub/pic.png", "s.ppm",  "../pic.png",
                                       "p.png",   "t.ppm",       "pic.ppm"};
  std::mt19937 random(kSeed + 1);
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
  };
  int accepted = 0, refused = 0;
  for (int batch = 0; batch < kBatches; ++batch) {
    fs::path root = freshTestFolder("output-plan-render-property");
    InFolder here(root);
    for (const char* folder : {"in/sub", "other"}) fs::create_directories(folder);
    fs::create_directory_symlink("in", "ln");
    std::vector<std::string> inputs;
    std::vector<fs::path> folders = {root};
    for (std::size_t i = 0, n = 2 + pick(3); i < n; ++i) {
      std::string folder = kFolders[pick(std::size(kFolders))];
      std::string name = kNames[pick(std::size(kNames))];
      bool instructions = pick(2) == 0;
      std::string path = folder + name + (instructions ? ".txt" : ".sf");
      if (pick(8) == 0) path = "-";
      if (path != "-" && !fs::exists(path)) {
        std::ofstream(path) << (instructions ? instructionsWriting(
                                                   kOutputFiles[pick(std::size(kOutputFiles))])
                                             : kValidScene);
      }
      if (instructions && path != "-") folders.push_back(fs::path(path).parent_path());
      inputs.push_back(path);
    }
    std::vector<std::string> args = {"sfrender", "-q", "--width", "4", "--height", "3"};
    args.insert(args.end(), inputs.begin(), inputs.end());
    std::string shown = "batch " + std::to_string(batch) + ":";
    for (const std::string& input : inputs) shown += " '" + input + "'";
    SCOPED_TRACE(shown);

    Snapshot before = snapshot(root);
    std::ostringstream out, err;
    int status = runTool(sfrender, args, out, err, kValidScene);
    int written = checkOutcome(
        root, inputs, before, snapshot(root), status, err.str(), "sfrender",
        [&](const fs::path& path) {
          return std::any_of(folders.begin(), folders.end(),
                             [&](const fs::path& folder) { return within(root / folder, path); });
        });
    written < 0 ? ++refused : ++accepted;
  }
  std::cout << "[ property ] " << accepted << " batches accepted, " << refused << " refused\n";
  EXPECT_GT(accepted, kBatches / 10);
  EXPECT_GT(refused, kBatches / 10);
}

}  // namespace
}  // namespace tools
