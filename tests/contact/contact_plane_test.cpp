// CONTACT with a PLANE solid (docs/theory.md §6c, "Plane"): the half-space below the RM
// marker's xy-plane against independent truth:
// - a sphere bouncing on a PLANE, and coming to rest on it, follows the same trajectory as on
//   the top face of a large BOX (1e-10: the same geometry computed in another frame), and rests
//   at the closed-form penetration (m g / k)^(1/e);
// - a cylinder released tilted on its face rights itself on a PLANE as on the BOX (1e-10);
// - a block on an inclined PLANE (the plane's marker tilted, gravity vertical) slides with
//   a = g (sin phi - mu_d cos phi);
// - the exact partials of sphere, box and cylinder against a tilted plane vs central
//   differences;
// - bad input: two planes, a partial rectangle, a TORUS that is no ring: one located message
//   each.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_support.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;

// The floor: the top face z = 0 of a large ground BOX, or a PLANE through the ground origin
// (with or without a rectangle).
const char* kBoxFloor =
    "MARKER/10, PART=1, QP=-50,-50,-1\n"
    "GRAPHICS/1, BOX, CORNER=10, X=100, Y=100, Z=1\n";
const char* kPlaneFloor =
    "MARKER/10, PART=1\n"
    "GRAPHICS/1, PLANE, RM=10\n";
const char* kBoundedPlaneFloor =
    "MARKER/10, PART=1\n"
    "GRAPHICS/1, PLANE, RM=10, XMIN=-50, XMAX=50, YMIN=-50, YMAX=50\n";

const char* kImpact = "IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5";

// A sphere of radius 0.1 (mass 1) at height `z` moving at (vx, 0, vz), on the floor.
std::string ballDeck(const char* floor, double z, double vx, double vz) {
  char part[160];
  std::snprintf(part, sizeof part,
                "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,%.17g, VX=%.17g, VZ=%.17g\n",
                z, vx, vz);
  return std::string("ball on a floor\n") +
         "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n" + "PART/1, GROUND\n" +
         floor + part +
         "MARKER/20, PART=2\n"
         "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, " +
         kImpact + "\nACCGRAV/KGRAV=-9.81\nEND\n";
}

double worstDifference(const std::vector<Sample>& a, const std::vector<Sample>& b, size_t& n) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  n = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k, ++n)
    worst = std::max({worst, (a[k].r - b[k].r).cwiseAbs().maxCoeff(),
                      (a[k].v - b[k].v).cwiseAbs().maxCoeff(),
                      (a[k].w - b[k].w).cwiseAbs().maxCoeff()});
  return worst;
}

TEST(ContactPlane, SphereBouncesAndRestsOnAPlaneAsOnALargeBox) {
  // Bounce: touching at t = 0, 1 m/s down and 0.3 m/s sideways; rest: released 1e-4 above,
  // settled after 1 s (damping ratio about 0.12 at 180 rad/s: the bounce decays as e^(-21 t)).
  struct Case {
    double z, vx, vz, end, dtout;
  };
  for (const Case c : {Case{0.1, 0.3, -1.0, 0.02, 1e-4}, Case{0.1001, 0.0, 0.0, 1.0, 1e-2}}) {
    const std::vector<Sample> box = simulate(
        buildFailingOnErrors(ballDeck(kBoxFloor, c.z, c.vx, c.vz)), c.end, c.dtout, 1e-10, 2e-4);
    for (const char* floor : {kPlaneFloor, kBoundedPlaneFloor}) {
      const std::vector<Sample> plane = simulate(
          buildFailingOnErrors(ballDeck(floor, c.z, c.vx, c.vz)), c.end, c.dtout, 1e-10, 2e-4);
      size_t n = 0;
      const double worst = worstDifference(plane, box, n);
      std::printf("sphere on %s PLANE vs BOX (%s): max difference %.2e over %zu samples\n",
                  floor == kPlaneFloor ? "an unbounded" : "a bounded", c.vz < 0 ? "bounce" : "rest",
                  worst, n);
      EXPECT_EQ(n, static_cast<size_t>(std::lround(c.end / c.dtout)) + 1);
      // The same depth and normal, computed in the plane's frame instead of the box's: the
      // runs differ by rounding only.
      EXPECT_LT(worst, 1e-10);
      if (c.vz == 0.0) {
        const double depth = 0.1 - plane.back().r.z(), truth = std::pow(kG / 1e6, 1.0 / 1.5);
        std::printf("  resting penetration %.12e, (m g / k)^(1/e) = %.12e\n", depth, truth);
        EXPECT_NEAR(depth, truth, 1e-6 * truth);
      }
    }
  }
}

