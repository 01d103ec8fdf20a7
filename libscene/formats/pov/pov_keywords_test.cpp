// The POV-Ray objects of scenefile/object_kinds.def: each kind's keyword
// names it back, and each is a statement the reader knows.
#include "libscene/formats/pov/pov_keywords.h"

#include <gtest/gtest.h>

namespace scene {
namespace {

TEST(PovKeywords, EachObjectKindHasAnObjectThatNamesItBack) {
  for (ObjectKind kind : kObjectKinds) {
    std::string_view keyword = povObjectKeyword(kind);
    ASSERT_TRUE(povObjectKind(keyword).has_value()) << keyword;
    EXPECT_EQ(*povObjectKind(keyword), kind);
    EXPECT_TRUE(isPovStatement(keyword)) << keyword;
  }
  EXPECT_EQ(povObjectKeyword(ObjectKind::Cube), "box");
  EXPECT_FALSE(povObjectKind("object").has_value());
  EXPECT_FALSE(povObjectKind("SPHERE").has_value());
}

}  // namespace
}  // namespace scene
