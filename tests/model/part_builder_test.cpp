// PART and MARKER statements (model/part_builder.cpp) against frames and inertias computed by
// hand (docs/theory.md §2: REULER body 3-1-3, ZP/XP axis points, RM reference markers, body
// frame at the CM marker, IP about IM with ADAMS's positive products of inertia), and the
// located diagnostics of each inconsistency.
//
// Tolerance: 1e-14 absolute on quantities of order 1-10. Angles written with D at multiples of
// 90 degrees give exact sines and cosines (docs/theory.md §2), so the only rounding left is a
// few products and sums of order-one numbers (a few ulp, ~1e-15).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/built_model.hpp"

namespace openmss::model {
namespace {

constexpr double kTol = 1e-14;

using Built = testing::BuiltModel;

Built build(const std::string& text) {
  return testing::buildModelFromText(text, "p.adm");
}

// A marker's pose in ground from the built model.
Eigen::Vector3d groundPosition(const Built& b, long id) {
  const Marker& m = b.marker(id);
  const Part& p = b.model.parts[m.part];
  return p.position + p.orientation * m.position;
}
Eigen::Matrix3d groundOrientation(const Built& b, long id) {
  const Marker& m = b.marker(id);
  return b.model.parts[m.part].orientation * m.orientation;
}

Eigen::Matrix3d rz90() {
  Eigen::Matrix3d r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return r;
}
Eigen::Matrix3d rx90() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return r;
}

const char* kHeader =
    "frames\n"
    "UNITS/SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n";

TEST(PartBuilder, MarkerFramesFromQpReulerAxisPointsAndRm) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=2, CM=20, IP=1,1,1, QG=1,2,3, REULER=90D,0,0\n"
                        "MARKER/20, PART=2\n"
                        "MARKER/21, PART=2, QP=1,0,0, REULER=0,90D,0\n"
                        "MARKER/22, PART=2, QP=0,0,0, ZP=0,1,0, XP=0,0,1\n"
                        "MARKER/23, PART=2, QP=0,1,0, RM=21\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.markers.size(), 5u);
  // The body frame is the CM marker's, which sits at the BCS origin: QG, Rz(90).
  const Part& p = b.part(2);
  EXPECT_TRUE(p.position.isApprox(Eigen::Vector3d(1, 2, 3), kTol));
  EXPECT_LT((p.orientation - rz90()).norm(), kTol);
  // MARKER/21: QP=(1,0,0) in the BCS -> (1,2,3) + Rz(90)(1,0,0) = (1,3,3) in ground;
  // REULER=0,90D,0 = Rz(0) Rx(90) Rz(0) relative to the BCS.
  EXPECT_LT((groundPosition(b, 21) - Eigen::Vector3d(1, 3, 3)).norm(), kTol);
  EXPECT_LT((b.marker(21).orientation - rx90()).norm(), kTol);
  EXPECT_LT((groundOrientation(b, 21) - rz90() * rx90()).norm(), kTol);
  // MARKER/22: z along the BCS y axis (ZP), x along the BCS z axis (XP): columns x=(0,0,1),
  // y = z x x = (1,0,0), z=(0,1,0).
  Eigen::Matrix3d axes22;
  axes22 << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  EXPECT_LT((b.marker(22).orientation - axes22).norm(), kTol);
  // MARKER/23: QP=(0,1,0) in MARKER/21's axes -> (1,0,0) + Rx(90)(0,1,0) = (1,0,1) in the BCS,
  // with MARKER/21's orientation.
  EXPECT_LT((b.marker(23).position - Eigen::Vector3d(1, 0, 1)).norm(), kTol);
  EXPECT_LT((b.marker(23).orientation - rx90()).norm(), kTol);
}

