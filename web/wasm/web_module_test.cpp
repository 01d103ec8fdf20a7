// The web module's check() and convert() give what sfcheck --format json
// and sfconvert --to TO - - give for the same text: the page promises
// their output, so each is held to the tool itself, run in this process.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "libscene/testing/test_support.h"
#include "scenefile/format.h"
#include "tools/common/tool_streams.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfconvert/sfconvert.h"
#include "web/wasm/web_check.h"
#include "web/wasm/web_convert.h"

namespace {

struct ToolRun {
  int status = 0;
  std::string out;
  std::string err;
};

// `tool` run on `input` given on standard input.
template <typename Tool>
ToolRun runOnStandardInput(Tool tool, std::vector<const char*> args, const std::string& input) {
  std::istringstream in(input);
  std::ostringstream out;
  std::ostringstream err;
  tools::ToolStreams streams(in, out, err);
  ToolRun run;
  run.status = tool(static_cast<int>(args.size()), args.data(), streams);
  run.out = out.str();
  run.err = err.str();
  return run;
}

const std::filesystem::path kExamples = std::filesystem::path(SCENE_TESTDATA_DIR) / "../examples";

const std::vector<std::string>& sampleTexts() {
  static const std::vector<std::string> texts = {
      scene::testing::readText(kExamples / "red-sphere.sf"),
      scene::testing::readText(kExamples / "blue-cube.txt"),
      "CAMERA\n1 2 3\nSPHERE 1\n",
      "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n",  // no object
      "SPHERE\nnot a colour\n",
      "",
      "\xff\xfe not UTF-8\n",
  };
  return texts;
}

TEST(WebModule, CheckGivesSfchecksDiagnosticsAndTheRegistrysFormatName) {
  for (const std::string& text : sampleTexts()) {
    nlohmann::json mine = nlohmann::json::parse(web::checkJson(text, "<stdin>"));
    ToolRun native =
        runOnStandardInput(tools::runSfcheck, {"sfcheck", "--format", "json", "-"}, text);
    nlohmann::json report = nlohmann::json::parse(native.out);
    EXPECT_EQ(mine["diagnostics"], report["files"][0]["diagnostics"]) << text;
    std::optional<scene::Format> format = scene::detectFormat(text, "<stdin>");
    EXPECT_EQ(mine["format"], format ? nlohmann::json(std::string(scene::formatInfo(*format).name))
                                     : nlohmann::json(nullptr))
        << text;
  }
}

TEST(WebModule, ConvertGivesSfconvertsOutputToStandardOutput) {
  for (const std::string& text : sampleTexts()) {
    for (const scene::FormatInfo& row : scene::formats()) {
      std::string to(row.name);
      web::WebConversion mine = web::convertText(text, "<stdin>", to);
      ToolRun native =
          runOnStandardInput(tools::runSfconvert,
                             {"sfconvert", "--to", to.c_str(), "--format", "json", "-", "-"}, text);
      ASSERT_EQ(mine.output.has_value(), native.status == 0) << to << "\n" << text;
      if (mine.output) {
        EXPECT_EQ(*mine.output, native.out) << to << "\n" << text;
      }
      EXPECT_EQ(mine.binary, row.binary);
    }
  }
}

// Given the MTL file's name, an .obj and its MTL are the files
// `sfconvert - NAME.obj` writes; without it, the .obj alone.
TEST(WebModule, ConvertGivesAnObjWithItsMtlAsSfconvertWritesThem) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("web-module-obj-" + std::to_string(::getpid()));
  for (const std::string& text : sampleTexts()) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string objPath = (dir / "scene.obj").string();
    web::WebConversion mine = web::convertText(text, "<stdin>", "obj", "scene.mtl");
    ToolRun native =
        runOnStandardInput(tools::runSfconvert, {"sfconvert", "-q", "-", objPath.c_str()}, text);
    ASSERT_EQ(mine.output.has_value(), native.status == 0) << text;
    if (!mine.output) continue;
    EXPECT_EQ(*mine.output, scene::testing::readText(dir / "scene.obj")) << text;
    // sfconvert writes no empty MTL.
    const bool mtlWritten = std::filesystem::exists(dir / "scene.mtl");
    EXPECT_EQ(mine.materialLibrary, mtlWritten ? scene::testing::readText(dir / "scene.mtl") : "")
        << text;
    EXPECT_NE(mine.output->find("mtllib scene.mtl\n"), std::string::npos) << *mine.output;
    EXPECT_TRUE(web::convertText(text, "<stdin>", "obj").materialLibrary.empty());
  }
  std::filesystem::remove_all(dir);
}

TEST(WebModule, ConvertRefusesAFormatNotInTheRegistry) {
  web::WebConversion mine = web::convertText(sampleTexts()[0], "<stdin>", "ply");
  EXPECT_FALSE(mine.output);
  EXPECT_EQ(mine.diagnostics, "[]");
}

}  // namespace
