// Inputs that try to cost time or memory: each is answered with a
// diagnostic, in bounded time, like any other input.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>

#include "libscene/testing/test_support.h"
#include "scenefile/read.h"

namespace scene {
namespace {

// The seconds a scene takes to parse whose sphere's colour line ends in a
// number of `digits` sevens, checking its one diagnostic.
double secondsToParseALongNumber(std::size_t digits) {
  const std::string tail = "\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  std::string text = testing::kCameraRecord + "SPHERE\n1 1 ";
  text.reserve(text.size() + digits + tail.size());
  text.append(digits, '7');
  text += tail;
  // Past the default maxFileSize (1 GiB) at a billion digits: raised, so
  // that the reader itself meets the line.
  ReadOptions options;
  options.maxFileSize = text.size();
  auto start = std::chrono::steady_clock::now();
  ReadResult r = parseScene(text, "big.sf", options);
  double seconds = testing::secondsSince(start);
  testing::expectOne(r.diagnostics, DiagnosticCode::NumberOutOfRange, 8, 5);
  EXPECT_EQ(r.diagnostics.errorCount(), 1u);
  return seconds;
}

// A colour line whose third number has a billion digits, read in time in
// proportion to its length. A sixteenth of it, read first, gives the pace of
// this machine and build: the whole may take sixteen times as long, and
// four times that for the noise of a busy machine (256 times, were the
// read quadratic).
TEST(HostileInput, AOneGigabyteLine) {
  double sixteenth = secondsToParseALongNumber(std::size_t{1} << 26);
  double whole = secondsToParseALongNumber(std::size_t{1} << 30);
  EXPECT_LT(whole, 64 * sixteenth) << sixteenth << " s, then " << whole;
}

TEST(HostileInput, BinaryGarbage) {
  std::mt19937_64 rng(42);
  for (int round = 0; round < 20; ++round) {
    std::string text(1 << 20, '\0');
    for (char& c : text) c = static_cast<char>(rng());
    auto start = std::chrono::steady_clock::now();
    ReadResult r = parseScene(text, "garbage");
    EXPECT_LT(testing::secondsSince(start), 5.0);
    EXPECT_TRUE(r.diagnostics.hasErrors());
    EXPECT_LE(r.diagnostics.items().size(), 2 * DiagnosticList::kDefaultErrorLimit + 1);
  }
}

TEST(HostileInput, PrintableGarbageInBothFormats) {
  // Random tokens drawn from the formats' own words and numbers: the
  // readers must recover from any order of them.
  const char* words[] = {
      "CAMERA",   "LIGHT",          "SPHERE",   "CUBE",        "START", "END", "OBJECT",
      "MATERIAL", "TRANSFORMATION", "LOCATION", "COLOUR",      "SCALE", "1",   "0",
      "-1",       "1e400",          "nan",      "OUTPUT_FILE", "x.ppm", "\n",  "\n",
      "\n"};
  std::mt19937_64 rng(7);
  for (int round = 0; round < 2000; ++round) {
    std::string text = round % 2 ? "OUTPUT_FILE a.ppm\n" : "";
    int count = static_cast<int>(rng() % 400);
    for (int i = 0; i < count; ++i) {
      text += words[rng() % std::size(words)];
      text += ' ';
    }
    ReadResult r = parseScene(text, "noise");
    for (const Diagnostic& d : r.diagnostics.items()) {
      ASSERT_GE(d.span.line, 1u) << text;
      ASSERT_GE(d.span.column, 1u) << text;
    }
  }
}

}  // namespace
}  // namespace scene