// USEXP (docs/language.md, "MARKER"): x exactly toward XP, ZP only fixing the x-z plane.
// Truth by hand: XP = (1,1,0), ZP = (0,1,0) from the origin. With USEXP x = (1,1,0)/sqrt2,
// z = (0,1,0) minus its x part = (-1,1,0)/sqrt2, y = z x x = (0,0,-1). Without it z = (0,1,0)
// exactly, x = (1,1,0) minus its z part = (1,0,0), y = (0,0,-1).
TEST(PartBuilder, UsexpMakesXpTheExactXAxis) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=2, CM=20, IP=1,1,1\n"
                        "MARKER/20, PART=2\n"
                        "MARKER/24, PART=2, ZP=0,1,0, XP=1,1,0, USEXP\n"
                        "MARKER/25, PART=2, ZP=0,1,0, XP=1,1,0\n"
                        "MARKER/26, PART=2, XP=0,0,2, USEXP\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  const double r = std::sqrt(0.5);
  Eigen::Matrix3d with, without, alongZ;
  with << r, 0, -r, r, 0, r, 0, -1, 0;
  without << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  // XP along the reference z and no ZP: z falls back to the reference y (as x falls back to
  // the reference y without XP when ZP is along x): x = (0,0,1), z = (0,1,0), y = (1,0,0).
  alongZ << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  EXPECT_LT((b.marker(24).orientation - with).norm(), kTol) << b.marker(24).orientation;
  EXPECT_LT((b.marker(25).orientation - without).norm(), kTol) << b.marker(25).orientation;
  EXPECT_LT((b.marker(26).orientation - alongZ).norm(), kTol) << b.marker(26).orientation;
}

TEST(PartBuilder, UsexpWithoutXpWithReulerOrDegenerateIsLocated) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=2, CM=20, IP=1,1,1\n"
                        "MARKER/20, PART=2\n"
                        "MARKER/21, PART=2, ZP=0,1,0, USEXP\n"
                        "MARKER/22, PART=2, REULER=0,0,0, XP=1,0,0, USEXP\n"
                        "MARKER/23, PART=2, ZP=2,0,0, XP=1,0,0, USEXP\n"
                        "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "p.adm:7:30: error: MARKER/21: USEXP makes XP the exact x axis, and no XP is given. "
          "Give XP=x,y,z, or remove USEXP.",
          "p.adm:8:44: error: MARKER/22: USEXP qualifies XP and ZP; REULER sets the frame "
          "alone. Remove USEXP (or give the frame by XP, ZP, USEXP instead).",
          "p.adm:9:1: error: MARKER/23: with USEXP the XP/ZP points do not define a frame (a "
          "point coincides with the origin, or the z point lies on the x axis). Move the points "
          "so that x is along the origin->XP line and ZP is off that line."}));
}

TEST(PartBuilder, BodyFrameIsTheCmMarkerAndMarkersAreRelativeToIt) {
  // The CM marker is off the BCS origin and turned: every marker of the part is then stored
  // relative to it, and its ground pose is unchanged.
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,1\n"
                        "MARKER/20, PART=2, QP=2,0,0, REULER=90D,0,0\n"
                        "MARKER/21, PART=2, QP=2,1,0\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  const Part& p = b.part(2);
  EXPECT_LT((p.position - Eigen::Vector3d(2, 0, 1)).norm(), kTol);
  EXPECT_LT((p.orientation - rz90()).norm(), kTol);
  // (2,1,1) - (2,0,1) = (0,1,0) in ground = (1,0,0) in the CM axes (x_CM = y_ground).
  EXPECT_LT((b.marker(21).position - Eigen::Vector3d(1, 0, 0)).norm(), kTol);
  EXPECT_LT((b.marker(21).orientation - rz90().transpose()).norm(), kTol);
  EXPECT_LT((groundPosition(b, 21) - Eigen::Vector3d(2, 1, 1)).norm(), kTol);
  EXPECT_EQ(b.model.movingParts, std::vector<int>{1});
  EXPECT_EQ(p.body, 0);
  EXPECT_EQ(b.model.groundPart, 0);
}

