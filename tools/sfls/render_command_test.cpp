#include "tools/sfls/render_command.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tools/common/file_io.h"
#include "tools/tool_test_support.h"

namespace sfls {
namespace {

namespace fs = std::filesystem;

class RenderCommandTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = tools::freshTestFolder("sfls-render"); }
  void TearDown() override { fs::remove_all(dir_); }

  RenderOutcome render(const std::string& name, const std::string& text, nlohmann::json arguments,
                       const render::CancelFlag& cancel = {}) {
    fractions_.clear();
    RenderRequest request{text, dir_ / name, std::move(arguments)};
    return renderDocument(
        request, [&](double fraction, std::string_view) { fractions_.push_back(fraction); },
        cancel);
  }

  std::vector<std::string> files() const { return tools::fileNamesIn(dir_); }

  fs::path dir_;
  std::vector<double> fractions_;
};

const nlohmann::json kSmall = {{"width", 16}, {"height", 12}};

TEST_F(RenderCommandTest, AScenesImageIsItsStemWithPngBesideIt) {
  RenderOutcome outcome = render("scene.sf", tools::kValidScene, kSmall);
  ASSERT_EQ(outcome.failure, "");
  EXPECT_FALSE(outcome.cancelled);
  EXPECT_EQ(outcome.image, dir_ / "scene.png");
  // The document's text is rendered, not the file (there is none here).
  EXPECT_EQ(tools::readWholeFile(dir_ / "scene.png")->substr(0, 4), "\x89PNG");
  ASSERT_FALSE(fractions_.empty());
  EXPECT_EQ(fractions_.back(), 1.0);
  // The LSP's array of arguments holding the object, and an output.
  outcome = render("scene.sf", tools::kValidScene,
                   nlohmann::json::array({{{"width", 8}, {"height", 8}, {"output", "out.ppm"}}}));
  EXPECT_EQ(outcome.image, dir_ / "out.ppm") << outcome.failure;
  EXPECT_EQ(files(), (std::vector<std::string>{"out.ppm", "scene.png"}));
}

TEST_F(RenderCommandTest, AnInstructionFilesOutputFileInItsFolderAndNoFurther) {
  RenderOutcome outcome = render("pic.txt", tools::instructionsWriting("pic.ppm"), kSmall);
  EXPECT_EQ(outcome.image, dir_ / "pic.ppm") << outcome.failure;
  outcome = render("out.txt", tools::instructionsWriting("../out.ppm"), kSmall);
  EXPECT_FALSE(outcome.image);
  EXPECT_NE(outcome.failure.find("OUTPUT_FILE '../out.ppm' leaves"), std::string::npos)
      << outcome.failure;
  EXPECT_EQ(files(), std::vector<std::string>{"pic.ppm"});
}

TEST_F(RenderCommandTest, ArgumentsOfTheWrongTypeOrOutOfRangeAreRefusedByName) {
  auto failure = [&](nlohmann::json arguments) {
    return render("scene.sf", tools::kValidScene, std::move(arguments)).failure;
  };
  EXPECT_EQ(failure({{"spp", 0}}), "spp: 0 is not between 1 and 1024");
  EXPECT_EQ(failure({{"depth", 65}}), "depth: 65 is not between 0 and 64");
  EXPECT_EQ(failure({{"width", "800"}}), "width: \"800\" is not a number");
  EXPECT_EQ(failure({{"width", 1.5}}), "width: '1.5' is not a whole number");
  EXPECT_EQ(failure({{"adaptive", 0}}), "adaptive: 0 is not above 0 and at most 1");
  EXPECT_EQ(failure({{"output", 3}}), "output: 3 is not the name of an image file");
  EXPECT_EQ(failure({{"widht", 3}}).substr(0, 26), "unknown argument 'widht'; ");
  EXPECT_EQ(failure(nlohmann::json::array({1, 2})),
            "the arguments are [1,2], not an object such as {\"width\": 800}");
  EXPECT_EQ(failure({{"width", 8192}, {"height", 8193}}),
            "width and height make 67117056 pixels, more than the limit of 67108864");
  EXPECT_EQ(files(), std::vector<std::string>{});
}

TEST_F(RenderCommandTest, ADocumentWithErrorsIsNotRendered) {
  RenderOutcome outcome = render("bad.sf", tools::kValidScene + "sphere\n", kSmall);
  EXPECT_EQ(outcome.failure.substr(0, 30), "the document has errors: 19:1:");
  EXPECT_EQ(files(), std::vector<std::string>{});
}

TEST_F(RenderCommandTest, ACancelledRenderWritesNothing) {
  render::CancelFlag cancel;
  cancel.request();
  RenderOutcome outcome = render("scene.sf", tools::kValidScene, kSmall, cancel);
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_FALSE(outcome.image);
  // Cancelled while it runs, from the progress of its first tile.
  render::CancelFlag midway;
  RenderRequest request{
      tools::kValidScene, dir_ / "scene.sf", {{"width", 256}, {"height", 256}, {"threads", 1}}};
  outcome = renderDocument(
      request,
      [&](double fraction, std::string_view) {
        if (fraction > 0) midway.request();
      },
      midway);
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_EQ(files(), std::vector<std::string>{});
}

}  // namespace
}  // namespace sfls
