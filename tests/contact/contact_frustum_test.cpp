// CONTACT with CYLINDER and FRUSTUM solids against independent truth (docs/theory.md §6c,
// "Frustum pairs"):
// - a cylinder lying on a box floor settles where each rim carries half the weight:
//   k d^e = m g / 2 (the two rims are the two contact points of the line contact);
// - a cylinder standing on its flat face, released tilted by 2 degrees, rights itself and
//   settles at k d^e = m g (the bottom rim's samples share one force);
// - the rim samples of a tilted face at a given placement against their depths computed here
//   from the pose (force and moment);
// - a sphere hitting a cylinder's side: the penetration history against the 1-D IMPACT ODE
//   integrated here by RK4;
// - a cylinder rolls down an incline without slip: a = (2/3) g sin(phi);
// - the exact partials of every frustum pair against central differences of the residual;
// - the builder reads the sizes and refuses a steep frustum pair, a partial RANGLE, no volume.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_support.hpp"
#include "mechanics/contact/contact_loads.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;

const char* kFloor =
    "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, QP=-50,-50,-1\n"
    "GRAPHICS/1, BOX, CORNER=10, X=100, Y=100, Z=1\n";

// Cylinder of radius 0.1, length 0.4, mass 2 (CM marker 20 at its centre): lying with its
// axis along ground x (marker 21 at one end disc, z along x) or standing (z up), touching the
// floor z = 0. `orientation` is the part's REULER.
std::string cylinderDeck(const std::string& qg, const std::string& marker21, const std::string& law,
                         const std::string& extra) {
  return std::string("cylinder on a floor\n") + kFloor +
         "PART/2, MASS=2, CM=20, IP=" + "0.02833333333333333,0.02833333333333333,0.01, QG=" + qg +
         "\n" +
         "MARKER/20, PART=2\n"
         "MARKER/21, PART=2, " +
         marker21 +
         "\n"
         "GRAPHICS/2, CYLINDER, CM=21, RADIUS=0.1, LENGTH=0.4\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, " +
         law + extra + "\nACCGRAV/KGRAV=-9.81\nEND\n";
}