TEST(PartBuilder, InertiaWithProductsImOffsetAndImAxes) {
  const Built b = build(std::string(kHeader) +
                        // products: Ixy=0.5, Ixz=0.25, Iyz=0.125 (positive integrals)
                        "PART/3, MASS=2, CM=30, IP=4,5,6,0.5,0.25,0.125\n"
                        "MARKER/30, PART=3\n"
                        // IM one unit along z from the CM, same axes
                        "PART/4, MASS=2, CM=40, IM=41, IP=5,6,3\n"
                        "MARKER/40, PART=4\n"
                        "MARKER/41, PART=4, QP=0,0,1\n"
                        // IM at the CM, turned 90 degrees about z
                        "PART/5, MASS=1, CM=50, IM=51, IP=1,2,3\n"
                        "MARKER/50, PART=5\n"
                        "MARKER/51, PART=5, REULER=90D,0,0\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  Eigen::Matrix3d expected3;
  expected3 << 4, -0.5, -0.25, -0.5, 5, -0.125, -0.25, -0.125, 6;
  EXPECT_LT((b.part(3).inertia - expected3).norm(), kTol);
  // Parallel axes from IM to the CM: I_cm = I_im - m (|d|^2 1 - d d^T), d = (0,0,1), m = 2:
  // diag(5,6,3) - diag(2,2,0) = diag(3,4,3).
  EXPECT_LT((b.part(4).inertia - Eigen::Vector3d(3, 4, 3).asDiagonal().toDenseMatrix()).norm(),
            kTol);
  // IM axes turned by Rz(90): x_IM = y_CM, y_IM = -x_CM, so Ixx_CM = Iyy_IM = 2 and
  // Iyy_CM = Ixx_IM = 1.
  EXPECT_LT((b.part(5).inertia - Eigen::Vector3d(2, 1, 3).asDiagonal().toDenseMatrix()).norm(),
            kTol);
  EXPECT_EQ(b.part(3).mass, 2.0);
  EXPECT_EQ(b.model.bodyCount(), 3);
}

TEST(PartBuilder, InitialVelocitiesAndExactCoordinates) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=1, CM=20, IP=1,1,1, VX=1, VZ=-2, WY=3, EXACT=X:PSI\n"
                        "MARKER/20, PART=2\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  const Part& p = b.part(2);
  // Only the components given are set (the others are free in the initial conditions).
  using Components = std::array<std::optional<double>, 3>;
  EXPECT_EQ(p.velocity, (Components{1.0, std::nullopt, -2.0}));
  EXPECT_EQ(p.angularVelocity, (Components{std::nullopt, 3.0, std::nullopt}));
  EXPECT_EQ(p.exact, (std::array<bool, 6>{true, false, false, true, false, false}));
}

// ADAMS makes CM optional: without it the part's BCS (QG, REULER) is the centre-of-mass frame
// and IP is about the BCS origin in BCS axes (or about IM). Without MASS the part is massless.
TEST(PartBuilder, APartWithoutCmHasItsBcsAsTheCentreOfMassFrame) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=2, IP=1,2,3, QG=1,2,3, REULER=90D,0,0\n"
                        "MARKER/20, PART=2, QP=1,0,0\n"
                        "PART/3, QG=0,0,5\n"  // massless, no inertia, no CM
                        "MARKER/30, PART=3\n"
                        "PART/4, MASS=3, IM=40, IP=20,20,1\n"  // no CM, inertia about IM
                        "MARKER/40, PART=4, QP=0,0,2\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  const Part& p = b.part(2);
  EXPECT_LT((p.position - Eigen::Vector3d(1, 2, 3)).norm(), kTol);
  EXPECT_LT((p.orientation - rz90()).norm(), kTol);
  EXPECT_LT((p.inertia - Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix()).norm(), kTol);
  // QP in the BCS: one along the BCS x axis, which is ground y.
  EXPECT_LT((groundPosition(b, 20) - Eigen::Vector3d(1, 3, 3)).norm(), kTol);
  const Part& q = b.part(3);
  EXPECT_EQ(q.mass, 0.0);
  EXPECT_EQ(q.inertia, Eigen::Matrix3d::Zero());
  EXPECT_LT((q.position - Eigen::Vector3d(0, 0, 5)).norm(), kTol);
  // IM two above the CM (the BCS origin): I_cm = I_im - m (d.d 1 - d d^T), d = (0, 0, 2).
  const Part& r = b.part(4);
  const Eigen::Matrix3d expected = Eigen::Vector3d(8, 8, 1).asDiagonal();
  EXPECT_LT((r.inertia - expected).norm(), kTol);
  EXPECT_EQ(b.model.bodyCount(), 3);
}

