#include "tools/common/output_file_format.h"

#include <gtest/gtest.h>

namespace tools {
namespace {

TEST(OutputFileFormat, AnImageExtensionInAnyCase) {
  EXPECT_TRUE(hasImageExtension("picture.png"));
  EXPECT_TRUE(hasImageExtension("dir.x/picture.PNG"));
  EXPECT_TRUE(hasImageExtension("picture.exr"));
  EXPECT_FALSE(hasImageExtension("picture"));
  EXPECT_FALSE(hasImageExtension("picture.txt"));
  EXPECT_FALSE(hasImageExtension("png"));
  for (std::string_view extension : imageExtensions()) {
    EXPECT_TRUE(hasImageExtension("a" + std::string(extension))) << extension;
  }
}

}  // namespace
}  // namespace tools