TEST(ContactPlane, CylinderRightsItselfOnAPlaneAsOnALargeBox) {
  // Standing, released tilted 2 degrees about x with its low edge on the floor (the test of
  // contact_frustum_test.cpp): the rim samples against the plane are those against the face.
  const double tilt = 2.0 * std::numbers::pi / 180.0;
  char part[200];
  std::snprintf(part, sizeof part,
                "PART/2, MASS=2, CM=20, IP=0.02833333333333333,0.02833333333333333,0.01, "
                "QG=0,0,%.17g, REULER=0,2D,0\n",
                0.2 * std::cos(tilt) + 0.1 * std::sin(tilt));
  auto deck = [&](const char* floor) {
    return std::string(
               "cylinder\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, "
               "TIME=SECOND\nPART/1, GROUND\n") +
           floor + part +
           "MARKER/20, PART=2\nMARKER/21, PART=2, QP=0,0,-0.2\n"
           "GRAPHICS/2, CYLINDER, CM=21, RADIUS=0.1, LENGTH=0.4\n"
           "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, "
           "EXPONENT=1.5\nACCGRAV/KGRAV=-9.81\nEND\n";
  };
  const std::vector<Sample> box =
      simulate(buildFailingOnErrors(deck(kBoxFloor)), 0.5, 1e-2, 1e-8, 1e-3);
  const std::vector<Sample> plane =
      simulate(buildFailingOnErrors(deck(kPlaneFloor)), 0.5, 1e-2, 1e-8, 1e-3);
  size_t n = 0;
  const double worst = worstDifference(plane, box, n);
  std::printf("cylinder on a PLANE vs BOX: max difference %.2e over %zu samples\n", worst, n);
  EXPECT_EQ(n, 51u);
  EXPECT_LT(worst, 1e-10);
}

// A 0.2 x 0.2 x 0.1 block (mass 1) on a ground PLANE whose marker is turned by phi about
// ground y (REULER 90D, phi, -90D = Rz(90) Rx(phi) Rz(-90) = Ry(phi)), gravity along -z: the
// plane's normal is (sin phi, 0, cos phi) and gravity's part along it points downhill,
// (cos phi, 0, -sin phi).
std::string inclineDeck(double phi) {
  const double deg = phi * 180.0 / std::numbers::pi;
  char text[1200];
  std::snprintf(text, sizeof text,
                "block on an inclined plane\n"
                "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
                "PART/1, GROUND\n"
                "MARKER/10, PART=1, REULER=90D,%.17gD,-90D\n"
                "GRAPHICS/1, PLANE, RM=10\n"
                "PART/2, MASS=1, CM=20, IP=0.00417,0.00417,0.00667, QG=%.17g,0,%.17g, "
                "REULER=90D,%.17gD,-90D\n"
                "MARKER/20, PART=2\n"
                "MARKER/21, PART=2, QP=-0.1,-0.1,-0.05\n"
                "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
                "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=1e3, DMAX=1e-6, "
                "EXPONENT=1, COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, "
                "STICTION_TRANSITION_VELOCITY=1e-3, FRICTION_TRANSITION_VELOCITY=1e-2\n"
                "ACCGRAV/KGRAV=-9.81\nEND\n",
                deg, 0.05 * std::sin(phi), 0.05 * std::cos(phi), deg);
  return text;
}

