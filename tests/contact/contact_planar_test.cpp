// 2-D CONTACT (docs/theory.md §6c, "2-D contact"): CIRCLE, ARC, POINT and CURVE geometries in
// one plane, with the normal and friction laws of the 3-D contacts. Against independent truth:
// - a disc dropped inside a fixed ring (a flipped CIRCLE) bounces as the IMPACT ODE of its
//   penetration integrated by RK4 (the history to 1e-6 of its peak), and the onset is located
//   at the free-fall closed form;
// - a disc striking a fixed disc with POISSON rebounds at the restitution coefficient;
// - an ARC holds the disc only within its sweep (the other half of the ring lets it fall);
// - a disc and a POINT resting on a CURVE floor sink to (m g / k)^(1/e), the curve traversed
//   either way with its side flipped to match;
// - the Newton matrix against central differences (ring with friction, disc and point on a
//   curve);
// - bad input: two holes, a disc larger than its hole, geometries out of one plane, a flip of a
//   solid: one located message each.

#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_support.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;
const char* kUnits = "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n";

// A disc of radius 0.1 (mass 1) centred at (0, y0) moving at (0, vy) inside a fixed ring of
// radius 0.15 (a flipped CIRCLE, or an ARC of the given sweep), gravity -g along y.
std::string ringDeck(const std::string& law, double y0, double vy, double g,
                     const char* ring = "CIRCLE, CM=10, RADIUS=0.15", double x0 = 0.0) {
  char part[200];
  std::snprintf(part, sizeof part,
                "PART/2, MASS=1, CM=20, IP=0.005,0.005,0.01, QG=%.17g,%.17g,0, VY=%.17g\n", x0, y0,
                vy);
  return std::string("disc in a ring\n") + kUnits + "PART/1, GROUND\nMARKER/10, PART=1\n" +
         "GRAPHICS/1, " + ring + "\n" + part + "MARKER/20, PART=2\n" +
         "GRAPHICS/2, CIRCLE, CM=20, RADIUS=0.1\n" +
         "CONTACT/1, IGEOM=2, JGEOM=1, JFLIP_GEOMETRY=1, " + law +
         "\nACCGRAV/JGRAV=" + std::to_string(-g) + "\nEND\n";
}

const char* kImpact = "IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5";

TEST(ContactPlanar, DiscInARingBouncesAsTheImpactOde) {
  // Touching the ring's bottom at t = 0 (centre 0.05 below the ring's), moving down at 1 m/s:
  // the penetration d = -y - 0.05 obeys d'' = g - F(d, d')/m, as the sphere on a floor.
  const ImpactOde ode{1e6, 1.5, 100.0, 1e-3, kG};
  const double dt = 1e-5, end = 0.02;
  const std::vector<Sample> run =
      simulate(build(ringDeck(kImpact, -0.05, -1.0, kG)), end, dt, 1e-10, 2e-6);
  ASSERT_EQ(run.size(), 2001u);
  std::vector<double> t, depth, truth;
  double x[2] = {0.0, 1.0}, sideways = 0.0;
  for (size_t k = 0; k < run.size(); ++k) {
    if (k > 0)
      for (int q = 0; q < 1000; ++q) ode.rk4(x, dt / 1000);
    t.push_back(run[k].t);
    depth.push_back(-run[k].r.y() - 0.05);
    truth.push_back(x[0]);
    sideways = std::max({sideways, std::abs(run[k].r.x()), std::abs(run[k].r.z())});
  }
  const double maxTruth = peak(truth), maxRun = peak(depth);
  const double durationTruth = returnTime(t, truth), durationRun = returnTime(t, depth);
  double worst = 0.0;
  for (size_t k = 0; k < run.size(); ++k) worst = std::max(worst, std::abs(depth[k] - truth[k]));
  std::printf(
      "disc in a ring: max penetration %.9e (truth %.9e, rel %.2e), duration %.9e (truth %.9e, "
      "rel %.2e), worst |d - truth| %.2e, off-axis motion %.1e\n",
      maxRun, maxTruth, std::abs(maxRun / maxTruth - 1), durationRun, durationTruth,
      std::abs(durationRun / durationTruth - 1), worst, sideways);
  ASSERT_GT(durationTruth, 0.0);
  // As the sphere's bounce (contact_normal_law_test.cpp): 1e-6 of the peak.
  EXPECT_NEAR(maxRun, maxTruth, 1e-6 * maxTruth);
  EXPECT_NEAR(durationRun, durationTruth, 1e-6 * durationTruth);
  EXPECT_LT(worst, 1e-6 * maxTruth);
  EXPECT_LT(sideways, 1e-12);  // the force lies along y: the disc stays on its line
}

