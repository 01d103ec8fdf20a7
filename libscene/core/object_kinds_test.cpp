// The object kinds of scenefile/object_kinds.def: the enum, the record names
// and the messages' list all follow its lines, in their order.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "scenefile/scene.h"

namespace scene {
namespace {

TEST(ObjectKinds, FollowTheListInItsOrder) {
  ASSERT_EQ(std::size(kObjectKinds), 4u);
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < std::size(kObjectKinds); ++i) {
    ObjectKind kind = kObjectKinds[i];
    // The enum's numbers are the list's places: the GPU shader's kind
    // numbers and every table indexed by kind rely on it.
    EXPECT_EQ(static_cast<std::size_t>(kind), i);
    std::string_view name = objectKindName(kind);
    EXPECT_TRUE(names.insert(name).second) << "two kinds named " << name;
    ASSERT_TRUE(objectKindFromName(name).has_value()) << name;
    EXPECT_EQ(*objectKindFromName(name), kind);
  }
  EXPECT_EQ(objectKindName(ObjectKind::Plane), "PLANE");
  EXPECT_EQ(objectKindName(ObjectKind::Cube), "CUBE");
}

TEST(ObjectKinds, KnowOnlyTheirRecordNamesExactly) {
  EXPECT_FALSE(objectKindFromName("sphere").has_value());
  EXPECT_FALSE(objectKindFromName("CAMERA").has_value());
  EXPECT_FALSE(objectKindFromName("").has_value());
}

TEST(ObjectKinds, AreOfferedInMessagesInTheListsOrder) {
  EXPECT_EQ(objectKindChoices(), "PLANE, SPHERE, CYLINDER or CUBE");
}

}  // namespace
}  // namespace scene
