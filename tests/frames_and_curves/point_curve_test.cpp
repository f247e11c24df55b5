// PTCV, the point-to-curve constraint (docs/theory.md §5d), against independent truth:
//   (a) a bead on a circular wire (a CLOSED CURVE_POINTS curve through 65 points of a circle)
//       is a pendulum: its angle against RK4 on theta'' = -(g/R) sin theta, its energy
//       conserved;
//   (b) a bead on a straight-line curve (ORDER=2, as the corpus's rail curves) against the same
//       bead on a JPRIM INLINE along that line: trajectories and reactions agree;
//   (c) the Newton matrix of a bead on a curve carried by a turning part against central
//       differences, with the structural pattern covering it;
//   (d) bad input: located messages naming the PTCV.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

#include "analysis/request_values.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

using L = mechanics::StateLayout;

const double kRadius = 0.8, kGravity = 9.81, kStart = std::numbers::pi / 3.0;

// MATRIX/1: n + 1 points of a circle of radius r about the origin in the x-y plane, starting at
// the bottom (0, -r) and ending where it started (a CLOSED curve repeats its first point).
std::string circleMatrix(int n, double r) {
  std::ostringstream out;
  out.precision(17);
  out << "MATRIX/1, FULL=RORDER, ROWS=" << n + 1 << ", COLUMNS=3, VALUES=";
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    out << (k ? ", " : "") << r * std::sin(a) << ", " << -r * std::cos(a) << ", 0";
  }
  out << ", 0, " << -r << ", 0";  // exactly the first point
  out << "\n";
  return out.str();
}

std::string beadOnCircle() {
  std::ostringstream s;
  s.precision(17);
  s << "bead on a circular wire\n"
       "UNITS/ SYSTEM=NONE\n"
       "PART/1, GROUND\n"
       "MARKER/10, PART=1\n"
       "MARKER/11, PART=1, FLOATING\n"
       "PART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3, QG="
    << kRadius * std::sin(kStart) << "," << -kRadius * std::cos(kStart) << ",0\n"
    << "MARKER/20, PART=2\n"
    << circleMatrix(64, kRadius)
    << "CURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
       "PTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\n"
       "ACCGRAV/ JGRAV=-9.81\n"
       "REQUEST/1, FORCE, I=20, J=10\n"
       "END\n";
  return s.str();
}

// theta'' = -(g/R) sin theta by classical RK4 with a step of 1e-4 (global error ~1e-13).
double pendulumAngle(double t) {
  double th = kStart, w = 0.0;
  const int n = static_cast<int>(std::round(t / 1e-4));
  const double h = t / n, c = kGravity / kRadius;
  for (int k = 0; k < n; ++k) {
    const double k1t = w, k1w = -c * std::sin(th);
    const double k2t = w + 0.5 * h * k1w, k2w = -c * std::sin(th + 0.5 * h * k1t);
    const double k3t = w + 0.5 * h * k2w, k3w = -c * std::sin(th + 0.5 * h * k2t);
    const double k4t = w + h * k3w, k4w = -c * std::sin(th + h * k3t);
    th += h / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t);
    w += h / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return th;
}

TEST(PointCurve, BeadOnACircularWireIsAPendulum) {
  const model::Model m = test::buildModelFromText(beadOnCircle(), "bead.adm");
  ASSERT_EQ(m.ptcvs.size(), 1u);
  test::BdfRun run(m, 1e-9, 0.005, true);
  run.start();
  const double energy0 = kGravity * (-kRadius * std::cos(kStart));
  double worstAngle = 0.0, worstEnergy = 0.0, worstRadius = 0.0, worstTension = 0.0;
  int compared = 0;
  for (double t = 0.1; t <= 2.0 + 1e-9; t += 0.1) {
    run.advanceTo(t);
    const double x = run.body(0, L::kR), y = run.body(0, L::kR + 1), z = run.body(0, L::kR + 2);
    const double vx = run.body(0, L::kV), vy = run.body(0, L::kV + 1);
    const double theta = std::atan2(x, -y);
    // The wire is a cubic interpolant of the circle through 64 arcs: it departs from the circle
    // by about (5/384) h^4 / R^3 ~ 1e-6 R (h the chord); the integrator's ERROR=1e-9 adds less.
    // Over 2 s (about 1 period) 2e-4 rad bounds the phase drift this makes.
    EXPECT_NEAR(theta, pendulumAngle(t), 2e-4) << "t=" << t;
    EXPECT_NEAR(std::hypot(x, y), kRadius, 1e-5) << "t=" << t;
    EXPECT_NEAR(z, 0.0, 1e-12);
    const double energy = 0.5 * (vx * vx + vy * vy) + kGravity * y;
    EXPECT_NEAR(energy, energy0, 1e-5) << "t=" << t;
    // The reaction on the bead (REQUEST FORCE I=20, J=RM): the normal force
    // m (g cos theta + v^2 / R) towards the centre.
    const auto f = requestColumns(run.system(), m.requests[0], t, run.y(), run.yp());
    const double v2 = vx * vx + vy * vy;
    const double tension = kGravity * std::cos(theta) + v2 / kRadius;
    EXPECT_NEAR(f[0], tension, 1e-3 * tension) << "t=" << t;
    worstAngle = std::max(worstAngle, std::abs(theta - pendulumAngle(t)));
    worstEnergy = std::max(worstEnergy, std::abs(energy - energy0));
    worstRadius = std::max(worstRadius, std::abs(std::hypot(x, y) - kRadius));
    worstTension = std::max(worstTension, std::abs(f[0] - tension) / tension);
    ++compared;
  }
  EXPECT_EQ(compared, 20);
  std::printf(
      "bead on a circle over 2 s: |theta - RK4| <= %.2e rad, |E - E0| <= %.2e, "
      "|r - R| <= %.2e, tension rel. error <= %.2e\n",
      worstAngle, worstEnergy, worstRadius, worstTension);
}

