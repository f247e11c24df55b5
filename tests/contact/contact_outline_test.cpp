// CONTACT with an OUTLINE floor (docs/theory.md §6c, "OUTLINE floors"): a closed planar GRAPHICS
// OUTLINE is a half-space bounded sideways by its polygon, its normal by the right-hand rule of
// the winding. Against independent truth:
// - a sphere bouncing and resting on a square OUTLINE floor follows the same trajectory as on
//   the equivalent PLANE (the same plane, the same marker axes: bit-equal);
// - a sphere over the notch of an L-shaped OUTLINE falls through as in free fall (to 1e-6), while
// one
//   over the L bounces;
// - a block on an OUTLINE laid in an inclined plane (its markers placed, not turned) slides with
//   a = g (sin phi - mu_d cos phi), as on the tilted PLANE;
// - the Newton matrix against central differences on a tilted OUTLINE;
// - bad input: an open, a non-planar and a two-part OUTLINE: one located message each.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_support.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;

// The PLANE through the ground origin, and the square OUTLINE -50..50 in the same plane,
// counter-clockwise seen from +z (normal +z), its first marker at a corner with ground axes.
const char* kPlaneFloor =
    "MARKER/10, PART=1, QP=-50,-50,0\n"
    "GRAPHICS/1, PLANE, RM=10\n";
const char* kOutlineFloor =
    "MARKER/10, PART=1, QP=-50,-50,0\nMARKER/11, PART=1, QP=50,-50,0\n"
    "MARKER/12, PART=1, QP=50,50,0\nMARKER/13, PART=1, QP=-50,50,0\n"
    "GRAPHICS/1, OUTLINE=10,11,12,13,10\n";
// An L: the square 0..2 x 0..2 less its quarter 1..2 x 1..2 (a notch), counter-clockwise.
const char* kLFloor =
    "MARKER/10, PART=1\nMARKER/11, PART=1, QP=2,0,0\nMARKER/12, PART=1, QP=2,1,0\n"
    "MARKER/13, PART=1, QP=1,1,0\nMARKER/14, PART=1, QP=1,2,0\nMARKER/15, PART=1, QP=0,2,0\n"
    "GRAPHICS/1, OUTLINE=10,11,12,13,14,15,10\n";

// A sphere of radius 0.1 (mass 1) at (x, y, z) moving at (vx, 0, vz), on the floor.
std::string ballDeck(const char* floor, double x, double y, double z, double vx, double vz) {
  char part[200];
  std::snprintf(part, sizeof part,
                "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=%.17g,%.17g,%.17g, VX=%.17g, "
                "VZ=%.17g\n",
                x, y, z, vx, vz);
  return std::string("ball on a floor\n") +
         "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n" + "PART/1, GROUND\n" +
         floor + part +
         "MARKER/20, PART=2\n"
         "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, "
         "EXPONENT=1.5\nACCGRAV/KGRAV=-9.81\nEND\n";
}

double worstDifference(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    worst = std::max({worst, (a[k].r - b[k].r).cwiseAbs().maxCoeff(),
                      (a[k].v - b[k].v).cwiseAbs().maxCoeff(),
                      (a[k].w - b[k].w).cwiseAbs().maxCoeff()});
  return worst;
}

TEST(ContactOutline, SphereOnAnOutlineFloorRunsAsOnThePlane) {
  // Bounce (touching at t = 0, 1 m/s down, 0.3 m/s sideways) and rest (released 1e-4 above).
  struct Case {
    double z, vx, vz, end, dtout;
  };
  for (const Case c : {Case{0.1, 0.3, -1.0, 0.02, 1e-4}, Case{0.1001, 0.0, 0.0, 1.0, 1e-2}}) {
    const std::vector<Sample> plane =
        simulate(buildFailingOnErrors(ballDeck(kPlaneFloor, 0, 0, c.z, c.vx, c.vz)), c.end, c.dtout,
                 1e-10, 2e-4);
    const std::vector<Sample> outline =
        simulate(buildFailingOnErrors(ballDeck(kOutlineFloor, 0, 0, c.z, c.vx, c.vz)), c.end,
                 c.dtout, 1e-10, 2e-4);
    const double worst = worstDifference(outline, plane);
    std::printf("sphere on an OUTLINE vs PLANE (%s): max difference %.2e over %zu samples\n",
                c.vz < 0 ? "bounce" : "rest", worst, outline.size());
    ASSERT_EQ(outline.size(), static_cast<size_t>(std::lround(c.end / c.dtout)) + 1);
    // The same plane in the same axes: the same operations, so the same bits.
    EXPECT_EQ(worst, 0.0);
    if (c.vz == 0.0) {
      const double depth = 0.1 - outline.back().r.z(), truth = std::pow(kG / 1e6, 1.0 / 1.5);
      EXPECT_NEAR(depth, truth, 1e-6 * truth);
    }
  }
}

