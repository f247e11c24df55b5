// Orientation conventions against independent constructions: 3-1-3 Euler angles, the ORIENT
// body-fixed sequences, axis-point frames and Euler parameters.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "common/rotation.hpp"

namespace openmss {
namespace {

Eigen::Matrix3d axisRotation(int axis, double t) {
  return Eigen::AngleAxisd(t, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

TEST(Rotation, Euler313IsZThenNewXThenNewZ) {
  const double psi = 0.3, theta = 1.1, phi = -0.7;
  const Eigen::Matrix3d expected = axisRotation(2, psi) * axisRotation(0, theta) *
                                   axisRotation(2, phi);
  EXPECT_TRUE(matrixFromEuler313(psi, theta, phi).isApprox(expected, 1e-15));
  const Eigen::Vector3d back = euler313FromMatrix(expected);
  EXPECT_NEAR(back(0), psi, 1e-14);
  EXPECT_NEAR(back(1), theta, 1e-14);
  EXPECT_NEAR(back(2), phi, 1e-14);
}

TEST(Rotation, QuarterTurnsAreExact) {
  // 90D, 180D: exact zeros and ones, not 6e-17 (see docs/theory.md section 2).
  const double d = std::numbers::pi / 180.0;
  const Eigen::Matrix3d a = matrixFromEuler313(180 * d, 90 * d, 180 * d);
  Eigen::Matrix3d expected;
  expected << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  EXPECT_EQ(a, expected);
}

TEST(Rotation, OrientSequencesRoundTrip) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int code = 1; code <= 10; ++code) {
    int a, b, c;
    ASSERT_TRUE(orientSequence(code, &a, &b, &c));
    for (int trial = 0; trial < 20; ++trial) {
      double t1 = u(rng), t2 = u(rng), t3 = u(rng);
      // Keep the middle angle inside the principal range of its sequence.
      if (a == c) t2 = std::abs(t2) < 0.05 ? 0.5 : std::abs(t2);
      else t2 = std::clamp(t2 / 2.0, -1.5, 1.5);
      const Eigen::Matrix3d r = axisRotation(a, t1) * axisRotation(b, t2) * axisRotation(c, t3);
      const Eigen::Vector3d back = bodyFixedAngles(r, a, b, c);
      const Eigen::Matrix3d again =
          axisRotation(a, back(0)) * axisRotation(b, back(1)) * axisRotation(c, back(2));
      EXPECT_TRUE(again.isApprox(r, 1e-12)) << "code " << code;
      EXPECT_NEAR(back(1), t2, 1e-12) << "code " << code;
    }
  }
  int a, b, c;
  EXPECT_FALSE(orientSequence(11, &a, &b, &c));
}

TEST(Rotation, OrientSequencesAtTheirSingularMiddleAngle) {
  for (int code = 1; code <= 10; ++code) {
    int a, b, c;
    orientSequence(code, &a, &b, &c);
    const double t2 = a == c ? 0.0 : std::numbers::pi / 2;
    const Eigen::Matrix3d r = axisRotation(a, 0.4) * axisRotation(b, t2) * axisRotation(c, 0.0);
    const Eigen::Vector3d back = bodyFixedAngles(r, a, b, c);
    const Eigen::Matrix3d again =
        axisRotation(a, back(0)) * axisRotation(b, back(1)) * axisRotation(c, back(2));
    EXPECT_TRUE(again.isApprox(r, 1e-12)) << "code " << code;
  }
}

TEST(Rotation, AxisPointFrame) {
  Eigen::Matrix3d a;
  // Marker 15 of the ADAMS/Solver overview's piston example: ZP = (10,1,0), XP = (10,0,1) about QP = (10,0,0).
  ASSERT_TRUE(matrixFromAxisPoints({10, 0, 0}, {10, 1, 0}, {10, 0, 1}, true, true, &a));
  EXPECT_TRUE(a.col(2).isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(a.col(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(a.col(1).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_FALSE(matrixFromAxisPoints({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, true, true, &a));
}

TEST(Rotation, EulerParametersHaveNonNegativeScalarPart) {
  const Eigen::Matrix3d r = axisRotation(0, -std::numbers::pi / 2);
  const Eigen::Vector4d q = quaternionFromMatrix(r);
  EXPECT_NEAR(q(0), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q(1), -std::sqrt(0.5), 1e-15);
  EXPECT_GE(quaternionFromMatrix(axisRotation(1, 3.0))(0), 0.0);
}

}  // namespace
}  // namespace openmss