TEST(ContactPlanar, OnsetInARingIsAtTheFreeFallTime) {
  // 0.01 of clearance, 1 m/s down: first touch at (-1 + sqrt(1 + 2 g 0.01)) / g.
  const double touch = (-1.0 + std::sqrt(1.0 + 2.0 * kG * 0.01)) / kG;
  std::vector<analysis::ContactEvent> events;
  const std::vector<Sample> run =
      simulate(build(ringDeck(kImpact, -0.04, -1.0, kG)), 0.03, 1e-4, 1e-6, 1e-3, &events);
  ASSERT_EQ(run.size(), 301u);
  ASSERT_GE(events.size(), 2u);
  EXPECT_TRUE(events[0].onset);
  EXPECT_FALSE(events[1].onset);
  std::printf("disc in a ring: onset at %.12f (free fall %.12f, diff %.2e)\n", events[0].time,
              touch, events[0].time - touch);
  // The bisection's bracket (1e-10 of a step) plus the free flight's integration error.
  EXPECT_NEAR(events[0].time, touch, 1e-6);
}

TEST(ContactPlanar, DiscOnDiscReboundsAtTheRestitutionCoefficient) {
  // The moving disc (radius 0.1) touches a fixed disc (radius 0.05) at t = 0 moving at 1 m/s
  // towards it along -y, no gravity: POISSON returns the speed times e.
  for (const double e : {0.3, 0.8}) {
    std::string deck =
        ringDeck("POISSON, PENALTY=1e5, RESTITUTION_COEFFICIENT=" + std::to_string(e), 0.15, -1.0,
                 0.0, "CIRCLE, CM=10, RADIUS=0.05");
    deck.replace(deck.find("JFLIP_GEOMETRY=1, "), 18, "");
    const std::vector<Sample> run = simulate(build(deck), 0.03, 1e-4, 1e-8, 1e-5);
    ASSERT_EQ(run.size(), 301u);
    ASSERT_GT(run.back().r.y(), 0.15) << "separated";
    std::printf("disc on disc, POISSON e = %.2f: rebound ratio %.6f\n", e, run.back().v.y());
    EXPECT_NEAR(run.back().v.y(), e, 1e-3);  // as the sphere's (contact_normal_law_test.cpp)
  }
}

TEST(ContactPlanar, AnArcHoldsTheDiscOnlyWithinItsSweep) {
  // The lower half of the ring (RANGLE -180D from +x, clockwise) stops the disc; the upper half
  // (+180D) lets it fall freely from rest: y = -g t^2 / 2 (to the integrator's accuracy).
  const std::vector<Sample> lower =
      simulate(build(ringDeck(kImpact, 0.0, 0.0, kG, "ARC, CM=10, RADIUS=0.15, RANGLE=-180D")), 0.3,
               1e-2, 1e-8, 1e-3);
  const std::vector<Sample> upper =
      simulate(build(ringDeck(kImpact, 0.0, 0.0, kG, "ARC, CM=10, RADIUS=0.15, RANGLE=180D")), 0.3,
               1e-2, 1e-8, 1e-3);
  ASSERT_EQ(upper.size(), 31u);
  double freeFall = 0.0, lowest = 0.0;
  for (const Sample& s : upper)
    freeFall = std::max(freeFall, std::abs(s.r.y() + 0.5 * kG * s.t * s.t));
  for (const Sample& s : lower) lowest = std::min(lowest, s.r.y());
  std::printf("ARC: upper half, max |y - free fall| %.2e; lower half, lowest y %.6f\n", freeFall,
              lowest);
  // Free fall to the integrator's accuracy (ERROR 1e-8 over 0.3 s), where the arc would hold
  // the disc 0.05 below the centre.
  EXPECT_LT(freeFall, 1e-6);
  EXPECT_GT(lowest, -0.06);  // held at the ring's bottom, 0.05 below its centre, a few mm deep
}

