#include "scenefile/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "scenefile/matrix.h"

namespace scene {
namespace {

constexpr double kPi = std::numbers::pi;

TransformOp op(TransformKind kind, double x, double y = 0.0, double z = 0.0) {
  return TransformOp{kind, glm::dvec3(x, y, z), {}};
}

glm::dvec3 apply(const glm::dmat4& m, glm::dvec3 p) {
  return glm::dvec3(m * glm::dvec4(p, 1.0));
}

// Largest difference of the 3x3 blocks, relative to each column's norm.
double columnError(const glm::dmat4& a, const glm::dmat4& b) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double norm = glm::length(glm::dvec3(a[c]));
    worst = std::max(worst, glm::length(glm::dvec3(a[c]) - glm::dvec3(b[c])) / norm);
  }
  return worst;
}

TEST(ComposeTransform, RotationsFollowTheRightHandRule) {
  glm::dmat4 rz = composeTransform(std::vector{op(TransformKind::RotateZ, kPi / 2)});
  glm::dvec3 x = apply(rz, {1, 0, 0});
  EXPECT_NEAR(x.x, 0.0, 1e-16);
  EXPECT_NEAR(x.y, 1.0, 1e-16);  // x turns toward y
  glm::dmat4 rx = composeTransform(std::vector{op(TransformKind::RotateX, kPi / 2)});
  EXPECT_NEAR(apply(rx, {0, 1, 0}).z, 1.0, 1e-16);  // y turns toward z
  glm::dmat4 ry = composeTransform(std::vector{op(TransformKind::RotateY, kPi / 2)});
  EXPECT_NEAR(apply(ry, {0, 0, 1}).x, 1.0, 1e-16);  // z turns toward x
}

TEST(ComposeTransform, AppliesOperationsInFileOrder) {
  // Translate first, then rotate: the translation turns with the rotation.
  glm::dmat4 m = composeTransform(
      std::vector{op(TransformKind::Translate, 1, 0, 0), op(TransformKind::RotateZ, kPi / 2)});
  glm::dvec3 origin = apply(m, {0, 0, 0});
  EXPECT_NEAR(origin.x, 0.0, 1e-16);
  EXPECT_NEAR(origin.y, 1.0, 1e-16);
  // Scale after translate scales the translation too.
  glm::dmat4 s = composeTransform(
      std::vector{op(TransformKind::Translate, 1, 2, 3), op(TransformKind::Scale, 2, 3, 4)});
  EXPECT_EQ(apply(s, {0, 0, 0}), glm::dvec3(2, 6, 12));
  EXPECT_EQ(s, transformMatrix(op(TransformKind::Scale, 2, 3, 4)) *
                   transformMatrix(op(TransformKind::Translate, 1, 2, 3)));
}

TEST(DecomposeTransform, RecoversScaleRotationTranslation) {
  std::vector<TransformOp> ops = {op(TransformKind::Scale, 2, 3, 0.5),
                                  op(TransformKind::RotateX, 0.3), op(TransformKind::RotateY, -1.1),
                                  op(TransformKind::RotateZ, 2.5),
                                  op(TransformKind::Translate, 1, -2, 3)};
  glm::dmat4 m = composeTransform(ops);
  TransformDecomposition d = decomposeTransform(m);
  EXPECT_TRUE(d.exact());
  EXPECT_NEAR(d.scale.x, 2.0, 1e-15);
  EXPECT_NEAR(d.scale.y, 3.0, 1e-15);
  EXPECT_NEAR(d.scale.z, 0.5, 1e-15);
  EXPECT_NEAR(d.rotation.x, 0.3, 1e-15);
  EXPECT_NEAR(d.rotation.y, -1.1, 1e-15);
  EXPECT_NEAR(d.rotation.z, 2.5, 1e-15);
  EXPECT_EQ(d.translation, glm::dvec3(1, -2, 3));
  EXPECT_LT(columnError(m, d.recomposed), 1e-15);
}

TEST(DecomposeTransform, StaysExactAtAndNearGimbalLock) {
  // ROTATE_Y = +-pi/2 couples the x and z angles; naive extraction from
  // asin and atan2 of tiny entries loses digits there.
  for (double b :
       {kPi / 2, -kPi / 2, kPi / 2 - 1e-9, kPi / 2 + 1e-12, -kPi / 2 + 1e-14, 1.57079632679}) {
    for (double a : {0.0, 0.7, -2.9}) {
      for (double c : {0.0, 1.3, -0.4}) {
        glm::dmat4 m = composeTransform(
            std::vector{op(TransformKind::Scale, 0.5, 2, 7), op(TransformKind::RotateX, a),
                        op(TransformKind::RotateY, b), op(TransformKind::RotateZ, c)});
        TransformDecomposition d = decomposeTransform(m);
        EXPECT_LT(columnError(m, d.recomposed), 1e-15) << a << " " << b << " " << c;
        EXPECT_TRUE(d.exact());
      }
    }
  }
}