// A bead sliding down a straight line through (0, 0, 0) and (3, -1.5, 1) (ground), damped along
// it by a translational damper (to ground marker 13, so that the FORCE requests between 20 and
// the constraint's J see the constraint alone): once as a PTCV on an ORDER=2 curve through 4 points
// of the line, once as a JPRIM INLINE whose J marker has z along the line.
std::string beadOnLine(bool inline_) {
  const std::string head =
      "bead on a line\n"
      "UNITS/ SYSTEM=NONE\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "MARKER/11, PART=1, FLOATING\n"
      // z along (3, -1.5, 1)/|.|: the 3-1-3 angles psi = atan2(3, 1.5), theta = acos(1/|.|).
      "MARKER/12, PART=1, ZP=3,-1.5,1, XP=1,2,0\n"
      "MARKER/13, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=0.1,0.2,0.3, QG=0.6,-0.3,0.2, VX=0.3, VY=-0.15, VZ=0.1\n"
      "MARKER/20, PART=2\n"
      "ACCGRAV/ JGRAV=-9.81\n"
      "SFORCE/1, TRANSLATIONAL, I=20, J=13, FUNCTION=-0.8*VR(20,13)\n"
      "REQUEST/1, FORCE, I=20, J=" +
      std::string(inline_ ? "12" : "10") + "\n";
  if (inline_) return head + "JPRIM/1, INLINE, I=20, J=12\nEND\n";
  return head +
         "MATRIX/1, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=-3,1.5,-1, 0,0,0, 3,-1.5,1, 6,-3,2\n"
         "CURVE/1, OPEN, MATRIX=1, CURVE_POINTS, ORDER=2\n"
         "PTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\n"
         "END\n";
}