// A floor CURVE along the ground x axis (-1..1), a disc of radius 0.1 (or a POINT at its
// centre) on a part whose centre is at (0.1, y0). `reversed`: the points listed from +x to -x
// (material below: on the left of travel); otherwise from -x to +x with JFLIP_GEOMETRY (material
// below after the flip).
std::string curveFloorDeck(bool reversed, bool point, double y0) {
  const char* points = reversed ? "1,0,0, 0.5,0,0, 0,0,0, -0.5,0,0, -1,0,0"
                                : "-1,0,0, -0.5,0,0, 0,0,0, 0.5,0,0, 1,0,0";
  char part[160];
  std::snprintf(part, sizeof part, "PART/2, MASS=1, CM=20, IP=0.005,0.005,0.01, QG=0.1,%.17g,0\n",
                y0);
  return std::string("disc on a curve\n") + kUnits + "PART/1, GROUND\nMARKER/10, PART=1\n" +
         "MATRIX/1, FULL=RORDER, ROWS=5, COLUMNS=3, VALUES=" + points + "\n" +
         "CURVE/1, OPEN, MATRIX=1, CURVE_POINTS\n" + "GRAPHICS/1, CURVE, CID=1, CRM=10\n" + part +
         "MARKER/20, PART=2\n" +
         (point ? "GRAPHICS/2, POINT, RM=20\n" : "GRAPHICS/2, CIRCLE, CM=20, RADIUS=0.1\n") +
         "CONTACT/1, IGEOM=2, JGEOM=1, " + (reversed ? "" : "JFLIP_GEOMETRY=1, ") + kImpact +
         "\nACCGRAV/JGRAV=-9.81\nEND\n";
}

TEST(ContactPlanar, DiscAndPointRestOnACurveAtTheClosedFormPenetration) {
  const double truth = std::pow(kG / 1e6, 1.0 / 1.5);  // k d^e = m g
  for (const bool point : {false, true})
    for (const bool reversed : {true, false}) {
      const double radius = point ? 0.0 : 0.1;
      const std::vector<Sample> run =
          simulate(build(curveFloorDeck(reversed, point, radius + 1e-4)), 1.0, 1e-2, 1e-10, 2e-4);
      ASSERT_EQ(run.size(), 101u);
      const double depth = radius - run.back().r.y();
      std::printf("%s on a CURVE (%s): resting penetration %.12e, (m g / k)^(1/e) = %.12e\n",
                  point ? "POINT" : "disc", reversed ? "listed right to left" : "flipped", depth,
                  truth);
      EXPECT_NEAR(depth, truth, 1e-6 * truth);
      EXPECT_NEAR(run.back().r.x(), 0.1, 1e-9);  // a straight floor: no sideways push
    }
}

TEST(ContactPlanar, NewtonMatrixMatchesCentralDifferences) {
  const char* friction =
      ", COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=1e-3, "
      "FRICTION_TRANSITION_VELOCITY=1e-2";
  // The disc pressed 1e-3 into the ring, off the axis, moving and spinning in the plane.
  const std::string ring = ringDeck(std::string(kImpact) + friction, -0.042, 0.0, kG,
                                    "CIRCLE, CM=10, RADIUS=0.15", 0.03);
  Eigen::VectorXd v(6);
  v << 0.3, -0.2, 0.0, 0.0, 0.0, 0.7;
  checkJacobian(ring, v);
  for (const bool point : {false, true}) {
    std::string floor = curveFloorDeck(true, point, point ? -5e-4 : 0.0995);
    floor.replace(floor.find("\nACCGRAV"), 0, friction);
    checkJacobian(floor, v);
  }
}

void expectOneError(const std::string& text, int line, const std::string& what) {
  contact_test::expectOneError(testing::buildModelFromText(text, "p.adm"), line, what);
}

TEST(ContactPlanar, BadPlanarInputIsLocated) {
  const std::string head =
      "planar\nPART/1, GROUND\nMARKER/10, PART=1\nGRAPHICS/1, CIRCLE, CM=10, RADIUS=0.15\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2, QP=0,0,0.5\n"
      "GRAPHICS/2, CIRCLE, CM=20, RADIUS=0.1\nGRAPHICS/3, CIRCLE, CM=20, RADIUS=0.2\n"
      "GRAPHICS/4, CIRCLE, CM=21, RADIUS=0.1\nGRAPHICS/5, BOX, CORNER=20, X=1, Y=1, Z=1\n";
  const std::string law = ", IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-3, EXPONENT=2\nEND\n";
  // Line 12 is the CONTACT.
  expectOneError(head + "CONTACT/1, IGEOM=2, JGEOM=1, IFLIP_GEOMETRY=2, JFLIP_GEOMETRY=1" + law, 12,
                 "two flipped circles (holes) always overlap");
  expectOneError(head + "CONTACT/1, IGEOM=3, JGEOM=1, JFLIP_GEOMETRY=1" + law, 12,
                 "the disc (radius 0.200000) does not fit in the hole (radius 0.150000)");
  expectOneError(head + "CONTACT/1, IGEOM=4, JGEOM=1" + law, 12,
                 "GRAPHICS/4 and GRAPHICS/1 are not in one plane");
  expectOneError(head + "CONTACT/1, IGEOM=5, JGEOM=1, IFLIP_GEOMETRY=5" + law, 12,
                 "IFLIP_GEOMETRY names GRAPHICS/5, which is not a CIRCLE, ARC or CURVE");
}

}  // namespace
}  // namespace openmss::contact_test
