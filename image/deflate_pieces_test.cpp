// deflatePieces: one zlib stream whatever the pieces, the same bytes for
// any number of threads.
#include "image/deflate_pieces.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

namespace image {
namespace {

// Bytes that compress somewhat: a slow ramp with noise, as an image's row.
std::vector<unsigned char> testData(std::size_t size) {
  std::vector<unsigned char> data(size);
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < size; ++i) {
    state = state * 1664525u + 1013904223u;
    data[i] = static_cast<unsigned char>((i / 97) + ((state >> 28) & 3));
  }
  return data;
}

std::string deflated(const std::vector<unsigned char>& data, std::size_t unit,
                     std::size_t pieceBytes, int threads) {
  PieceSource source;
  source.units = data.size() / unit;
  source.unitBytes = unit;
  source.pieceBytes = pieceBytes;
  // Odd units from the data itself, even ones through the scratch.
  source.unit = [&](std::size_t k, unsigned char* scratch) -> const unsigned char* {
    if (k % 2 == 1) return data.data() + k * unit;
    std::copy(data.begin() + k * unit, data.begin() + (k + 1) * unit, scratch);
    return scratch;
  };
  return deflatePieces(source, 2, threads);
}

std::vector<unsigned char> inflated(const std::string& stream, std::size_t size) {
  std::vector<unsigned char> out(size + 1);
  uLongf length = out.size();
  int status =
      uncompress(out.data(), &length, reinterpret_cast<const Bytef*>(stream.data()), stream.size());
  EXPECT_EQ(status, Z_OK);
  out.resize(length);
  return out;
}

TEST(DeflatePieces, ManyPiecesMakeOneStreamOfTheData) {
  std::vector<unsigned char> data = testData(301 * 333);
  // Pieces of 7 units of 301 bytes: 48 pieces, the last short.
  std::string stream = deflated(data, 301, 2000, 3);
  EXPECT_EQ(inflated(stream, data.size()), data);
  // uncompress checks the Adler-32; the header's check too.
  EXPECT_EQ(
      ((static_cast<unsigned char>(stream[0]) << 8) | static_cast<unsigned char>(stream[1])) % 31,
      0);
}

TEST(DeflatePieces, TheSameBytesForAnyThreads) {
  std::vector<unsigned char> data = testData(50'000);
  std::string one = deflated(data, 100, 4000, 1);
  EXPECT_EQ(deflated(data, 100, 4000, 2), one);
  EXPECT_EQ(deflated(data, 100, 4000, 5), one);
}

TEST(DeflatePieces, OnePieceAndNoData) {
  std::vector<unsigned char> data = testData(5000);
  EXPECT_EQ(inflated(deflated(data, 50, 1 << 20, 2), data.size()), data);
  std::vector<unsigned char> none;
  std::string empty = deflated(none, 10, 100, 2);
  ASSERT_FALSE(empty.empty());
  EXPECT_TRUE(inflated(empty, 0).empty());
}

}  // namespace
}  // namespace image
