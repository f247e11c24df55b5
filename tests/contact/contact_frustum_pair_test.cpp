// CONTACT between two CYLINDER/FRUSTUM solids against independent truth (docs/theory.md §6c,
// "Frustum against frustum"):
// - line contact of parallel axes: the force at a given placement is k d1^e + k d2^e with the
//   section depths d1, d2 at the two ends of the overlap computed here by hand, and the moment
//   about the I marker is theirs;
// - two parallel cylinders pressed together by gravity settle at 2 k d^e = m g;
// - a cylinder resting on another crossed at 90 degrees settles at k d^e = m g;
// - elastic undamped collisions (crossed off-centre, so the hit spins the part; parallel) keep
//   their kinetic energy to 1e-6;
// - the exact partials against central differences. Steep pairs go to FCL
//   (contact_fcl_test.cpp).

#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_support.hpp"
#include "mechanics/contact/contact_loads.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;

// Ground solid: a FRUSTUM (or CYLINDER when top == bottom) along ground x from x = -0.5 to 0.5
// (REULER 90D,90D,0D turns the marker's z along ground x).
std::string groundAlongX(double bottom, double top) {
  char g[200];
  std::snprintf(g, sizeof g, "GRAPHICS/1, FRUSTUM, CM=10, BOTTOM=%.17g, TOP=%.17g, LENGTH=1\n",
                bottom, top);
  return std::string(
             "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
             "PART/1, GROUND\n"
             "MARKER/10, PART=1, QP=-0.5,0,0, REULER=90D,90D,0D\n") +
         g;
}

// Moving cylinder of radius 0.05, length 0.4, mass 2 (CM marker 20 at its centre, marker 21
// at its end disc z = -0.2 of the part). `placement` gives QG, REULER and velocities.
std::string movingCylinder(const std::string& placement) {
  return "PART/2, MASS=2, CM=20, IP=0.027916666666666666,0.027916666666666666,0.0025, " +
         placement +
         "\n"
         "MARKER/20, PART=2\n"
         "MARKER/21, PART=2, QP=0,0,-0.2\n"
         "GRAPHICS/2, CYLINDER, CM=21, RADIUS=0.05, LENGTH=0.4\n";
}

std::string deck(const std::string& ground, const std::string& placement, const std::string& law,
                 bool gravity) {
  return "two cylinders\n" + ground + movingCylinder(placement) + "CONTACT/1, IGEOM=2, JGEOM=1, " +
         law + "\n" + (gravity ? "ACCGRAV/KGRAV=-9.81\n" : "") + "END\n";
}

const char* kLaw = "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, EXPONENT=1.5";

TEST(ContactFrustumPair, LineContactForceIsTheClosedFormSummedOverTheStations) {
  // Ground frustum r(x) = 0.1 - 0.01 (x + 0.5); the cylinder (axis along x at height 0.139,
  // x from 0.3 to 0.7) overlaps it from x = 0.3 to 0.5: the stations are there, with section
  // depths d(x) = r(x) + 0.05 - 0.139.
  const model::Model m =
      build(deck(groundAlongX(0.1, 0.09), "QG=0.5,0,0.139, REULER=90D,90D,0D",
                 "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", false));
  mechanics::MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState();
  const auto loads =
      mechanics::contact::contactLoads<double>(m, s.layout(), m.contacts.at(0), y.data(), false);
  auto depth = [](double x) { return 0.1 - 0.01 * (x + 0.5) + 0.05 - 0.139; };
  const double f1 = 1e5 * std::pow(depth(0.3), 1.5), f2 = 1e5 * std::pow(depth(0.5), 1.5);
  std::printf(
      "line contact: %d points, Fz %.15e (truth %.15e), My %.15e (truth %.15e), |Fx|+|Fy| "
      "%.2e\n",
      loads.points, loads.force.z, f1 + f2, loads.torqueAtI.y, -0.2 * f2,
      std::abs(loads.force.x) + std::abs(loads.force.y));
  ASSERT_EQ(loads.points, 2);
  // Rounding only: the depths (~1e-3) are differences of numbers ~0.1, good to ~1e-13
  // relative each, and the force follows them with the exponent 1.5.
  EXPECT_NEAR(loads.force.z, f1 + f2, 1e-11 * (f1 + f2));
  // The moment is about the I marker, marker 21 at the cylinder's end x = 0.3 (theory §6c,
  // "Loads"): station x = 0.5 is 0.2 ahead of it with its force along +z: My = -0.2 F2.
  EXPECT_NEAR(loads.torqueAtI.y, -0.2 * f2, 1e-11 * f2);
  EXPECT_LT(std::abs(loads.force.x) + std::abs(loads.force.y), 1e-12 * f1);
}

