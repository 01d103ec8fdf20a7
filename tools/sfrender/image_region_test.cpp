#include "tools/sfrender/image_region.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

namespace tools {
namespace {

TEST(ImageRegion, ReadsFourWholeNumbers) {
  std::optional<render::PixelRegion> r = parseRegion("7,5,40,31");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->x0, 7);
  EXPECT_EQ(r->y0, 5);
  EXPECT_EQ(r->width(), 33);
  EXPECT_EQ(r->height(), 26);
  for (const char* bad :
       {"", "1,2,3", "1,2,3,4,5", "1,2,3,x", "1;2;3;4", "1,2,3,4,", "1.5,2,3,4"}) {
    EXPECT_FALSE(parseRegion(bad)) << bad;
  }
}

TEST(ImageRegion, ReadsATile) {
  std::optional<TileChoice> t = parseTile("2/4");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->index, 2);
  EXPECT_EQ(t->count, 4);
  EXPECT_FALSE(parseTile("2"));
  EXPECT_FALSE(parseTile("2/4/8"));
}

TEST(ImageRegion, RefusesWhatLeavesTheImage) {
  EXPECT_FALSE(regionRefusal({0, 0, 640, 480}, 640, 480));
  EXPECT_TRUE(regionRefusal({0, 0, 641, 480}, 640, 480));
  EXPECT_TRUE(regionRefusal({0, 10, 640, 10}, 640, 480));  // empty
  EXPECT_TRUE(regionRefusal({-1, 0, 5, 5}, 640, 480));
  EXPECT_FALSE(tileRefusal({0, 480}, 480));
  EXPECT_TRUE(tileRefusal({0, 481}, 480));
  MaybeFailure outside = regionRefusal({0, 0, 641, 480}, 640, 480);
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->code, ExitCode::Usage);
  EXPECT_EQ(outside->message.rfind("--region: ", 0), 0u) << outside->message;
  EXPECT_EQ(tileRefusal({0, 481}, 480)->code, ExitCode::Usage);
}

TEST(ImageRegion, TheOptionsChecksSayWhatIsWrong) {
  std::string empty = "5,0,5,3", outside = "-1,0,5,5", fine = "0,0,5,5", tile = "4/4";
  EXPECT_NE(regionOption()(empty).find("empty"), std::string::npos);
  EXPECT_NE(regionOption()(outside).find("below 0"), std::string::npos);
  EXPECT_EQ(regionOption()(fine), "");
  EXPECT_NE(tileOption()(tile).find("between 0 and 3"), std::string::npos);
}

}  // namespace
}  // namespace tools
