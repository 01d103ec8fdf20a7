// docs/ACCURACY.md, "Acne": no self-shadowing speckle ("acne")
// at any scale from 1e-6 to 1e6, nor for scenes placed up to 1e6 away from
// the origin.
//
// The acne scene (acne_scene.h) at each layout, at one sample per pixel: a
// pixel whose surface faces the light (cosine > 0.1) with a clear path to
// it must not be drawn at ambient level, nor below its ambient + diffuse
// floor; one whose path is blocked must be; no pixel may be NaN or
// infinite; and the object ids agree with the reference away from outlines.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "renderer/render.h"
#include "tests/geometry/acne_measure.h"

namespace acne {
// Names the layout in gtest's messages.
void PrintTo(const Layout& layout, std::ostream* out) {
  *out << "scale " << layout.label;
}
}  // namespace acne

namespace {

class Acne : public testing::TestWithParam<acne::Layout> {};

void checkNoAcne(const acne::Measurement& m) {
  const acne::Counts& c = m.counts;
  std::printf("[ acne ] scale %-28s geometry %.3f%% (%d differ; %d by the image's colours)\n",
              m.layout.label.c_str(), 100.0 * (m.pixels - m.disagree) / m.pixels, m.disagree,
              m.colourDisagree);
  for (int p = 0; p < acne::kPrimitives; ++p) {
    std::printf("[ acne ]   %-18s dark lit %-18s under-lit %-18s shadow leaks %s\n",
                acne::kPrimitiveNames[p], acne::fraction(c.darkLit[p], c.lit[p]).c_str(),
                acne::fraction(c.underLit[p], c.lit[p]).c_str(),
                acne::fraction(c.leaks[p], c.shadowed[p]).c_str());
    EXPECT_GT(c.lit[p], 0) << acne::kPrimitiveNames[p] << " has no lit pixel to judge";
    EXPECT_EQ(c.darkLit[p], 0) << acne::kPrimitiveNames[p];
    EXPECT_EQ(c.underLit[p], 0) << acne::kPrimitiveNames[p];
    EXPECT_EQ(c.leaks[p], 0) << acne::kPrimitiveNames[p];
  }
  EXPECT_EQ(c.nonFinite, 0);
  EXPECT_EQ(m.disagreeOffEdge, 0);
  EXPECT_EQ(m.colourDisagreeOffEdge, 0);
  EXPECT_GE(m.pixels - m.disagree, 0.995 * m.pixels);
}

TEST_P(Acne, LitPixelsAreNeverDrawnAtAmbientLevel) {
  checkNoAcne(acne::measureRenderer(GetParam()));
}

// The same checks on the GPU path (lavapipe where no GPU is present), and
// its image against the CPU's: at least 99.9% of the channels within 1/255.
TEST_P(Acne, GpuLitPixelsAreNeverDrawnAtAmbientLevel) {
  render::GpuProbe probe = render::probeGpu();
  if (!probe.available) GTEST_SKIP() << "no Vulkan device: " << probe.reason;
  std::vector<float> gpu, cpu;
  acne::Measurement m = acne::measureRenderer(GetParam(), render::RenderDevice::Gpu, &gpu);
  std::printf("[ acne ] on %s\n", probe.name.c_str());
  checkNoAcne(m);
  acne::measureRenderer(GetParam(), render::RenderDevice::Cpu, &cpu);
  ASSERT_EQ(gpu.size(), cpu.size());
  std::size_t identical = 0, close = 0;
  for (std::size_t k = 0; k < gpu.size(); ++k) {
    identical += gpu[k] == cpu[k] ? 1 : 0;
    close += std::abs(gpu[k] - cpu[k]) <= 1.0f / 255.0f ? 1 : 0;
  }
  std::printf("[ acne ] gpu against cpu: %zu of %zu channels identical, %zu within 1/255\n",
              identical, gpu.size(), close);
  EXPECT_GE(static_cast<double>(close), 0.999 * static_cast<double>(gpu.size()));
}

std::string layoutName(const testing::TestParamInfo<acne::Layout>& info) {
  std::string name = "scale_";
  for (char ch : info.param.label) {
    if (std::isalnum(static_cast<unsigned char>(ch))) name += ch;
    if (ch == '-') name += "minus";
    if (ch == ',') name += "_";
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Layouts, Acne, testing::ValuesIn(acne::layouts()), layoutName);

}  // namespace