TEST(ContactFrustumPair, ParallelCylindersPressedTogetherSettleWhereEachEndCarriesHalf) {
  const model::Model m =
      build(deck(groundAlongX(0.1, 0.1), "QG=0,0,0.15, REULER=90D,90D,0D", kLaw, true));
  const std::vector<Sample> run = simulate(m, 1.0, 1e-2, 1e-8, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const double d = std::pow(2.0 * kG / 2.0 / 1e5, 1.0 / 1.5);  // 2 k d^e = m g
  const Sample& last = run.back();
  std::printf("parallel cylinders: depth %.9e, truth (mg/2k)^(1/e) = %.9e (rel %.2e), |w| %.2e\n",
              0.15 - last.r.z(), d, std::abs((0.15 - last.r.z()) / d - 1), last.w.norm());
  // Settled: the bounce (damping ratio ~0.3 at 66 rad/s) decays by e^-20 in 1 s.
  EXPECT_NEAR(0.15 - last.r.z(), d, 1e-6 * d);
  EXPECT_LT(last.w.norm() + last.v.norm(), 1e-6);
  EXPECT_LT(std::abs(last.r.x()) + std::abs(last.r.y()), 1e-9);
}

TEST(ContactFrustumPair, CylinderCrossedAtRightAnglesRestsOnOnePoint) {
  // REULER 0,90D,0 turns the part's axis along ground -y: crossed with the ground cylinder.
  const model::Model m =
      build(deck(groundAlongX(0.1, 0.1), "QG=0,0,0.15, REULER=0,90D,0", kLaw, true));
  const std::vector<Sample> run = simulate(m, 1.0, 1e-2, 1e-8, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  const double d = std::pow(2.0 * kG / 1e5, 1.0 / 1.5);  // k d^e = m g
  const Sample& last = run.back();
  std::printf("crossed cylinders: depth %.9e, truth (mg/k)^(1/e) = %.9e (rel %.2e), |w| %.2e\n",
              0.15 - last.r.z(), d, std::abs((0.15 - last.r.z()) / d - 1), last.w.norm());
  EXPECT_NEAR(0.15 - last.r.z(), d, 1e-6 * d);
  EXPECT_LT(last.w.norm() + last.v.norm(), 1e-6);
  EXPECT_LT(std::abs(last.r.x()) + std::abs(last.r.y()), 1e-9);
}

// Kinetic energy of the moving cylinder: translation and rotation with the inertia turned
// into ground axes (IP in the part's axes: 0.0279..., 0.0279..., 0.0025).
double kinetic(const Sample& s) {
  const Eigen::Matrix3d ip =
      Eigen::Vector3d(0.027916666666666666, 0.027916666666666666, 0.0025).asDiagonal();
  const Eigen::Matrix3d inertia = s.a * ip * s.a.transpose();
  return 0.5 * 2.0 * s.v.squaredNorm() + 0.5 * s.w.dot(inertia * s.w);
}

TEST(ContactFrustumPair, UndampedElasticCollisionsKeepTheirEnergy) {
  const char* law = "IMPACT, STIFFNESS=1e6, DAMPING=0, DMAX=1e-3, EXPONENT=1.5";
  struct Case {
    const char* name;
    const char* placement;
    bool spins;
  };
  // Crossed, the part's axis along -y with its CM 0.1 off the ground axis: the hit spins it.
  // Parallel, centred: both stations push alike.
  const Case cases[] = {{"crossed off-centre", "QG=0,0.1,0.15, REULER=0,90D,0, VZ=-1", true},
                        {"parallel", "QG=0,0,0.15, REULER=90D,90D,0D, VZ=-1", false}};
  int compared = 0;
  for (const Case& c : cases) {
    const model::Model m = build(deck(groundAlongX(0.1, 0.1), c.placement, law, false));
    const std::vector<Sample> run = simulate(m, 0.03, 1e-4, 1e-10, 1e-5);
    ASSERT_EQ(run.size(), 301u);
    const double before = kinetic(run.front()), after = kinetic(run.back());
    std::printf("%s collision: energy change %.3e of %.6f, final |w| %.3e, vz %.6f\n", c.name,
                (after - before) / before, before, run.back().w.norm(), run.back().v.z());
    ASSERT_GT(run.back().v.z(), 0.0) << "rebounding";
    if (c.spins) {
      EXPECT_GT(run.back().w.norm(), 1.0);  // the off-centre hit turned energy into spin
    } else {
      EXPECT_LT(run.back().w.norm(), 1e-9);
    }
    // The bar: an elastic, undamped impact loses < 1e-6 of its energy.
    EXPECT_LT(std::abs(after - before), 1e-6 * before);
    ++compared;
  }
  EXPECT_EQ(compared, 2);
}

const char* kFrictionLaw =
    "IMPACT, STIFFNESS=1e5, DAMPING=50, DMAX=1e-3, EXPONENT=1.5, COULOMB_FRICTION=ON, "
    "MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=0.1, "
    "FRICTION_TRANSITION_VELOCITY=1";

TEST(ContactFrustumPair, PartialsOfParallelAndCrossedPairsAreExact) {
  Eigen::VectorXd v(6);
  v << 0.7, 0.2, -0.1, 0.3, 0.2, 1.0;
  // Parallel, the cylinder past the frustum's end (a station on each solid's end).
  checkJacobian(
      deck(groundAlongX(0.1, 0.09), "QG=0.5,0.01,0.139, REULER=90D,90D,0D", kFrictionLaw, false),
      v);
  // Crossed at 80 degrees, off-centre, on a frustum.
  checkJacobian(
      deck(groundAlongX(0.1, 0.09), "QG=0.05,0.07,0.142, REULER=10D,90D,0", kFrictionLaw, false),
      v);
}

}  // namespace
}  // namespace openmss::contact_test