TEST(PointCurve, StraightLineCurveMatchesInline) {
  const model::Model curve = test::buildModelFromText(beadOnLine(false), "line.adm");
  const model::Model line = test::buildModelFromText(beadOnLine(true), "inline.adm");
  test::BdfRun a(curve, 1e-9, 0.01, true), b(line, 1e-9, 0.01, true);
  a.start();
  b.start();
  double worst = 0.0, worstForce = 0.0;
  int compared = 0;
  for (double t = 0.2; t <= 1.0 + 1e-9; t += 0.2) {
    a.advanceTo(t);
    b.advanceTo(t);
    // Both integrate the same 1-DOF motion (plus free rotation) to ERROR=1e-9: 1e-6 is margin.
    for (int c : {L::kR, L::kR + 1, L::kR + 2, L::kV, L::kV + 1, L::kV + 2}) {
      EXPECT_NEAR(a.body(0, c), b.body(0, c), 1e-6) << "t=" << t << " entry " << c;
      worst = std::max(worst, std::abs(a.body(0, c) - b.body(0, c)));
      ++compared;
    }
    const auto fa = requestColumns(a.system(), curve.requests[0], t, a.y(), a.yp());
    const auto fb = requestColumns(b.system(), line.requests[0], t, b.y(), b.yp());
    for (int c : {0, 1, 2, 3}) {
      EXPECT_NEAR(fa[c], fb[c], 1e-5) << "t=" << t << " column " << c;
      worstForce = std::max(worstForce, std::abs(fa[c] - fb[c]));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 50);
  // The bead moved: the comparison is not of two resting states.
  EXPECT_GT(std::abs(a.body(0, L::kR) - 0.6), 0.5);
  std::printf("PTCV line vs INLINE over 1 s: states within %.2e, reactions within %.2e\n", worst,
              worstForce);
}

// A wire part turning about ground z (held by a spring), carrying a closed egg-shaped curve in
// a tilted RM marker; a bead on it under gravity.
const char* kTurningWire =
    "bead on a turning wire\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=3, CM=21, IP=1,1,2, WZ=1.5\n"
    "MARKER/21, PART=2\n"
    "MARKER/22, PART=2, QP=0.1,0.2,0, REULER=10D,20D,0D\n"
    "MARKER/23, PART=2, FLOATING\n"
    "MATRIX/1, FULL=RORDER, ROWS=7, COLUMNS=3, VALUES=1,0,0, 0.5,0.9,0, -0.6,0.7,0, -1.1,0,0,"
    " -0.6,-0.7,0, 0.5,-0.9,0, 1,0,0\n"
    "CURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
    "PART/3, MASS=0.5, CM=30, IP=0.01,0.01,0.01, QG=1.084807753,0.373648178,0\n"
    "MARKER/30, PART=3\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "SFORCE/1, ROTATIONAL, I=21, J=10, FUNCTION=-2*AZ(21,10)\n"
    "PTCV/1, I=30, JFLOAT=23, CURVE=1, RM=22\n"
    "ACCGRAV/ JGRAV=-9.81\n"
    "END\n";

TEST(PointCurve, NewtonMatrixMatchesCentralDifferences) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kTurningWire, "wire.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));  // the starting-gap warning may be reported
  test::BdfRun run(m, 1e-6, 0.01, true);
  run.start();
  run.advanceTo(0.25);
  Eigen::VectorXd y = run.y(), yp = run.yp();
  for (int c = 0; c < yp.size(); ++c) yp(c) += 0.01 * std::cos(2.0 + c);
  Eigen::MatrixXd jac;
  const double worst = testing::checkNewtonMatrix(run.system(), 0.25, y, yp, 19.0, "PTCV", &jac);
  const int nonzeros = testing::expectPatternCovers(run.system(), jac);
  EXPECT_GT(nonzeros, 40);
  // The constraint holds along the run: the bead stays on the curve (index-3 BDF, ERROR=1e-6).
  const mechanics::MultibodySystem& s = run.system();
  int ptcvRows = 0;
  for (int k = 0; k < s.constraints().size(); ++k)
    if (s.constraints().equations()[k].ptcv == 0) ++ptcvRows;
  EXPECT_EQ(ptcvRows, 2);
  std::printf("PTCV Newton matrix: largest relative difference %.2e, %d nonzeros covered\n", worst,
              nonzeros);
}

std::vector<std::string> buildErrors(const std::string& body) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      "bad\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
      "MATRIX/1, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=0,0,0, 1,0,0, "
      "2,0,0, 3,0,0\nCURVE/1, OPEN, MATRIX=1, CURVE_POINTS\n" +
          body + "END\n",
      "bad.adm", ds, d);
  model::Model m;
  model::buildModel(ds, m, d);
  std::vector<std::string> out;
  for (const auto& x : d.all())
    if (x.severity == Severity::Error) out.push_back(format(x));
  return out;
}

TEST(PointCurve, BadInputIsLocatedAndNamed) {
  auto one = [](const std::string& body, const std::string& expected) {
    const auto errors = buildErrors(body);
    ASSERT_EQ(errors.size(), 1u) << body;
    EXPECT_NE(errors[0].find(expected), std::string::npos) << errors[0];
  };
  one("PTCV/5, I=20, JFLOAT=11, CURVE=1, RM=10, VEL=2\n",
      "bad.adm:9:42: error: PTCV/5: VEL (the initial speed along the curve) is not supported");
  one("PTCV/5, I=20, JFLOAT=11, CURVE=7, RM=10\n",
      "bad.adm:9:26: error: PTCV/5: CURVE/7 does not exist");
  one("PTCV/5, I=20, JFLOAT=20, CURVE=1, RM=10\n",
      "bad.adm:9:15: error: PTCV/5: JFLOAT=20 is not on the part of RM");
  one("PTCV/5, I=11, JFLOAT=10, CURVE=1, RM=10\n",
      "bad.adm:9:1: error: PTCV/5: I and RM are on the same part");
}

}  // namespace
}  // namespace openmss::analysis
