// The format registry: one row per format of formats.def, in its order, each
// complete, and detection, lookups and conversions all going through it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/convert.h"
#include "scenefile/format.h"
#include "scenefile/read.h"

namespace scene {
namespace {

const std::string kScene = testing::kCameraRecord +
                           "LIGHT\n1 1 1\n1 0 0 0\n0 1 0 5\n0 0 1 0\n0 0 0 1\n"
                           "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 -3\n0 0 0 1\n";

TEST(FormatRegistry, HasOneCompleteRowPerFormatInTheOrderOfTheList) {
  std::vector<Format> listed = {
#define SCENEFILE_FORMAT(enumerator, name, folder, row) Format::enumerator,
#include "scenefile/formats.def"
#undef SCENEFILE_FORMAT
  };
  ASSERT_EQ(formats().size(), listed.size());
  std::set<std::string_view> names, extensions;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const FormatInfo& row = formats()[i];
    EXPECT_EQ(row.format, listed[i]) << row.name;
    EXPECT_EQ(&formatInfo(row.format), &row);
    EXPECT_TRUE(names.insert(row.name).second) << "two formats named " << row.name;
    EXPECT_FALSE(row.singular.empty() || row.plural.empty() || row.startsWith.empty());
    ASSERT_FALSE(row.extensions.empty()) << row.name;
    for (std::string_view extension : row.extensions) {
      EXPECT_TRUE(extension.starts_with('.')) << extension;
      EXPECT_TRUE(extensions.insert(extension).second) << "two formats claim " << extension;
    }
    EXPECT_NE(row.recognise, nullptr) << row.name;
    EXPECT_NE(row.read, nullptr) << row.name;
    EXPECT_NE(row.write, nullptr) << row.name;
  }
}

TEST(FormatRegistry, FindsEachFormatByNameAndByExtension) {
  for (const FormatInfo& row : formats()) {
    ASSERT_NE(findFormatByName(row.name), nullptr);
    EXPECT_EQ(findFormatByName(row.name)->format, row.format);
    for (std::string_view extension : row.extensions) {
      std::string file = "some/folder/scene" + std::string(extension);
      ASSERT_NE(findFormatByExtension(file), nullptr) << file;
      EXPECT_EQ(findFormatByExtension(file)->format, row.format);
    }
    EXPECT_NE(describeFormats().find(row.plural), std::string::npos) << describeFormats();
    EXPECT_NE(formatNames().find(row.name), std::string::npos);
  }
  EXPECT_EQ(findFormatByName("povray"), nullptr);
  EXPECT_EQ(findFormatByExtension("scene.SF"), nullptr) << "extensions compare exactly";
  EXPECT_EQ(findFormatByExtension("scene"), nullptr);
  EXPECT_EQ(formatNames(), "sf, instructions, gltf, glb, pov, obj");
}

// Every format writes the scene in a form its own reader recognises by
// content alone, whatever the file is called, and reads back.
TEST(FormatRegistry, EveryFormatRecognisesAndReadsWhatItWrites) {
  ReadResult original = parseScene(kScene, "a.sf");
  ASSERT_TRUE(original.ok());
  for (const FormatInfo& row : formats()) {
    DiagnosticList out;
    std::optional<std::string> written = convertScene(original.scene, row.format, {}, out);
    ASSERT_TRUE(written) << row.name;
    EXPECT_NE(row.recognise(*written), Recognition::None) << row.name;
    EXPECT_EQ(detectFormat(*written, "no-extension"), row.format) << row.name;
    ReadResult back = parseSceneAs(row.format, *written, "back" + std::string(row.extensions[0]));
    EXPECT_TRUE(back.ok()) << row.name;
    EXPECT_EQ(back.scene.objects.size(), 1u) << row.name;
    EXPECT_EQ(back.scene.lights.size(), 1u) << row.name;
  }
}

TEST(FormatRegistry, TheUnknownFormatErrorNamesEveryFormat) {
  ReadResult r = parseScene("hello world\n", "notes");
  ASSERT_EQ(r.diagnostics.items().size(), 1u);
  const Diagnostic& d = r.diagnostics.items()[0];
  EXPECT_EQ(d.code, DiagnosticCode::UnknownFormat);
  for (const FormatInfo& row : formats()) {
    EXPECT_NE(d.message.find(row.singular), std::string::npos) << d.message;
    EXPECT_NE(d.hint.find(row.startsWith), std::string::npos) << d.hint;
  }
}

TEST(FormatRegistry, TheExtensionDecidesOnlyWhatTheContentLeavesOpen) {
  // Content that says nothing: a .pov is POV-Ray, anything else a scene file.
  EXPECT_EQ(detectFormat("", "empty.pov"), Format::Pov);
  EXPECT_EQ(detectFormat("\n\n", "empty.sf"), Format::SceneFile);
  EXPECT_EQ(detectFormat("", ""), Format::SceneFile);
  // Content in no format: only POV-Ray, which has no signature, goes by name.
  EXPECT_EQ(detectFormat("hello\n", "a.pov"), Format::Pov);
  EXPECT_EQ(detectFormat("hello\n", "a.sf"), std::nullopt);
  EXPECT_EQ(detectFormat("hello\n", "a.gltf"), std::nullopt);
  // Content wins over the name.
  EXPECT_EQ(detectFormat("CAMERA\n", "a.pov"), Format::SceneFile);
  EXPECT_EQ(detectFormat("OUTPUT_FILE a.ppm\n", "a.sf"), Format::InstructionFile);
  EXPECT_EQ(detectFormat("{\"asset\": {}}", "a.sf"), Format::Gltf);
  // A POV-Ray directive is certain, over the line formats' first word.
  EXPECT_EQ(detectFormat("#version 3.7;\ncamera { location 0 }\n", "a.txt"), Format::Pov);
}

TEST(FormatRegistry, ReadingAsANamedFormatIgnoresTheContentsClaim) {
  ReadResult asInstructions = parseSceneAs(Format::InstructionFile, kScene, "a.txt");
  EXPECT_FALSE(asInstructions.ok()) << "a scene file is no instruction file";
  ReadResult tooLarge = parseSceneAs(Format::SceneFile, kScene, "a.sf", [] {
    ReadOptions options;
    options.maxFileSize = 10;
    return options;
  }());
  ASSERT_FALSE(tooLarge.ok());
  EXPECT_EQ(tooLarge.diagnostics.items()[0].code, DiagnosticCode::FileTooLarge);
}

}  // namespace
}  // namespace scene