TEST(DecomposeTransform, NaiveEulerAnglesWouldNotBeExact) {
  // The contrast that motivates the method: angles from asin(-r20) and
  // atan2 of the tiny first column at b = pi/2 - 1e-9.
  glm::dmat4 m = composeTransform(std::vector{op(TransformKind::RotateX, 0.7),
                                              op(TransformKind::RotateY, kPi / 2 - 1e-9),
                                              op(TransformKind::RotateZ, 1.3)});
  double b = std::asin(-m[0][2]);
  double a = std::atan2(m[1][2], m[2][2]);
  double c = std::atan2(m[0][1], m[0][0]);
  glm::dmat4 naive = composeTransform(std::vector{
      op(TransformKind::RotateX, a), op(TransformKind::RotateY, b), op(TransformKind::RotateZ, c)});
  EXPECT_GT(columnError(m, naive), 1e-12);
  EXPECT_LT(columnError(m, decomposeTransform(m).recomposed), 1e-15);
}

TEST(DecomposeTransform, MirrorsBecomeNegativeScales) {
  glm::dmat4 m = composeTransform(
      std::vector{op(TransformKind::Scale, 1, -2, 3), op(TransformKind::RotateZ, 0.4)});
  TransformDecomposition d = decomposeTransform(m);
  EXPECT_TRUE(d.exact());
  EXPECT_LT(d.scale.x * d.scale.y * d.scale.z, 0.0);
  EXPECT_LT(columnError(m, d.recomposed), 1e-15);
  // One negative factor comes back as written.
  TransformDecomposition once =
      decomposeTransform(transformMatrix(op(TransformKind::Scale, 1, 1, -4)));
  EXPECT_EQ(once.scale, glm::dvec3(1, 1, -4));
  EXPECT_EQ(once.rotation, glm::dvec3(0.0));
  // Two negative factors are no mirror but a half turn, and come back so.
  TransformDecomposition twice =
      decomposeTransform(transformMatrix(op(TransformKind::Scale, 1, -1, -1)));
  EXPECT_EQ(twice.scale, glm::dvec3(1, 1, 1));
  EXPECT_NEAR(std::abs(twice.rotation.x), kPi, 1e-15);
  EXPECT_TRUE(twice.exact());
}

TEST(DecomposeTransform, DetectsShear) {
  glm::dmat4 m(1.0);
  m[1][0] = 0.3;  // x += 0.3 y
  TransformDecomposition d = decomposeTransform(m);
  EXPECT_FALSE(d.exact());
  EXPECT_GT(d.relativeError, 0.1);
  // The approximation is a proper rotation and scale.
  glm::dmat3 rs = linearPart(d.recomposed);
  EXPECT_NEAR(glm::dot(rs[0], rs[1]), 0.0, 1e-15);
  // A shear at rounding level is no shear.
  glm::dmat4 tiny(1.0);
  tiny[1][0] = 1e-17;
  EXPECT_TRUE(decomposeTransform(tiny).exact());
}

TEST(DecomposeTransform, SeededRandomTransformsAtManyScales) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> angle(-2 * kPi, 2 * kPi);
  std::uniform_real_distribution<double> exponent(-4, 4);
  std::uniform_real_distribution<double> offset(-1e8, 1e8);
  for (int i = 0; i < 20000; ++i) {
    auto scale = [&] {
      double s = std::pow(10.0, exponent(rng));
      return rng() % 2 ? s : -s;
    };
    glm::dmat4 m = composeTransform(std::vector{
        op(TransformKind::Scale, scale(), scale(), scale()), op(TransformKind::RotateX, angle(rng)),
        op(TransformKind::RotateY, i % 4 == 0 ? kPi / 2 : angle(rng)),
        op(TransformKind::RotateZ, angle(rng)),
        op(TransformKind::Translate, offset(rng), offset(rng), offset(rng))});
    TransformDecomposition d = decomposeTransform(m);
    ASSERT_LT(columnError(m, d.recomposed), 1e-14) << i;
    ASSERT_EQ(glm::dvec3(d.recomposed[3]), glm::dvec3(m[3])) << i;
  }
}

TEST(CameraFromLookAt, BuildsRightUpBackEye) {
  glm::dmat4 m = cameraFromLookAt({0, 0, 5}, {0, 0, 0});
  EXPECT_EQ(glm::dvec3(m[0]), glm::dvec3(1, 0, 0));
  EXPECT_EQ(glm::dvec3(m[1]), glm::dvec3(0, 1, 0));
  EXPECT_EQ(glm::dvec3(m[2]), glm::dvec3(0, 0, 1));
  EXPECT_EQ(glm::dvec3(m[3]), glm::dvec3(0, 0, 5));
  glm::dmat4 up = cameraFromLookAt({0, 0, 0}, {0, 3, 0});  // straight up: top is +Z
  EXPECT_EQ(glm::dvec3(up[1]), glm::dvec3(0, 0, 1));
}

