// How the tools write their outputs (file_io.h): whole or not at all, never
// over their own input, through links as the shell would, and never outside
// an instruction file's folder unless the user names the output. The tools
// run in-process with their streams captured; tests/integrity/ kills real
// runs with SIGKILL.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "tools/common/exit_code.h"
#include "tools/common/file_io.h"
#include "tools/common/output_location.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/sfrender/sfrender.h"
#include "tools/tool_test_support.h"

namespace tools {
namespace {

namespace fs = std::filesystem;

// An instruction file whose first line names its image.
std::string instructions(const std::string& outputFile) {
  return "OUTPUT_FILE " + outputFile +
         "\nSTART CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n"
         "START LIGHT\nLOCATION 3 3 3\nCOLOUR 1 1 1\nEND LIGHT\n"
         "START OBJECT SPHERE\nSTART MATERIAL\nCOLOUR 0 0 1\nEND MATERIAL\nEND OBJECT\n";
}

class IntegrityTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTestFolder("sfintegrity");
    fs::create_directories(dir_ / "work");
    fs::create_directories(dir_ / "outside");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Paths are relative to dir_/work; "../outside/..." lies beyond it.
  std::string path(const std::string& name) const { return (dir_ / "work" / name).string(); }

  std::string write(const std::string& name, const std::string& content) const {
    fs::create_directories(fs::path(path(name)).parent_path());
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

  std::string read(const std::string& name) const {
    return readWholeFile(path(name)).valueOr("<missing>");
  }

  // The names in a folder of dir_/work, to see that nothing stayed behind.
  std::vector<std::string> files(const std::string& folder = "") const {
    return fileNamesIn(dir_ / "work" / folder);
  }

  template <typename Tool>
  int run(Tool tool, const std::vector<std::string>& args) {
    return runTool(tool, args, out_, err_);
  }

  bool errorSays(const std::string& text) const {
    return err_.str().find(text) != std::string::npos;
  }

  fs::path dir_;
  std::ostringstream out_;
  std::ostringstream err_;
};

unsigned modeOf(const std::string& file) {
  struct stat info {};
  ::stat(file.c_str(), &info);
  return info.st_mode & 0777;
}

// --- file_io.h ---------------------------------------------------------------

TEST_F(IntegrityTest, NewFilesFollowTheUmaskAndReplacedFilesKeepTheirMode) {
  mode_t before = ::umask(027);
  ASSERT_FALSE(writeFileAtomically(path("new.sf"), "a"));
  EXPECT_EQ(modeOf(path("new.sf")), 0640u);
  ::umask(022);
  ASSERT_FALSE(writeFileAtomically(path("other.sf"), "a"));
  EXPECT_EQ(modeOf(path("other.sf")), 0644u);
  // A file the user made private stays private when it is written again.
  ::chmod(path("new.sf").c_str(), 0600);
  ASSERT_FALSE(writeFileAtomically(path("new.sf"), "b"));
  EXPECT_EQ(modeOf(path("new.sf")), 0600u);
  EXPECT_EQ(read("new.sf"), "b");
  ::umask(before);
}

TEST_F(IntegrityTest, WritingALinkReplacesTheFileItLeadsToAndKeepsTheLink) {
  write("real/scene.sf", "old");
  fs::create_symlink("real/scene.sf", path("link.sf"));
  ASSERT_FALSE(writeFileAtomically(path("link.sf"), "new"));
  EXPECT_TRUE(fs::is_symlink(path("link.sf")));
  EXPECT_EQ(read("real/scene.sf"), "new");
  EXPECT_EQ(files("real"), (std::vector<std::string>{"scene.sf"}));
  // A link to a file not there yet creates it, as the shell's '>' does.
  fs::create_symlink("real/later.sf", path("later.sf"));
  ASSERT_FALSE(writeFileAtomically(path("later.sf"), "made"));
  EXPECT_TRUE(fs::is_symlink(path("later.sf")));
  EXPECT_EQ(read("real/later.sf"), "made");
  // A loop of links is no file.
  fs::create_symlink("loop-b", path("loop-a"));
  fs::create_symlink("loop-a", path("loop-b"));
  EXPECT_EQ(writeFileAtomically(path("loop-a"), "x").value_or(ToolFailure{}).message,
            "its symbolic links cannot be followed (a loop, or more than 40)");
}

TEST_F(IntegrityTest, OnlyRegularFilesAreReplaced) {
  fs::create_directory(path("folder"));
  EXPECT_EQ(writeFileAtomically(path("folder"), "x").value_or(ToolFailure{}).message,
            "it is a directory");
  EXPECT_EQ(writeFileAtomically("/dev/null", "x").value_or(ToolFailure{}).message,
            "it is a character device, not a regular file");
  EXPECT_EQ(writeFileAtomically(path("missing/x.sf"), "x").value_or(ToolFailure{}).message,
            "its folder '" + path("missing") + "' does not exist");
  EXPECT_EQ(files(), (std::vector<std::string>{"folder"}));
}

// /dev/stdout leads through /proc/self/fd/1 to "pipe:[N]", a name no folder
// holds: it was taken for a loop of links. It is a pipe, and said so.
TEST_F(IntegrityTest, StandardOutputAsAFileIsNamedForWhatItIs) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  EXPECT_EQ(writeFileAtomically("/proc/self/fd/" + std::to_string(ends[1]), "x")
                .value_or(ToolFailure{})
                .message,
            "it is a pipe, not a regular file");
  ::close(ends[0]);
  ::close(ends[1]);
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  EXPECT_EQ(writeFileAtomically(path("fifo"), "x").value_or(ToolFailure{}).message,
            "it is a pipe, not a regular file");
  EXPECT_EQ(files(), (std::vector<std::string>{"fifo"}));
}

// An exception (std::bad_alloc from a writer) between the temporary's
// creation and its rename must not leave the temporary.
TEST_F(IntegrityTest, AnExceptionLeavesNoTemporary) {
  try {
    StagedFile file;
    ASSERT_FALSE(file.open(path("out.sf"), false));
    ASSERT_FALSE(file.write("part"));
    throw std::bad_alloc();
  } catch (const std::bad_alloc&) {
  }
  EXPECT_TRUE(files().empty());
}

// sfrender learns that its image cannot be written before the first ray:
// a render of hours (8192 x 8192, 1024 samples a pixel) fails at once. As
// root every folder is writable, so the cases are those root cannot write
// either: no folder, a file where the folder should be, /proc, a folder
// as the target; and a disk too full for a PPM's known size.
TEST_F(IntegrityTest, SfrenderFindsAnUnwritableTargetBeforeRendering) {
  write("file", "x");
  fs::create_directory(path("folder.ppm"));
  for (const std::string& target : {path("missing/x.ppm"), path("file/x.ppm"),
                                    std::string("/proc/sfrender-test.ppm"), path("folder.ppm")}) {
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(run(sfrender, {"sfrender", "-o", target, "--width", "8192", "--height", "8192",
                             "--spp", "1024", "--quiet"}),
              toInt(ExitCode::IoError))
        << target << ": " << err_.str();
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 1.0) << target;
    EXPECT_TRUE(errorSays(target + ": error: cannot write the image: ")) << err_.str();
  }
  EXPECT_TRUE(errorSays("it is a directory")) << err_.str();
  EXPECT_EQ(files(), (std::vector<std::string>{"file", "folder.ppm"}));
  std::string error =
      checkCanWrite(path("huge.ppm"), true, std::uint64_t{1} << 62).value_or(ToolFailure{}).message;
  EXPECT_NE(error.find("it needs 4611686018427387904 bytes but the file system has "),
            std::string::npos)
      << error;
  EXPECT_FALSE(checkCanWrite(path("small.ppm"), true, 100));
  EXPECT_EQ(files(), (std::vector<std::string>{"file", "folder.ppm"}));
}