// Zero principal moments (a point mass, a slender rod) are accepted; a negative moment is
// not (negative kinetic energy).
TEST(PartBuilder, ZeroPrincipalMomentsAreAcceptedAndNegativeOnesAreNot) {
  const Built b = build(std::string(kHeader) +
                        "PART/2, MASS=1, CM=20, IP=0,0,0\n"
                        "MARKER/20, PART=2\n"
                        "PART/3, MASS=1, CM=30, IP=0,1,1\n"  // a rod along x
                        "MARKER/30, PART=3\n"
                        "PART/4, MASS=1, CM=40, IP=-1,1,1\n"
                        "MARKER/40, PART=4\n"
                        "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.messages(),
            (std::vector<std::string>{
                "p.adm:9:24: error: PART/4: the inertia tensor has a negative principal moment "
                "about the CM. Check IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz] (ADAMS products are "
                "+integrals) and, with IM, the parallel-axis transfer to the CM."}));
}

TEST(PartBuilder, EveryInconsistencyIsLocated) {
  const Built b = build(std::string(kHeader) +
                        "MARKER/11, PART=1, QP=1,0,0, ZP=2,0,0, XP=3,0,0\n"  // 5: XP on z
                        "PART/2, MASS=1, CM=20, IP=1,1,1,0\n"                // 6: IP count
                        "MARKER/20, PART=2, RM=10\n"                         // 7: RM elsewhere
                        "PART/3, MASS=-1, IP=1,1,1\n"                        // 8: MASS < 0
                        "MARKER/30, PART=3\n"
                        "PART/4, MASS=1, CM=40, IM=10, IP=1,1,1\n"  // 10: IM on ground
                        "MARKER/40, PART=4\n"
                        "PART/5, MASS=1, CM=50, IP=1,1,1, VM=51\n"  // 12: VM
                        "MARKER/50, PART=5\n"
                        "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "p.adm:5:1: error: MARKER/11: the ZP/XP points do not define a frame (a point "
          "coincides with the origin, or the x point lies on the z axis). Move the points so "
          "that z is along the origin->ZP line and XP is off that line.",
          "p.adm:6:24: error: PART/2: IP needs 3 or 6 numbers. Write "
          "IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz].",
          "p.adm:12:34: error: PART/5: VM is not supported yet. Remove it; initial velocities "
          "refer to the CM marker.",
          "p.adm:7:20: error: MARKER/20: RM=10 must be a marker on the same part positioned "
          "without RM. Give a marker of PART/2.",
          "p.adm:6:17: error: PART/2: CM marker 20 is not a marker of this part. Give a MARKER "
          "with PART=2.",
          "p.adm:8:9: error: PART/3: MASS must not be negative. Give MASS=<value> >= 0 (0 "
          "or no MASS: a massless part held by constraints).",
          "p.adm:10:24: error: PART/4: IM marker 10 is not a marker of this part. Give a "
          "MARKER with PART=4."}));
}

TEST(PartBuilder, AMarkerBeforeAnyPartNeedsPart) {
  const Built b = build("no part yet\nMARKER/10\nPART/1, GROUND\nEND\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.messages(), (std::vector<std::string>{
                              "p.adm:2:1: error: MARKER/10: missing required argument PART. "
                              "Add PART=<part id>."}));
}

}  // namespace
}  // namespace openmss::model
