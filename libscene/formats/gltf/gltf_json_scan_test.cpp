#include "libscene/formats/gltf/gltf_json_scan.h"

#include <gtest/gtest.h>

#include <string>

namespace scene::gltf {
namespace {

std::string nested(int levels) {
  return std::string(levels, '[') + std::string(levels, ']');
}

TEST(GltfJsonScan, TheDepthLimitIsTheByteOfTheFirstBracketPastIt) {
  EXPECT_FALSE(scanJson(nested(4), 4).tooDeepAt);
  EXPECT_EQ(scanJson(nested(5), 4).tooDeepAt, 4u);
  EXPECT_EQ(scanJson(R"({"a": [{"b": [[]]}]})", 4).tooDeepAt, 14u);
  // Brackets inside strings, escaped quotes included, do not nest.
  EXPECT_FALSE(scanJson(R"({"a\"[[[[": "[[[[\\", "b": []})", 2).tooDeepAt);
}

TEST(GltfJsonScan, ObjectsOfTopLevelArraysAreCountedByWeight) {
  EXPECT_EQ(scanJson(R"({"nodes": [{}, {}], "materials": [{}], "cameras": [{}],)"
                     R"( "lights": [{}, {}], "scenes": [{"nodes": [{}]}]})",
                     64)
                .objects,
            2u + 5u + 2u + 4u + 1u);
  // Only objects directly in a top-level array count: not those in an
  // array of arrays, nor the arrays themselves.
  EXPECT_EQ(scanJson(R"({"nodes": [[{}], {}, []], "x": {"nodes": [{}]}})", 64).objects, 1u);
  EXPECT_EQ(scanJson(R"({"nodes": [{}], "x": "[{}, {}]"})", 64).objects, 1u);
}

// Text that is not JSON is scanned as ever, so that what it is refused for
// does not change: a stray closer lowers the depth below 0 (it delays the
// limit), but no container closes that was not opened (the count goes on).
TEST(GltfJsonScan, StrayClosersLowerTheDepthButCloseNoContainer) {
  EXPECT_FALSE(scanJson("]]" + nested(5), 4).tooDeepAt);
  EXPECT_EQ(scanJson("]]" + nested(7), 4).tooDeepAt, 8u);
  EXPECT_EQ(scanJson(R"(]]{"nodes": [{}, {}, {}]})", 64).objects, 3u);
  EXPECT_EQ(scanJson(R"({"nodes": [{}, {}]}{"nodes": [{}]})", 64).objects, 3u);
}

}  // namespace
}  // namespace scene::gltf
