// adviseHugePages and resizeOnHugePages: the contents are what a plain
// resize gives, small arrays are left alone, and where the kernel offers
// transparent huge pages on request, an advised array is backed by them.
#include "renderer/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace render {
namespace {

// The kernel's mode, the bracketed word of "always [madvise] never", or ""
// where the file is absent.
std::string transparentHugePageMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto open = text.find('['), close = text.find(']');
  return open == std::string::npos || close == std::string::npos
             ? ""
             : text.substr(open + 1, close - open - 1);
}

// AnonHugePages of the mapping that holds `address`, in kB (smaps).
long anonHugeKilobytesAt(const void* address) {
  std::ifstream in("/proc/self/smaps");
  auto at = reinterpret_cast<std::uintptr_t>(address);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    std::uintptr_t low = 0, high = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> low >> dash >> high && dash == '-') {
      inside = low <= at && at < high;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      return std::stol(line.substr(14));
    }
  }
  return -1;
}

TEST(HugePages, ContentsAreThoseOfAPlainResize) {
  for (std::size_t count : {0u, 1u, 1000u, 3u << 20}) {
    std::vector<std::uint32_t> advised;
    resizeOnHugePages(advised, count);
    EXPECT_EQ(advised, std::vector<std::uint32_t>(count)) << count;
  }
  // A vector already holding elements keeps them.
  std::vector<int> held{1, 2, 3};
  resizeOnHugePages(held, 5);
  EXPECT_EQ(held, (std::vector<int>{1, 2, 3, 0, 0}));
}

TEST(HugePages, SmallArraysAreNotAdvised) {
  std::vector<char> small(kHugePageBytes - 1);
  EXPECT_FALSE(adviseHugePages(small.data(), small.size()));
  EXPECT_FALSE(adviseHugePages(nullptr, 8 * kHugePageBytes));
}

TEST(HugePages, AnAdvisedArrayGetsHugePagesWhereTheKernelOffersThem) {
  std::string mode = transparentHugePageMode();
  if (mode != "madvise" && mode != "always") {
    GTEST_SKIP() << "transparent huge pages are \"" << mode << "\" here";
  }
  std::vector<std::uint64_t> advised;
  resizeOnHugePages(advised, 8 * kHugePageBytes / sizeof(std::uint64_t));
  EXPECT_GT(anonHugeKilobytesAt(advised.data() + advised.size() / 2), 0)
      << "8 huge pages' worth advised, none huge (mode " << mode << ")";
}

}  // namespace
}  // namespace render