TEST(LookAtFromCamera, MeasuresRoll) {
  glm::dmat4 level = cameraFromLookAt({1, 2, 3}, {4, -1, 0});
  LookAtCamera back = lookAtFromCamera(level);
  EXPECT_LT(std::abs(back.roll), kRollTolerance);
  EXPECT_EQ(back.location, glm::dvec3(1, 2, 3));
  glm::dmat4 rebuilt = cameraFromLookAt(back.location, back.lookAt);
  EXPECT_LT(columnError(level, rebuilt), 1e-15);

  // Turn the camera by 10 degrees about its own +Z, which points backwards:
  // that is a roll of -10 degrees about the forward axis.
  double roll = 10.0 * kPi / 180.0;
  glm::dmat4 rolled = level * transformMatrix(op(TransformKind::RotateZ, roll));
  EXPECT_NEAR(lookAtFromCamera(rolled).roll, -roll, 1e-14);
}

// An eye near the largest double: the distance used to be
// 2^ceil(log2(1.8e308)) = 2^1024, an infinity.
TEST(LookAtFromCamera, AnEyeNearTheLargestDoubleGetsAFiniteLookAt) {
  constexpr double kLargest = std::numeric_limits<double>::max();
  for (glm::dvec3 eye : {glm::dvec3(kLargest), glm::dvec3(-kLargest, kLargest, 0.0),
                         glm::dvec3(kLargest / 1.01, 0.0, 0.0)}) {
    glm::dmat4 camera = cameraFromLookAt(eye, glm::dvec3(0.0, 1.0, 0.0));
    LookAtCamera back = lookAtFromCamera(camera);
    ASSERT_TRUE(back.expressible);
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(back.lookAt[i]));
    glm::dmat4 rebuilt = cameraFromLookAt(back.location, back.lookAt);
    EXPECT_LE(scaledLength(glm::dvec3(rebuilt[2] - camera[2])), kLookAtTolerance);
    EXPECT_LT(std::abs(back.roll), kRollTolerance);
  }
  // Forward +x from x = the largest double: every point ahead overflows.
  glm::dmat4 out(1.0);
  out[0] = glm::dvec4(0, 0, 1, 0);
  out[2] = glm::dvec4(-1, 0, 0, 0);
  out[3] = glm::dvec4(kLargest, 0, 0, 1);
  EXPECT_FALSE(lookAtFromCamera(out).expressible);
}

TEST(LookAtFromCamera, AxesOfAnyLengthGiveTheSameLookAt) {
  glm::dmat4 unit = cameraFromLookAt({1, 2, 3}, {4, -1, 0});
  LookAtCamera expected = lookAtFromCamera(unit);
  for (int exponent : {-1000, -500, 500, 1000}) {
    glm::dmat4 scaled = unit;
    for (int c = 0; c < 3; ++c) scaled[c] *= std::ldexp(1.0, exponent);
    LookAtCamera back = lookAtFromCamera(scaled);
    ASSERT_TRUE(back.expressible) << exponent;
    EXPECT_LE(scaledLength(back.lookAt - expected.lookAt), 1e-14) << exponent;
    EXPECT_LT(std::abs(back.roll), kRollTolerance) << exponent;
  }
}

TEST(UnitDirection, ScalesVectorsThePlainFormulaLoses) {
  EXPECT_EQ(unitDirection(glm::dvec3(0, 3, 4)), glm::normalize(glm::dvec3(0, 3, 4)));
  for (double s : {4.9e-324, 1e-300, 1e200, 1.7976931348623157e308}) {
    glm::dvec3 d = unitDirection(glm::dvec3(s, s, 0));
    EXPECT_NEAR(d.x, std::sqrt(0.5), 1e-15) << s;
    EXPECT_NEAR(d.y, std::sqrt(0.5), 1e-15) << s;
    EXPECT_NEAR(scaledLength(glm::dvec3(0, s, 0)), s, s * 1e-15) << s;
  }
  EXPECT_EQ(unitDirection(glm::dvec3(0.0)), glm::dvec3(0.0));
  // Far apart or subnormally close, LOOK_AT gives a camera all the same.
  glm::dmat4 far = cameraFromLookAt({-1e300, 0, 0}, {1e300, 0, 2e300});
  glm::dmat4 near = cameraFromLookAt({0, 0, 0}, {1e-320, 0, 1e-320});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(scaledLength(glm::dvec3(far[c])), 1.0, 1e-15);
    EXPECT_LT(scaledLength(glm::dvec3(far[c] - near[c])), 1e-15);
  }
}

}  // namespace
}  // namespace scene
