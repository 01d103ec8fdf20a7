// What the language features' tests share: a document opened from a text
// or a file of testdata/ or examples/, and its check as the server makes it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "tools/sfls/check_worker.h"
#include "tools/sfls/document.h"

namespace sfls::feature_test {

inline std::filesystem::path sourcePath(const std::string& relative) {
  return std::filesystem::path(SCENE_TESTDATA_DIR).parent_path() / relative;
}

inline std::string readSource(const std::string& relative) {
  std::ifstream in(sourcePath(relative), std::ios::binary);
  EXPECT_TRUE(in) << relative;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A document and the check of its version.
struct Opened {
  Document document;
  std::shared_ptr<Analysis> analysis;
};

inline Opened openText(std::string text, const std::string& name = "scene.sf") {
  std::filesystem::path file = std::filesystem::temp_directory_path() / name;
  Document document("file://" + file.string(), 1, std::move(text));
  std::shared_ptr<Analysis> analysis =
      analyse(CheckJob{document.uri(), document.version(), document.sharedText(), file});
  return {std::move(document), std::move(analysis)};
}

// `relative` to the source tree's root: "testdata/valid/x.sf", "examples/...".
inline Opened openSource(const std::string& relative) {
  std::filesystem::path file = sourcePath(relative);
  Document document("file://" + file.string(), 1, readSource(relative));
  std::shared_ptr<Analysis> analysis =
      analyse(CheckJob{document.uri(), document.version(), document.sharedText(), file});
  return {std::move(document), std::move(analysis)};
}

}  // namespace sfls::feature_test