TEST_F(IntegrityTest, TemporariesAreUniqueRecognisableAndNeverLeftByAnAbandonedWrite) {
  write("out.ppm", "old");
  StagedFile first;
  StagedFile second;
  ASSERT_FALSE(first.open(path("out.ppm"), true));
  ASSERT_FALSE(second.open(path("out.ppm"), false));
  std::string a = first.temporaryPath().filename().string();
  std::string b = second.temporaryPath().filename().string();
  EXPECT_NE(a, b);
  // .NAME.tmp-XXXXXX, and the extension again where it is kept.
  EXPECT_EQ(a.substr(0, 13), ".out.ppm.tmp-") << a;
  EXPECT_EQ(a.size(), std::string(".out.ppm.tmp-XXXXXX.ppm").size()) << a;
  EXPECT_EQ(a.substr(a.size() - 4), ".ppm");
  EXPECT_EQ(b.size(), std::string(".out.ppm.tmp-XXXXXX").size()) << b;
  ASSERT_FALSE(first.write("first"));
  ASSERT_FALSE(second.write("second"));
  // Until the rename, the target is the old file.
  EXPECT_EQ(read("out.ppm"), "old");
  ASSERT_FALSE(first.commit());
  EXPECT_EQ(read("out.ppm"), "first");
  {
    StagedFile abandoned;
    ASSERT_FALSE(abandoned.open(path("out.ppm"), false));
    ASSERT_FALSE(abandoned.write("never"));
  }
  ASSERT_FALSE(second.commit());
  EXPECT_EQ(read("out.ppm"), "second");
  EXPECT_EQ(files(), (std::vector<std::string>{"out.ppm"}));
}