TEST(ContactPlane, BlockSlidesDownAnInclinedPlaneWithTheDynamicCoefficient) {
  const double phi = 35.0 * std::numbers::pi / 180.0;
  const std::vector<Sample> run =
      simulate(buildFailingOnErrors(inclineDeck(phi)), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const Eigen::Vector3d downhill(std::cos(phi), 0.0, -std::sin(phi));
  const Sample& a = run[50];
  const Sample& b = run[100];
  ASSERT_GT(a.v.dot(downhill), 1.0);
  const double accel = (b.v - a.v).dot(downhill) / (b.t - a.t);
  const double truth = kG * (std::sin(phi) - 0.3 * std::cos(phi));
  std::printf(
      "block on an inclined PLANE: a = %.8f, g (sin phi - mu_d cos phi) = %.8f (rel "
      "%.2e), off-slope speed %.2e\n",
      accel, truth, std::abs(accel / truth - 1), std::abs(b.v.y()));
  EXPECT_NEAR(accel, truth, 1e-4 * truth);
  EXPECT_NEAR(b.v.y(), 0.0, 1e-9);
}

TEST(ContactPlane, PartialsAgainstATiltedPlaneMatchCentralDifferences) {
  // The block pressed into the tilted plane, moving and spinning (four corners in contact).
  std::string deck = inclineDeck(20.0 * std::numbers::pi / 180.0);
  const double phi = 20.0 * std::numbers::pi / 180.0;
  char qg[96];
  std::snprintf(qg, sizeof qg, "QG=%.17g,0,%.17g", 0.0499 * std::sin(phi), 0.0499 * std::cos(phi));
  deck.replace(deck.find("QG="), deck.find(", REULER=90D", deck.find("QG=")) - deck.find("QG="),
               qg);
  Eigen::VectorXd v(6);
  v << 0.3, -0.2, -0.01, 0.2, 0.1, -0.5;
  checkJacobian(deck, v);
  // The sphere pressed into an unbounded plane, with friction.
  std::string ball = ballDeck(kPlaneFloor, 0.0995, 0.0, 0.0);
  ball.replace(ball.find("\nACCGRAV"), 0,
               ", COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, "
               "STICTION_TRANSITION_VELOCITY=1e-3, FRICTION_TRANSITION_VELOCITY=1e-2");
  checkJacobian(ball, v);
}

void expectOneError(const std::string& text, int line, const std::string& what) {
  contact_test::expectOneError(testing::buildModelFromText(text, "p.adm"), line, what);
}

TEST(ContactPlane, BadPlanesAndTheTorusAreLocated) {
  const std::string head =
      "planes\nPART/1, GROUND\nMARKER/10, PART=1\nGRAPHICS/1, PLANE, RM=10\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
      "GRAPHICS/2, PLANE, RM=20\n"
      "GRAPHICS/3, PLANE, RM=20, XMIN=-1, XMAX=1\n"
      "GRAPHICS/4, TORUS, CM=20, MAJOR_RADIUS=0.1, MINOR_RADIUS=0.1\n";
  const std::string law = ", IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-3, EXPONENT=2\nEND\n";
  expectOneError(head + "CONTACT/1, IGEOM=2, JGEOM=1" + law, 10,
                 "two half-spaces (PLANE or OUTLINE)");
  expectOneError(head + "CONTACT/1, IGEOM=3, JGEOM=1" + law, 10,
                 "GRAPHICS/3 (line 8) is a PLANE with 2 of XMIN, XMAX, YMIN, YMAX given");
  expectOneError(head + "CONTACT/1, IGEOM=4, JGEOM=1" + law, 10,
                 "GRAPHICS/4 (line 9) is a TORUS with MAJOR_RADIUS = 0.100000 and MINOR_RADIUS = "
                 "0.100000: contact needs a ring");
}

}  // namespace
}  // namespace openmss::contact_test