TEST(ContactOutline, SphereBeyondThePolygonFallsThrough) {
  // Released 0.05 above the L (at (0.5, 1.5)) and above its notch (at (1.5, 1.5)): the first
  // bounces back up, the second falls freely, z(t) = z0 - g t^2 / 2.
  const double z0 = 0.15, end = 0.3;
  const std::vector<Sample> onL =
      simulate(buildFailingOnErrors(ballDeck(kLFloor, 0.5, 1.5, z0, 0, 0)), end, 1e-2, 1e-8, 1e-3);
  const std::vector<Sample> notch =
      simulate(buildFailingOnErrors(ballDeck(kLFloor, 1.5, 1.5, z0, 0, 0)), end, 1e-2, 1e-8, 1e-3);
  ASSERT_EQ(notch.size(), 31u);
  double freeFall = 0.0, lowest = 1e9;
  for (const Sample& s : notch)
    freeFall = std::max(freeFall, std::abs(s.r.z() - (z0 - 0.5 * kG * s.t * s.t)));
  for (const Sample& s : onL) lowest = std::min(lowest, s.r.z());
  std::printf("sphere over the notch: max |z - free fall| %.2e; over the L: lowest z %.6f\n",
              freeFall, lowest);
  // No force at all over the notch: the free fall to the integrator's accuracy (ERROR 1e-8
  // over 0.3 s; measured 1.4e-8), where a touch of the floor would stop the fall by 0.05.
  EXPECT_LT(freeFall, 1e-6);
  EXPECT_LT(notch.back().r.z(), -0.2);
  // Over the L the sphere (radius 0.1) stops within a few millimetres of the floor.
  EXPECT_GT(lowest, 0.095);
}

// A 0.2 x 0.2 x 0.1 block on a ground OUTLINE (or PLANE) in the plane through the origin with
// normal (sin phi, 0, cos phi): the OUTLINE's markers keep the ground axes and are placed at
// Ry(phi) (+-2, +-2, 0), counter-clockwise about the normal.
std::string inclineDeck(double phi, bool outline) {
  const double deg = phi * 180.0 / std::numbers::pi, c = std::cos(phi), s = std::sin(phi);
  std::string floor;
  if (outline) {
    const double xy[4][2] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
    char line[200];
    for (int k = 0; k < 4; ++k) {
      std::snprintf(line, sizeof line, "MARKER/%d, PART=1, QP=%.17g,%.17g,%.17g\n", 10 + k,
                    c * xy[k][0], xy[k][1], -s * xy[k][0]);
      floor += line;
    }
    floor += "GRAPHICS/1, OUTLINE=10,11,12,13,10\n";
  } else {
    char line[200];
    std::snprintf(line, sizeof line, "MARKER/10, PART=1, REULER=90D,%.17gD,-90D\n", deg);
    floor = std::string(line) + "GRAPHICS/1, PLANE, RM=10\n";
  }
  char text[1200];
  std::snprintf(text, sizeof text,
                "block on an inclined floor\n"
                "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
                "PART/1, GROUND\n%s"
                "PART/2, MASS=1, CM=20, IP=0.00417,0.00417,0.00667, QG=%.17g,0,%.17g, "
                "REULER=90D,%.17gD,-90D\n"
                "MARKER/20, PART=2\n"
                "MARKER/21, PART=2, QP=-0.1,-0.1,-0.05\n"
                "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
                "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=1e3, DMAX=1e-6, "
                "EXPONENT=1, COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, "
                "STICTION_TRANSITION_VELOCITY=1e-3, FRICTION_TRANSITION_VELOCITY=1e-2\n"
                "ACCGRAV/KGRAV=-9.81\nEND\n",
                floor.c_str(), 0.05 * s, 0.05 * c, deg);
  return text;
}