// A name of `bytes` bytes ending in `extension`, made of `character`
// repeated (and as many 'a' as a whole character leaves over).
std::string nameOfBytes(std::size_t bytes, const std::string& character,
                        const std::string& extension) {
  std::string name;
  while (name.size() + character.size() + extension.size() <= bytes) name += character;
  name.append(bytes - name.size() - extension.size(), 'a');
  return name + extension;
}

bool isUtf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    std::size_t length = c < 0x80         ? 1
                         : (c >> 5) == 6  ? 2
                         : (c >> 4) == 14 ? 3
                         : (c >> 3) == 30 ? 4
                                          : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k) {
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    }
    i += length;
  }
  return true;
}

// Every name the file system takes (up to 255 bytes), ASCII or UTF-8 of 2, 3
// and 4 bytes a character: written, its temporary's name shortened to fit,
// kept UTF-8, unique and recognisable, with its extension where asked.
TEST_F(IntegrityTest, NamesUpToTheLongestTheFileSystemTakesAreWritten) {
  for (const std::string character : {"a", "\u00e9", "\u20ac", "\U0001F600"}) {
    for (std::size_t bytes = 240; bytes <= 255; ++bytes) {
      std::string name = nameOfBytes(bytes, character, ".png");
      SCOPED_TRACE(std::to_string(bytes) + " bytes of " + character);
      ASSERT_EQ(name.size(), bytes);
      ASSERT_FALSE(writeFileAtomically(path(name), "new"));
      EXPECT_EQ(read(name), "new");
      StagedFile first, second;
      ASSERT_FALSE(first.open(path(name), true));
      ASSERT_FALSE(second.open(path(name), false));
      std::string a = first.temporaryPath().filename().string();
      std::string b = second.temporaryPath().filename().string();
      EXPECT_NE(a, b);
      EXPECT_LE(a.size(), 255u);
      EXPECT_LE(b.size(), 255u);
      EXPECT_TRUE(isUtf8(a) && isUtf8(b)) << a << "\n" << b;
      EXPECT_EQ(a.substr(a.size() - 4), ".png");
      EXPECT_EQ(a.substr(0, 2), "." + name.substr(0, 1));
      EXPECT_NE(b.find(".tmp-"), std::string::npos);
      ASSERT_FALSE(first.write("first") || first.commit());
      EXPECT_EQ(read(name), "first");
    }
  }
  // Each target once, and nothing else: no temporary left.
  EXPECT_EQ(files().size(), 4u * 16u);
}

