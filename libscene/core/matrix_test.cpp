#include "scenefile/matrix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scenefile/transform.h"

namespace scene {
namespace {

glm::dmat3 randomRotation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  std::vector<TransformOp> ops = {{TransformKind::RotateX, glm::dvec3(angle(rng), 0, 0), {}},
                                  {TransformKind::RotateY, glm::dvec3(angle(rng), 0, 0), {}},
                                  {TransformKind::RotateZ, glm::dvec3(angle(rng), 0, 0), {}}};
  return linearPart(composeTransform(ops));
}

TEST(SingularValues, OfARotatedDiagonal) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 1000; ++i) {
    glm::dmat3 a = randomRotation(rng) * glm::dmat3(glm::dvec3(3, 0, 0), glm::dvec3(0, 1e-5, 0),
                                                    glm::dvec3(0, 0, 0.25)) *
                   randomRotation(rng);
    glm::dvec3 s = singularValues(a);
    EXPECT_NEAR(s.x, 3.0, 1e-14);
    EXPECT_NEAR(s.y, 0.25, 1e-15);
    EXPECT_NEAR(s.z / 1e-5, 1.0, 1e-9);  // relative accuracy on the smallest
  }
}

TEST(ConditionNumber, MatchesItsCheapBound) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-7, 7);
  for (int i = 0; i < 5000; ++i) {
    glm::dvec3 d(std::pow(10.0, exponent(rng)), std::pow(10.0, exponent(rng)),
                 std::pow(10.0, exponent(rng)));
    glm::dmat3 a = randomRotation(rng) * glm::dmat3(glm::dvec3(d.x, 0, 0), glm::dvec3(0, d.y, 0),
                                                    glm::dvec3(0, 0, d.z));
    double exact = std::max({d.x, d.y, d.z}) / std::min({d.x, d.y, d.z});
    EXPECT_NEAR(conditionNumber(a) / exact, 1.0, 1e-6);
    for (double limit : {1e3, 1e8, 1e12}) {
      if (std::abs(exact / limit - 1.0) < 1e-6) continue;  // too close to call
      EXPECT_EQ(conditionNumberExceeds(a, limit), exact > limit) << exact << " vs " << limit;
    }
  }
}

TEST(ConditionNumber, InfiniteWhenSingular) {
  glm::dmat3 a(glm::dvec3(1, 2, 3), glm::dvec3(2, 4, 6), glm::dvec3(0, 0, 1));
  EXPECT_TRUE(std::isinf(conditionNumber(a)));
  EXPECT_TRUE(conditionNumberExceeds(a, 1e12));
}

}  // namespace
}  // namespace scene