TEST(ContactOutline, BlockSlidesDownAnInclinedOutlineAsOnThePlane) {
  const double phi = 35.0 * std::numbers::pi / 180.0;
  const std::vector<Sample> run =
      simulate(buildFailingOnErrors(inclineDeck(phi, true)), 1.0, 1e-2, 1e-7, 1e-3);
  const std::vector<Sample> plane =
      simulate(buildFailingOnErrors(inclineDeck(phi, false)), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const Eigen::Vector3d downhill(std::cos(phi), 0.0, -std::sin(phi));
  const double accel = (run[100].v - run[50].v).dot(downhill) / (run[100].t - run[50].t);
  const double truth = kG * (std::sin(phi) - 0.3 * std::cos(phi));
  const double worst = worstDifference(run, plane);
  std::printf(
      "block on an inclined OUTLINE: a = %.8f, g (sin phi - mu_d cos phi) = %.8f (rel %.2e); "
      "max difference from the PLANE's run %.2e\n",
      accel, truth, std::abs(accel / truth - 1), worst);
  ASSERT_GT(run[50].v.dot(downhill), 1.0);
  EXPECT_NEAR(accel, truth, 1e-4 * truth);
  // The same plane, its axes computed from the corners instead of the marker's angles: the
  // runs differ by the rounding of the axes (1e-16) grown over 1 s of sliding under the
  // integrator's error control (ERROR 1e-7).
  EXPECT_LT(worst, 1e-6);
}

TEST(ContactOutline, PartialsOnATiltedOutlineMatchCentralDifferences) {
  const double phi = 20.0 * std::numbers::pi / 180.0;
  std::string deck = inclineDeck(phi, true);
  char qg[96];
  std::snprintf(qg, sizeof qg, "QG=%.17g,0,%.17g", 0.0499 * std::sin(phi), 0.0499 * std::cos(phi));
  deck.replace(deck.find("QG="), deck.find(", REULER=90D", deck.find("QG=")) - deck.find("QG="),
               qg);
  Eigen::VectorXd v(6);
  v << 0.3, -0.2, -0.01, 0.2, 0.1, -0.5;
  const ColumnMismatch d = newtonMatrixMismatch(buildFailingOnErrors(deck), v, 1e-7);
  std::printf("tilted OUTLINE Jacobian: max |exact - central difference| %.3e of %.3e\n", d.worst,
              d.scale);
  EXPECT_LT(d.worst, 1e-6 * d.scale);
}

void expectOneError(const std::string& text, int line, const std::string& what) {
  contact_test::expectOneError(testing::buildModelFromText(text, "o.adm"), line, what);
}

TEST(ContactOutline, OpenNonPlanarAndTwoPartOutlinesAreLocated) {
  const std::string head =
      "outlines\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1, QP=1,0,0\n"
      "MARKER/12, PART=1, QP=1,1,0\nMARKER/13, PART=1, QP=0,1,0.01\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
      "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n";
  const std::string law = ", IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-3, EXPONENT=2\nEND\n";
  // Line 10 is the GRAPHICS, line 11 the CONTACT; the message is at its JGEOM value.
  expectOneError(head + "GRAPHICS/1, OUTLINE=10,11,12\nCONTACT/1, IGEOM=2, JGEOM=1" + law, 11,
                 "GRAPHICS/1 (line 10) is an OUTLINE of 3 markers");
  expectOneError(head + "GRAPHICS/1, OUTLINE=10,11,12,10,11\nCONTACT/1, IGEOM=2, JGEOM=1" + law, 11,
                 "that is open");
  expectOneError(head + "GRAPHICS/1, OUTLINE=10,11,12,13,10\nCONTACT/1, IGEOM=2, JGEOM=1" + law, 11,
                 "that is not planar");
  expectOneError(head + "GRAPHICS/1, OUTLINE=10,11,20,10\nCONTACT/1, IGEOM=2, JGEOM=1" + law, 11,
                 "whose markers lie on different parts (PART/1 and PART/2)");
}

}  // namespace
}  // namespace openmss::contact_test