TEST_F(IntegrityTest, FilesThatBelongTogetherAreRenamedOnlyWhenAllAreWritten) {
  write("pair.bin", "old bin");
  // The second cannot be written, so the first is not renamed either.
  MaybeFailure failure = writeFilesAtomically(
      {{path("pair.bin"), "new bin"}, {path("missing/pair.gltf"), "new gltf"}});
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->file, path("missing/pair.gltf"));
  EXPECT_EQ(failure->code, ExitCode::IoError);
  EXPECT_EQ(read("pair.bin"), "old bin");
  EXPECT_EQ(files(), (std::vector<std::string>{"pair.bin"}));
  ASSERT_FALSE(writeFilesAtomically({{path("pair.bin"), "new bin"}, {path("pair.gltf"), "gltf"}}));
  EXPECT_EQ(read("pair.bin"), "new bin");
  EXPECT_EQ(read("pair.gltf"), "gltf");
}

// --- no tool writes over its own input --------------------------------------

TEST_F(IntegrityTest, SfconvertRefusesItsInputByAnyName) {
  std::string in = write("scene.sf", kValidScene);
  fs::create_symlink("scene.sf", path("soft.sf"));
  fs::create_hard_link(in, path("hard.sf"));
  for (const std::string& output :
       {in, path("soft.sf"), path("hard.sf"), (dir_ / "work" / "." / "scene.sf").string(),
        (dir_ / "work" / "sub" / ".." / "scene.sf").string()}) {
    fs::create_directories(dir_ / "work" / "sub");
    EXPECT_EQ(run(runSfconvert, {"sfconvert", in, output}), toInt(ExitCode::InvalidInput))
        << output;
    EXPECT_TRUE(errorSays("sfconvert: error: the output '" + output +
                          "' is the input file; sfconvert never writes over its input"))
        << err_.str();
    EXPECT_EQ(read("scene.sf"), kValidScene);
  }
  // A relative name from the input's own folder too.
  fs::path before = fs::current_path();
  fs::current_path(dir_ / "work");
  int status = run(runSfconvert, {"sfconvert", "scene.sf", "./scene.sf", "--to", "sf"});
  fs::current_path(before);
  EXPECT_EQ(status, toInt(ExitCode::InvalidInput)) << err_.str();
  EXPECT_EQ(read("scene.sf"), kValidScene);
}

TEST_F(IntegrityTest, SfconvertRefusesABufferFileThatIsTheInputOrTheOutput) {
  // A scene file may bear any name, a buffer's among them.
  std::string in = write("out.bin", kValidScene);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("out.gltf"), "--external-buffers"}),
            toInt(ExitCode::InvalidInput));
  EXPECT_TRUE(errorSays("sfconvert: error: the buffer file '" + path("out.bin") +
                        "' is the input file; sfconvert never writes over its input"))
      << err_.str();
  EXPECT_EQ(read("out.bin"), kValidScene);
  EXPECT_EQ(files(), (std::vector<std::string>{"out.bin"}));
  // --to gltf into NAME.bin would write the buffer and the .gltf to one file.
  std::string scene = write("s.sf", kValidScene);
  EXPECT_EQ(
      run(runSfconvert, {"sfconvert", scene, path("x.bin"), "--to", "gltf", "--external-buffers"}),
      toInt(ExitCode::Usage));
  EXPECT_TRUE(errorSays("is the output itself")) << err_.str();
  EXPECT_EQ(files(), (std::vector<std::string>{"out.bin", "s.sf"}));
}

