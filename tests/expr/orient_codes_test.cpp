// ORIENT codes 1-26: each angle set is checked by building the rotation matrix independently
// from chosen angles (products of elementary rotations, body-fixed R_a R_b R_c, space-fixed
// R_c R_b R_a) and reading the angles back with orientValue, the function every ORIENT call
// uses. Angles are chosen inside each sequence's principal range and away from its gimbal
// lock, where the angles are unique; 1e-12 is a few hundred roundings of the matrix products.

#include <gtest/gtest.h>

#include <cmath>

#include "common/rotation.hpp"
#include "mechanics/orientation_measure.hpp"

namespace openmss {
namespace {

Eigen::Matrix3d elementary(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  r(i, i) = c;
  r(i, j) = -s;
  r(j, i) = s;
  r(j, j) = c;
  return r;
}

double orient(const Eigen::Matrix3d& r, int code, int component) {
  double out = 0.0;
  EXPECT_TRUE(mechanics::orientValue(M3<double>::from(r), code, component, &out)) << code;
  return out;
}

// Axis sequences of codes 1-12 (docs/expressions.md, "ORIENT codes").
const int kSequences[12][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0},
                               {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}};

TEST(OrientCodes, BodyAndSpaceFixedSequencesRecoverTheirAngles) {
  const double sets[3][3] = {{0.4, -0.3, 1.1}, {-2.5, 0.9, -0.2}, {1.7, 1.2, 2.9}};
  for (int code = 1; code <= 24; ++code) {
    const int* axes = kSequences[(code - 1) % 12];
    const bool proper = axes[0] == axes[2];
    for (const auto& set : sets) {
      // Middle angle in (0, pi) for proper Euler sequences, in (-pi/2, pi/2) otherwise.
      const double t[3] = {set[0], proper ? std::abs(set[1]) + 0.2 : set[1], set[2]};
      const Eigen::Matrix3d r =
          code <= 12 ? Eigen::Matrix3d(elementary(axes[0], t[0]) * elementary(axes[1], t[1]) *
                                       elementary(axes[2], t[2]))
                     : Eigen::Matrix3d(elementary(axes[2], t[2]) * elementary(axes[1], t[1]) *
                                       elementary(axes[0], t[0]));
      for (int k = 1; k <= 3; ++k) {
        EXPECT_NEAR(orient(r, code, k), t[k - 1], 1e-12) << "code " << code << " comp " << k;
      }
    }
  }
}

TEST(OrientCodes, SpaceFixedDiffersFromBodyFixedForTheSameAngles) {
  // The same matrix read as body-fixed 1-2-3 (code 1) and space-fixed 3-2-1 (code 18) gives
  // the same angles in reverse order: R_x(a) R_y(b) R_z(c) is space-fixed z, y, x by c, b, a.
  const Eigen::Matrix3d r = elementary(0, 0.3) * elementary(1, -0.5) * elementary(2, 1.2);
  EXPECT_NEAR(orient(r, 18, 1), 1.2, 1e-12);
  EXPECT_NEAR(orient(r, 18, 2), -0.5, 1e-12);
  EXPECT_NEAR(orient(r, 18, 3), 0.3, 1e-12);
}

TEST(OrientCodes, Code25IsAxAyAzAndCode26IsYawPitchRoll) {
  // A rotation about x alone: AX is that angle, AY = AZ = 0; likewise for y and z.
  EXPECT_NEAR(orient(elementary(0, 2.0), 25, 1), 2.0, 1e-14);
  // The others are 0 while the turn stays within +-90 degrees (beyond, AY's atan2 of (0, cos)
  // is pi: ADAMS calls AX/AY/AZ meaningful only for small rotations about the other axes).
  EXPECT_NEAR(orient(elementary(0, 0.5), 25, 2), 0.0, 1e-14);
  EXPECT_NEAR(orient(elementary(1, -2.5), 25, 2), -2.5, 1e-14);
  EXPECT_NEAR(orient(elementary(2, 3.0), 25, 3), 3.0, 1e-14);
  EXPECT_NEAR(orient(elementary(2, 3.0), 25, 1), 0.0, 1e-14);
  // YAW, PITCH, ROLL: body 3-2-1 angles with the second negated (docs/expressions.md, "ORIENT
  // codes").
  const Eigen::Matrix3d r = elementary(2, 0.7) * elementary(1, 0.4) * elementary(0, -1.3);
  EXPECT_NEAR(orient(r, 26, 1), 0.7, 1e-12);
  EXPECT_NEAR(orient(r, 26, 2), -0.4, 1e-12);
  EXPECT_NEAR(orient(r, 26, 3), -1.3, 1e-12);
}

TEST(OrientCodes, ComponentMapOfTheSequenceTable) {
  int a = 0, b = 0, c = 0, k = 0;
  ASSERT_TRUE(orientBodySequence(23, 1, &a, &b, &c, &k));  // space-fixed 3-1-3
  EXPECT_EQ(a, 2);
  EXPECT_EQ(b, 0);
  EXPECT_EQ(c, 2);
  EXPECT_EQ(k, 3);
  EXPECT_FALSE(orientBodySequence(25, 1, &a, &b, &c, &k));
  EXPECT_FALSE(orientBodySequence(12, 4, &a, &b, &c, &k));
}

}  // namespace
}  // namespace openmss