TEST(ContactFrustum, CylinderLyingOnAFloorSettlesWhereEachRimCarriesHalfTheWeight) {
  // The part's z axis is its own axis (IP: Izz = m r^2 / 2); REULER 90D,90D,0D turns it along
  // ground x; marker 21 sits at the end disc z = -0.2 of the part.
  const model::Model m =
      build(cylinderDeck("0,0,0.1, REULER=90D,90D,0D", "QP=0,0,-0.2",
                         "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", ""));
  const std::vector<Sample> run = simulate(m, 1.0, 1e-2, 1e-8, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const double d = std::pow(2.0 * kG / 2.0 / 1e5, 1.0 / 1.5);  // k d^e = m g / 2
  const Sample& last = run.back();
  std::printf(
      "lying cylinder: depth %.9e, truth (mg/2k)^(1/e) = %.9e (rel %.2e), |v| %.2e, "
      "|w| %.2e\n",
      0.1 - last.r.z(), d, std::abs((0.1 - last.r.z()) / d - 1), last.v.norm(), last.w.norm());
  // Settled: the damped rocking (about 25 1/s of decay) has died out to well below 1e-6.
  EXPECT_NEAR(0.1 - last.r.z(), d, 1e-6 * d);
  EXPECT_LT(last.w.norm(), 1e-6);
  EXPECT_LT(std::abs(last.r.x()) + std::abs(last.r.y()), 1e-9);
}

// With one point per rim (the rim's centroid) this cylinder still rocked at t = 2 s
// (|w| = 0.37 rad/s); the rim samples damp the rocking (theory §6c, "rim samples").
TEST(ContactFrustum, CylinderOnItsFlatFaceRightsItselfAndSettlesUnderTheWholeWeight) {
  // Standing (axis along z), released tilted by 2 degrees about x with its low bottom edge
  // touching the floor: the rim samples (deeper ones carry more) right it; at rest the 12
  // samples share one force: k d^e = m g.
  const double tilt = 2.0 * std::numbers::pi / 180.0;
  const double zc = 0.2 * std::cos(tilt) + 0.1 * std::sin(tilt);  // low edge at z = 0
  char qg[96];
  std::snprintf(qg, sizeof qg, "0,0,%.17g, REULER=0,2D,0", zc);
  const model::Model m = build(cylinderDeck(
      qg, "QP=0,0,-0.2", "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", ""));
  const std::vector<Sample> run = simulate(m, 2.0, 1e-2, 1e-8, 1e-3);
  ASSERT_EQ(run.size(), 201u);
  const double d = std::pow(2.0 * kG / 1e5, 1.0 / 1.5);  // k d^e = m g
  const Sample& last = run.back();
  std::printf("standing cylinder: depth %.9e, truth (mg/k)^(1/e) = %.9e (rel %.2e), |w| %.2e\n",
              0.2 - last.r.z(), d, std::abs((0.2 - last.r.z()) / d - 1), last.w.norm());
  EXPECT_NEAR(0.2 - last.r.z(), d, 1e-6 * d);
  EXPECT_LT(last.w.norm(), 1e-6);
}

TEST(ContactFrustum, RimSamplesOfATiltedFaceShareOneForceByDepth) {
  // Standing cylinder tilted by 2 degrees about x (REULER 0,2D,0), its bottom centre c at
  // z = -0.001. A rim point at body angle psi is at height zc(psi) = -0.001 + R sin(psi) sin(2
  // deg): its depth is 0.001 - R sin(2 deg) sin(psi). The samples start at the deepest point
  // (psi = -90 deg) every 30 degrees; those inside (7 here) carry k d^e d / sum d. The moment
  // about the I marker (c) is sum R cos(2 deg) sin(psi) F (the forces are vertical).
  const double tilt = 2.0 * std::numbers::pi / 180.0, radius = 0.1;
  char qg[96];
  std::snprintf(qg, sizeof qg, "0,0,%.17g, REULER=0,2D,0", 0.2 * std::cos(tilt) - 0.001);
  const model::Model m = build(cylinderDeck(
      qg, "QP=0,0,-0.2", "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", ""));
  mechanics::MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState();
  const auto loads =
      mechanics::contact::contactLoads<double>(m, s.layout(), m.contacts.at(0), y.data(), false);
  double depths[12], sum = 0.0;
  int inside = 0;
  for (int k = 0; k < 12; ++k) {
    const double psi = (-90.0 + 30.0 * k) * std::numbers::pi / 180.0;
    depths[k] = 0.001 - radius * std::sin(tilt) * std::sin(psi);
    if (depths[k] > 0.0) sum += depths[k], ++inside;
  }
  double fz = 0.0, mx = 0.0;
  for (int k = 0; k < 12; ++k) {
    if (depths[k] <= 0.0) continue;
    const double psi = (-90.0 + 30.0 * k) * std::numbers::pi / 180.0;
    const double f = 1e5 * std::pow(depths[k], 1.5) * depths[k] / sum;
    fz += f;
    mx += radius * std::cos(tilt) * std::sin(psi) * f;
  }
  std::printf(
      "tilted face: %d samples (truth %d), Fz %.15e (truth %.15e), Mx %.15e (truth %.15e)\n",
      loads.points, inside, loads.force.z, fz, loads.torqueAtI.x, mx);
  ASSERT_EQ(inside, 7);
  EXPECT_EQ(loads.points, inside);
  // Rounding only: depths ~1e-3 from coordinates ~0.2 (1e-13 relative each).
  EXPECT_NEAR(loads.force.z, fz, 1e-11 * fz);
  EXPECT_NEAR(loads.torqueAtI.x, mx, 1e-11 * fz * radius);
  EXPECT_LT(std::abs(loads.force.x) + std::abs(loads.force.y), 1e-12 * fz);
}

TEST(ContactFrustum, SphereHittingACylinderSideFollowsTheImpactOde) {
  // Ground cylinder of radius 0.2 about z (z from -0.25 to 0.25); a sphere of radius 0.1
  // (mass 1) touching its side at t = 0 at azimuth 30 degrees and height 0.05, moving towards
  // the axis at 1 m/s, no gravity: d = 0.3 - rho obeys d'' = -F(d, d').
  const ImpactOde ode{1e6, 1.5, 100.0, 1e-3, 0.0};
  const double c30 = std::cos(std::numbers::pi / 6), s30 = std::sin(std::numbers::pi / 6);
  char sphere[200];
  std::snprintf(sphere, sizeof sphere,
                "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=%.17g,%.17g,0.05, VX=%.17g, "
                "VY=%.17g\n",
                0.3 * c30, 0.3 * s30, -c30, -s30);
  const model::Model m = build(std::string("sphere on a cylinder side\n") +
                               "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
                               "PART/1, GROUND\n"
                               "MARKER/10, PART=1, QP=0,0,-0.25\n"
                               "GRAPHICS/1, CYLINDER, CM=10, RADIUS=0.2, LENGTH=0.5\n" +
                               sphere +
                               "MARKER/20, PART=2\n"
                               "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, "
                               "ZSCALE=0.2\n"
                               "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, "
                               "DMAX=1e-3, EXPONENT=1.5\n"
                               "END\n");
  const double dt = 1e-5;
  const std::vector<Sample> run = simulate(m, 0.02, dt, 1e-10, 2e-6);
  ASSERT_EQ(run.size(), 2001u);
  std::vector<double> t, depth, truth;
  double x[2] = {0.0, 1.0};
  for (size_t k = 0; k < run.size(); ++k) {
    if (k > 0)
      for (int q = 0; q < 1000; ++q) ode.rk4(x, dt / 1000);
    t.push_back(run[k].t);
    depth.push_back(0.3 - std::hypot(run[k].r.x(), run[k].r.y()));
    truth.push_back(x[0]);
  }
  const double maxTruth = peak(truth), maxRun = peak(depth);
  const double durTruth = returnTime(t, truth), durRun = returnTime(t, depth);
  double worst = 0.0, height = 0.0;
  for (size_t k = 0; k < run.size(); ++k) {
    worst = std::max(worst, std::abs(depth[k] - truth[k]));
    height = std::max(height, std::abs(run[k].r.z() - 0.05));
  }
  std::printf(
      "sphere on cylinder side: max penetration %.9e (truth %.9e, rel %.2e), duration "
      "%.9e (truth %.9e, rel %.2e), worst |d - truth| %.2e over %zu samples\n",
      maxRun, maxTruth, std::abs(maxRun / maxTruth - 1), durRun, durTruth,
      std::abs(durRun / durTruth - 1), worst, run.size());
  ASSERT_GT(durTruth, 0.0);
  // The same bar as the sphere on a floor (contact_normal_law_test): 1e-6 relative.
  EXPECT_NEAR(maxRun, maxTruth, 1e-6 * maxTruth);
  EXPECT_NEAR(durRun, durTruth, 1e-6 * durTruth);
  EXPECT_LT(worst, 1e-6 * maxTruth);
  EXPECT_LT(height, 1e-12);  // the side normal is horizontal
}

TEST(ContactFrustum, CylinderRollsDownAnInclineAtTwoThirdsGSinPhi) {
  // The incline is the floor under gravity tilted by phi about y (as contact_friction_test);
  // the cylinder lies along y so it rolls along x. Rigid truth a = (2/3) g sin(phi); the
  // force acts at r - d/2 from the axis (d = 1.8e-6 here), a relative shift ~ d/r (theory §6c).
  const double phi = 20.0 * std::numbers::pi / 180.0;
  char gravity[128];
  std::snprintf(gravity, sizeof gravity, "ACCGRAV/IGRAV=%.17g, KGRAV=%.17g\n", kG * std::sin(phi),
                -kG * std::cos(phi));
  const std::string deck = std::string("rolling cylinder\n") + kFloor +
                           "PART/2, MASS=2, CM=20, IP=0.02833333333333333,0.02833333333333333,"
                           "0.01, QG=0,0,0.1, REULER=0,90D,0\n"
                           "MARKER/20, PART=2\n"
                           "MARKER/21, PART=2, QP=0,0,-0.2\n"
                           "GRAPHICS/2, CYLINDER, CM=21, RADIUS=0.1, LENGTH=0.4\n"
                           "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e9, DAMPING=3e3, "
                           "DMAX=1e-6, EXPONENT=1.5, COULOMB_FRICTION=ON, MU_STATIC=0.5, "
                           "MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=1e-3, "
                           "FRICTION_TRANSITION_VELOCITY=1e-2\n" +
                           gravity + "END\n";
  const std::vector<Sample> run = simulate(build(deck), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const double rolling = 2.0 / 3.0 * kG * std::sin(phi);
  const double accel = (run[100].v.x() - run[50].v.x()) / (run[100].t - run[50].t);
  double slip = 0.0, drift = 0.0;
  int compared = 0;
  for (const Sample& s : run) {
    if (s.t < 0.1) continue;
    // The lowest line's velocity along x: v_x - r w_y (the axis is along y).
    slip = std::max(slip, std::abs(s.v.x() - 0.1 * s.w.y()));
    drift = std::max(drift, std::abs(s.r.y()));
    ++compared;
  }
  std::printf(
      "rolling cylinder: a = %.8f, (2/3) g sin phi = %.8f (rel %.2e), max slip %.3e, "
      "max |y| %.2e over %d samples\n",
      accel, rolling, std::abs(accel / rolling - 1), slip, drift, compared);
  EXPECT_NEAR(accel, rolling, 1e-4 * rolling);
  EXPECT_LT(slip, 1e-3);  // rolls: the contact points stay on the stiction branch (vs)
  EXPECT_LT(drift, 1e-9);
  EXPECT_EQ(compared, 91);
}

const char* kFrictionLaw =
    "IMPACT, STIFFNESS=1e5, DAMPING=50, DMAX=1e-3, EXPONENT=1.5, COULOMB_FRICTION=ON, "
    "MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=0.1, "
    "FRICTION_TRANSITION_VELOCITY=1";

TEST(ContactFrustum, PartialsOfEveryFrustumPairAreExact) {
  Eigen::VectorXd v(6);
  v << 0.7, 0.2, -0.1, 0.3, 0.2, 1.0;
  // Lying, tilted 3 degrees about y: one rim partly in the floor (the acos branch).
  checkJacobian(cylinderDeck("0,0,0.099, REULER=90D,87D,0D", "QP=0,0,-0.2", kFrictionLaw, ""), v);
  // Standing, tilted 0.5 degrees: the whole bottom rim in the floor (all 12 samples inside:
  // the centre's depth 9.9e-4 exceeds rho = R sin 0.5 deg = 8.7e-4). Nearer to upright the
  // samples turn with u = -perp/|perp|, whose curvature 1/|perp| makes central differences with
  // h = 1e-7 too coarse for the 1e-6 bar (measured 1.4e-6 at 0.05 degrees).
  checkJacobian(cylinderDeck("0,0,0.199, REULER=0,0.5D,0", "QP=0,0,-0.2", kFrictionLaw, ""), v);
  // A sphere into a frustum's slanted side (frustum on ground, sphere I) and a box corner into
  // a cylinder's side (the box is I, the cylinder J).
  const std::string sphereOnFrustum =
      "sphere on a frustum\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "GRAPHICS/1, FRUSTUM, CM=10, BOTTOM=0.3, TOP=0.1, LENGTH=0.4\n"
      "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0.29,0.05,0.2\n"
      "MARKER/20, PART=2\n"
      "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
      "CONTACT/1, IGEOM=2, JGEOM=1, " +
      std::string(kFrictionLaw) + "\nEND\n";
  checkJacobian(sphereOnFrustum, v);
  const std::string boxOnCylinder =
      "box corner in a cylinder\nPART/1, GROUND\nMARKER/10, PART=1, REULER=0,90D,0\n"
      "GRAPHICS/1, CYLINDER, CM=10, RADIUS=0.2, LENGTH=1\n"
      "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.006, QG=0.5,0.01,0.195, REULER=10D,20D,5D\n"
      "MARKER/20, PART=2\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
      "CONTACT/1, IGEOM=2, JGEOM=1, " +
      std::string(kFrictionLaw) + "\nEND\n";
  checkJacobian(boxOnCylinder, v);
}

// Exactly one error containing `text`, located at `line`.
void expectOneError(const std::string& deck, int line, const std::string& text) {
  contact_test::expectOneError(testing::buildModelFromText(deck, "contact.adm"), line, text,
                               nullptr);
}

TEST(ContactFrustum, BuilderReadsSizesAndRefusesWhatItCannotSimulate) {
  const std::string head =
      "frustums\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "GRAPHICS/1, FRUSTUM, CM=10, BOTTOM=0.3, TOP=0.1, LENGTH=-0.4\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
      "GRAPHICS/2, CYLINDER, CM=20, RADIUS=0.2, LENGTH=0.5, SIDES=20\n"
      "GRAPHICS/3, CYLINDER, CM=20, RADIUS=0.2, LENGTH=0.5, RANGLE=90D\n"
      "GRAPHICS/4, CYLINDER, CM=20, RADIUS=0, LENGTH=0.5\n"
      "GRAPHICS/5, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n";
  const std::string law = ", IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-3, EXPONENT=2\nEND\n";
  const testing::BuiltModel b =
      testing::buildModelFromText(head + "CONTACT/1, IGEOM=5, JGEOM=1" + law, "c.adm");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.contacts.size(), 1u);
  const model::ContactSolid& f = b.model.contacts[0].jSolids.at(0);
  EXPECT_EQ(f.shape, model::ContactSolid::Shape::Frustum);
  EXPECT_EQ(f.size, Eigen::Vector3d(0.3, 0.1, -0.4));
  // A cylinder against the steep (26.6 degree) frustum: an FCL pair (theory §6c, "FCL").
  EXPECT_TRUE(testing::buildModelFromText(head + "CONTACT/1, IGEOM=2, JGEOM=1" + law, "c.adm").ok);
  expectOneError(head + "CONTACT/1, IGEOM=3, JGEOM=1" + law, 11, "partial CYLINDER");
  expectOneError(head + "CONTACT/1, IGEOM=4, JGEOM=1" + law, 11, "it has no volume");
}

}  // namespace
}  // namespace openmss::contact_test