TEST_F(IntegrityTest, SfconvertWritesAGltfAndItsBufferThroughALink) {
  std::string in = write("s.sf", kValidScene);
  fs::create_directories(dir_ / "work" / "real");
  fs::create_symlink("real/model.gltf", path("link.gltf"));
  ASSERT_EQ(run(runSfconvert, {"sfconvert", in, path("link.gltf"), "--external-buffers"}), 0)
      << err_.str();
  // The buffer lies beside the file written, under its name.
  EXPECT_EQ(files("real"), (std::vector<std::string>{"model.bin", "model.gltf"}));
  EXPECT_NE(read("real/model.gltf").find("\"uri\": \"model.bin\""), std::string::npos);
  EXPECT_EQ(run(runSfconvert, {"sfconvert", path("real/model.gltf"), path("back.sf")}), 0)
      << err_.str();
  EXPECT_EQ(run(runSfconvert, {"sfconvert", in, path("direct.sf")}), 0) << err_.str();
  EXPECT_EQ(read("back.sf"), read("direct.sf"));
}

TEST_F(IntegrityTest, SfrenderRefusesToWriteItsSceneByAnyName) {
  std::string scene = write("scene.sf", kValidScene);
  fs::create_symlink("scene.sf", path("soft.ppm"));
  fs::create_hard_link(scene, path("hard.ppm"));
  // -o naming the scene: by its own name (whose extension is no image
  // format: still told that it is the input), a link, a hard link.
  for (const std::string& output : {scene, path("soft.ppm"), path("hard.ppm")}) {
    EXPECT_EQ(run(sfrender, {"sfrender", scene, "-o", output, "--width", "8", "--height", "6"}),
              toInt(ExitCode::InvalidInput))
        << output;
    EXPECT_TRUE(errorSays("sfrender: error: the output '" + output +
                          "' is the input file; sfrender never writes over its input"))
        << err_.str();
    EXPECT_EQ(read("scene.sf"), kValidScene);
  }
  // An instruction file whose OUTPUT_FILE names itself.
  std::string self = write("self.txt", instructions("self.txt"));
  EXPECT_EQ(run(sfrender, {"sfrender", self, "--width", "8", "--height", "6"}),
            toInt(ExitCode::InvalidInput));
  EXPECT_TRUE(errorSays("is the input file; sfrender never writes over its input")) << err_.str();
  EXPECT_EQ(read("self.txt"), instructions("self.txt"));
  // The default name (the scene's, .png, in the current folder) is the scene.
  std::string odd = write("ball.png", kValidScene);
  fs::path before = fs::current_path();
  fs::current_path(dir_ / "work");
  int status = run(sfrender, {"sfrender", "ball.png", "--width", "8", "--height", "6"});
  fs::current_path(before);
  EXPECT_EQ(status, toInt(ExitCode::InvalidInput)) << err_.str();
  EXPECT_EQ(read("ball.png"), kValidScene);
}

// --- OUTPUT_FILE stays in its folder without -o ------------------------------

TEST_F(IntegrityTest, SfrenderKeepsOutputFileInItsFolder) {
  std::string outside = (dir_ / "outside").string();
  write("../outside/victim.ppm", "precious");
  fs::create_directory_symlink("../outside", path("out"));
  fs::create_symlink("../outside/victim.ppm", path("to-victim.ppm"));
  fs::create_symlink("../outside/new.ppm", path("to-new.ppm"));  // leads to nothing yet
  fs::create_symlink("to-new.ppm", path("chain.ppm"));           // a link to that link
  for (const std::string& name :
       {outside + "/abs.ppm", std::string("../outside/up.ppm"), std::string("a/../../x.ppm"),
        std::string("out/through-folder.ppm"), std::string("to-victim.ppm"),
        std::string("to-new.ppm"), std::string("chain.ppm")}) {
    std::string file = write("escape.txt", instructions(name));
    EXPECT_EQ(run(sfrender, {"sfrender", file, "--width", "8", "--height", "6"}),
              toInt(ExitCode::InvalidInput))
        << name;
    EXPECT_TRUE(errorSays("error: OUTPUT_FILE '" + name +
                          "' leaves the instruction file's folder [output-file-escapes]"))
        << err_.str();
    // sfcheck warns of the same.
    EXPECT_EQ(run(runSfcheck, {"sfcheck", "--werror", file}), 1) << name;
    EXPECT_TRUE(errorSays("[output-file-escapes]")) << err_.str();
  }
  EXPECT_EQ(read("../outside/victim.ppm"), "precious");
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir_ / "outside")) {
    left.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(left, (std::vector<std::string>{"victim.ppm"}));

  // A link that stays inside is followed; -o is the user's own choice.
  fs::create_directory(path("renders"));
  fs::create_symlink("renders/latest.ppm", path("latest.ppm"));
  std::string inside = write("inside.txt", instructions("latest.ppm"));
  EXPECT_EQ(run(sfrender, {"sfrender", inside, "--width", "8", "--height", "6", "--quiet"}), 0)
      << err_.str();
  EXPECT_TRUE(fs::is_symlink(path("latest.ppm")));
  EXPECT_EQ(read("renders/latest.ppm").substr(0, 9), "P6\n8 6\n25");
  std::string escaping = write("escape.txt", instructions("../outside/victim.ppm"));
  EXPECT_EQ(run(sfrender,
                {"sfrender", escaping, "-o", path("chosen.ppm"), "--width", "8", "--height", "6"}),
            0)
      << err_.str();
  EXPECT_EQ(read("../outside/victim.ppm"), "precious");
}

// glTF (in sfconvert's extras) and POV-Ray (in its exact-values comment)
// carry an OUTPUT_FILE too, and sfrender confines it the same way.
TEST_F(IntegrityTest, SfrenderIgnoresTheOutputFileThatOtherFormatsCarry) {
  // A glTF or POV-Ray file carries an instruction file's OUTPUT_FILE for its
  // round trip, here one that would leave the folder; it names no image:
  // sfrender writes NAME.png in the current folder, and nothing outside.
  std::string source = write("source.txt", instructions("../outside/x.ppm"));
  fs::path before = fs::current_path();
  for (std::string name : {"carried.gltf", "carried.glb", "carried.pov"}) {
    ASSERT_EQ(run(runSfconvert, {"sfconvert", source, path(name)}), 0) << err_.str();
    fs::current_path(dir_ / "work");
    int status = run(sfrender, {"sfrender", name, "--width", "8", "--height", "6"});
    fs::current_path(before);
    EXPECT_EQ(status, 0) << name << ": " << err_.str();
    EXPECT_TRUE(errorSays("sfrender: wrote carried.png (8x6)")) << name << ": " << err_.str();
    EXPECT_TRUE(fs::exists(dir_ / "work" / "carried.png")) << name;
    fs::remove(dir_ / "work" / "carried.png");
  }
  EXPECT_TRUE(fs::is_empty(dir_ / "outside"));
}

TEST_F(IntegrityTest, ALoopOfLinksInsideTheFolderIsReportedAsALoop) {
  fs::create_symlink("loop-b.ppm", path("loop-a.ppm"));
  fs::create_symlink("loop-a.ppm", path("loop-b.ppm"));
  std::string file = write("loop.txt", instructions("loop-a.ppm"));
  EXPECT_EQ(run(sfrender, {"sfrender", file, "--width", "8", "--height", "6"}),
            toInt(ExitCode::InvalidInput));
  EXPECT_TRUE(errorSays(file +
                        ":1:13: error: OUTPUT_FILE 'loop-a.ppm' leads into a loop of symbolic "
                        "links (or a chain of more than 40) [output-file-link-loop]"))
      << err_.str();
  EXPECT_FALSE(errorSays("leaves the instruction file's folder")) << err_.str();
  EXPECT_EQ(run(runSfcheck, {"sfcheck", file}), 0);
  EXPECT_TRUE(errorSays(":1:13: warning: OUTPUT_FILE 'loop-a.ppm' leads into a loop"))
      << err_.str();
  // With -o the loop is the user's to follow, and the write refuses it.
  EXPECT_EQ(run(sfrender, {"sfrender", file, "-o", path("loop-b.ppm"), "--width", "8"}),
            toInt(ExitCode::IoError));
  EXPECT_TRUE(errorSays("its symbolic links cannot be followed (a loop, or more than 40)"))
      << err_.str();
}

}  // namespace
}  // namespace tools
