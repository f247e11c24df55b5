// CVCV, the curve-to-curve constraint (docs/theory.md §5e), against independent truth:
//   (a) a circular cam (radius R, eccentric by e about its pivot, turned by a MOTION) against a
//       flat-faced follower on a translational joint: the face's lift is R + e sin(theta) in
//       closed form, the contact force m (g + y'') along the face normal, and the contact point
//       (read as the torque about the face marker) at x = e cos(theta);
//   (b) the same cam against a roller follower (a circle of radius r): the roller centre's lift
//       e sin(theta) + sqrt((R + r)^2 - e^2 cos^2(theta)), the force along the line of centres;
//   (c) a free cam (torsional spring) driving a roller follower under gravity: energy conserved,
//       and the Newton matrix against central differences;
//   (d) bad input: located messages naming the CVCV.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/request_values.hpp"
#include "mechanics/expression_run_state.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

using L = mechanics::StateLayout;

// The run state's warm start of the curve searches (docs/theory.md §5d), as a run driver keeps
// it, for a BdfRun: attached to its system (BdfRun owns a non-const system and lends it const;
// the run state is the one thing a driver sets on it), committed by advance() at every 0.005 s
// so that the local Newton from the committed parameters converges (without it every
// evaluation searches both curves globally, which is correct but slow).
class WarmStart {
 public:
  WarmStart(const model::Model& m, test::BdfRun& run) : state_(m), run_(run) {
    auto& s = const_cast<mechanics::MultibodySystem&>(run.system());
    state_.trackCurveParameters(s.constraints());
    s.setRunState(&state_);
    state_.accept(run.system(), 0.0, run.y(), run.yp());
  }
  void advance(double from, double to) {
    const int n = static_cast<int>(std::ceil((to - from) / 0.005 - 1e-9));
    for (int k = 1; k <= n; ++k) {
      const double t = from + (to - from) * k / n;
      run_.advanceTo(t);
      state_.accept(run_.system(), t, run_.y(), run_.yp());
    }
  }
  const mechanics::ExpressionRunState& state() const { return state_; }

 private:
  mechanics::ExpressionRunState state_;
  test::BdfRun& run_;
};

const double kR = 0.3, kE = 0.1, kRoller = 0.1, kOmega = 6.0, kMass = 2.0, kG = 9.81;

// MATRIX/id: n + 1 points of a circle of radius r about (cx, 0) counter-clockwise, the last
// repeating the first (a CLOSED curve).
std::string circleMatrix(int id, int n, double cx, double r) {
  std::ostringstream out;
  out.precision(17);
  out << "MATRIX/" << id << ", FULL=RORDER, ROWS=" << n + 1 << ", COLUMNS=3, VALUES=";
  for (int k = 0; k <= n; ++k) {
    const double a = 2.0 * std::numbers::pi * (k % n) / n;
    out << (k ? ", " : "") << cx + r * std::cos(a) << ", " << r * std::sin(a) << ", 0";
  }
  out << "\n";
  return out.str();
}

// Cam PART/2 turning about ground z at the origin (MOTION theta = omega t), carrying a circle of
// radius R about (e, 0) in IRM/21; follower PART/3 on a translational joint along ground y, with
// a flat face (a line along x, in JRM/31) or a roller (a circle of radius r about JRM/31).
std::string camFollower(bool roller) {
  const double y0 = roller ? std::sqrt((kR + kRoller) * (kR + kRoller) - kE * kE) : kR;
  std::ostringstream s;
  s.precision(17);
  s << "cam and follower\n"
       "UNITS/ SYSTEM=NONE\n"
       "PART/1, GROUND\n"
       "MARKER/10, PART=1\n"
       "MARKER/12, PART=1, ZP=0,1,0, XP=1,0,0\n"
       "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
       "MARKER/20, PART=2\n"
       "MARKER/21, PART=2\n"
       "MARKER/22, PART=2, FLOATING\n"
       "PART/3, MASS="
    << kMass << ", CM=30, IP=0.01,0.01,0.01, QG=0," << y0 << ",0\n"
    << "MARKER/30, PART=3, ZP=0,1,0, XP=1,0,0\n"
       "MARKER/31, PART=3\n"
       "MARKER/32, PART=3, FLOATING\n"
    << circleMatrix(1, 64, kE, kR);
  if (roller)
    s << circleMatrix(2, 64, 0.0, kRoller) << "CURVE/2, CLOSED, MATRIX=2, CURVE_POINTS\n";
  else
    s << "MATRIX/2, FULL=RORDER, ROWS=5, COLUMNS=3, VALUES=-0.5,0,0, -0.25,0,0, 0,0,0, "
         "0.25,0,0, 0.5,0,0\n"
         "CURVE/2, OPEN, MATRIX=2, CURVE_POINTS, ORDER=2\n";
  s << "CURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
       "JOINT/1, REVOLUTE, I=20, J=10\n"
       "MOTION/1, JOINT=1, ROTATION, FUNCTION="
    << kOmega << "*TIME\n"
    << "JOINT/2, TRANSLATIONAL, I=30, J=12\n"
       "CVCV/1, ICURVE=1, IRM=21, IFLOAT=22, JCURVE=2, JRM=31, JFLOAT=32\n"
       "ACCGRAV/ JGRAV=-9.81\n"
       "REQUEST/1, FORCE, I=31, J=21\n"
       "REQUEST/2, FORCE, I=21, J=31\n"
       "END\n";
  return s.str();
}

// The follower's lift (JRM's y) at cam angle th and its second time derivative (central
// differences of the closed form, h = 1e-4 s: error ~ h^2 |y''''| / 12 ~ 1e-7 here).
double lift(bool roller, double th) {
  if (!roller) return kR + kE * std::sin(th);
  const double c = kE * std::cos(th);
  return kE * std::sin(th) + std::sqrt((kR + kRoller) * (kR + kRoller) - c * c);
}
double liftAcceleration(bool roller, double t) {
  const double h = 1e-4;
  return (lift(roller, kOmega * (t + h)) - 2.0 * lift(roller, kOmega * t) +
          lift(roller, kOmega * (t - h))) /
         (h * h);
}

void followLift(bool roller) {
  const model::Model m = test::buildModelFromText(camFollower(roller), "cam.adm");
  ASSERT_EQ(m.cvcvs.size(), 1u);
  test::BdfRun run(m, 1e-8, 0.01, true);
  WarmStart warm(m, run);
  run.start();
  double previous = 0.0;
  double worstLift = 0.0, worstForce = 0.0, worstPoint = 0.0;
  int compared = 0;
  // Over 1.2 s the cam turns 7.2 rad: the contact goes once round the cam.
  for (double t = 0.05; t <= 1.2 + 1e-9; t += 0.05) {
    warm.advance(previous, t);
    previous = t;
    const double th = kOmega * t;
    const double y = run.body(1, L::kR + 1);
    // The cam is a cubic interpolant of a circle through 64 points: it departs from the circle
    // by about (5/384) h^4 / R^3 ~ 2e-7 (h the chord; the roller's 64 points add ~1e-7); the
    // integrator's ERROR=1e-8 on a kinematically driven system adds less. 2e-6 is margin.
    EXPECT_NEAR(y, lift(roller, th), 2e-6) << "t=" << t;
    worstLift = std::max(worstLift, std::abs(y - lift(roller, th)));
    // The contact force on the follower (REQUEST/1, I=JRM): its y component carries the
    // follower, m (g + y''). The interpolated circles' curvature is good to ~(h/R)^2/12 ~ 1e-3,
    // which enters y'' (about e omega^2 = 3.6): 1e-3 of m (g + e omega^2) bounds the error.
    const auto f = requestColumns(run.system(), m.requests[0], t, run.y(), run.yp());
    const double fy = kMass * (kG + liftAcceleration(roller, t));
    const double tol = 1e-3 * kMass * (kG + kE * kOmega * kOmega);
    EXPECT_NEAR(f[2], fy, tol) << "t=" << t;
    // Its x component: zero on the flat face; along the line of centres for the roller.
    const double cx = kE * std::cos(th), cy = kE * std::sin(th);
    const double fx = roller ? fy * (0.0 - cx) / (y - cy) : 0.0;
    EXPECT_NEAR(f[1], fx, tol) << "t=" << t;
    EXPECT_NEAR(f[3], 0.0, 1e-9) << "t=" << t;  // in the plane
    worstForce = std::max({worstForce, std::abs(f[2] - fy), std::abs(f[1] - fx)});
    // The torque about the face marker (flat) is the contact point's x times the force: the
    // contact point x = e cos(theta); about the roller's centre it is zero (force through it).
    const double tz = roller ? 0.0 : cx * f[2];
    EXPECT_NEAR(f[7], tz, 1e-3 * kMass * kG * 0.1) << "t=" << t;
    worstPoint = std::max(worstPoint, std::abs(f[7] - tz));
    // The reaction on the cam (REQUEST/2, I=IRM, J=JRM) is the opposite force.
    const auto g = requestColumns(run.system(), m.requests[1], t, run.y(), run.yp());
    EXPECT_NEAR(g[2], -f[2], 1e-9 * (1.0 + std::abs(f[2]))) << "t=" << t;
    compared += 5;
  }
  EXPECT_EQ(compared, 120);
  std::printf(
      "CVCV cam with %s follower over 1.2 s: |lift - closed form| <= %.2e, "
      "|force - m(g + y'')| <= %.2e, |torque - x_contact F| <= %.2e\n",
      roller ? "roller" : "flat", worstLift, worstForce, worstPoint);
}

TEST(CurveCurve, CamWithFlatFollowerLiftsInClosedForm) { followLift(false); }
TEST(CurveCurve, CamWithRollerFollowerLiftsInClosedForm) { followLift(true); }

// A free cam (a torsional spring to ground, a tilted-in-plane IRM off the pivot) pushing a
// roller follower held down by gravity: a conservative 1-DOF system.
std::string freeCam() {
  const double y0 = std::sqrt((kR + kRoller) * (kR + kRoller) - kE * kE);
  std::ostringstream s;
  s.precision(17);
  s << "free cam\n"
       "UNITS/ SYSTEM=NONE\n"
       "PART/1, GROUND\n"
       "MARKER/10, PART=1\n"
       "MARKER/12, PART=1, ZP=0,1,0, XP=1,0,0\n"
       "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.05, WZ=10\n"
       "MARKER/20, PART=2\n"
       // IRM turned by 90 degrees about z and moved to (e, 0): the circle about its origin.
       "MARKER/21, PART=2, QP=0.1,0,0, REULER=90D,0D,0D\n"
       "MARKER/22, PART=2, FLOATING\n"
       "PART/3, MASS="
    << kMass << ", CM=30, IP=0.01,0.01,0.01, QG=0," << y0 << ",0\n"
    << "MARKER/30, PART=3, ZP=0,1,0, XP=1,0,0\n"
       "MARKER/31, PART=3\n"
       "MARKER/32, PART=3, FLOATING\n"
    << circleMatrix(1, 64, 0.0, kR) << circleMatrix(2, 64, 0.0, kRoller)
    << "CURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
       "CURVE/2, CLOSED, MATRIX=2, CURVE_POINTS\n"
       "JOINT/1, REVOLUTE, I=20, J=10\n"
       "SFORCE/1, ROTATIONAL, I=20, J=10, FUNCTION=-4*AZ(20,10)\n"
       "JOINT/2, TRANSLATIONAL, I=30, J=12\n"
       "CVCV/1, ICURVE=1, IRM=21, IFLOAT=22, JCURVE=2, JRM=31, JFLOAT=32\n"
       "ACCGRAV/ JGRAV=-9.81\n"
       "END\n";
  return s.str();
}

TEST(CurveCurve, FreeCamConservesEnergyAndNewtonMatrixMatchesCentralDifferences) {
  const model::Model m = test::buildModelFromText(freeCam(), "freecam.adm");
  ASSERT_EQ(m.cvcvs.size(), 1u);
  test::BdfRun run(m, 1e-9, 0.005, true);
  WarmStart warm(m, run);
  run.start();
  double previous = 0.0;
  // The cam's angle about ground z, unwrapped along the run (marker 20 starts aligned with
  // ground), for the spring's potential 2 theta^2.
  double theta = 0.0;
  auto energy = [&] {
    const auto f =
        mechanics::markerState(m, run.system().layout(), m.markerIndex.at(20), run.y().data());
    const double a = std::atan2(f.a.c[0].y, f.a.c[0].x);
    theta += std::remainder(a - theta, 2.0 * std::numbers::pi);
    const double wz = run.body(0, L::kW + 2);  // body z is ground z
    const double vy = run.body(1, L::kV + 1), y = run.body(1, L::kR + 1);
    return 0.5 * 0.05 * wz * wz + 0.5 * kMass * vy * vy + kMass * kG * y + 2.0 * theta * theta;
  };
  const double e0 = energy();
  double worst = 0.0, turned = 0.0;
  int compared = 0;
  for (double t = 0.1; t <= 1.2 + 1e-9; t += 0.1) {
    warm.advance(previous, t);
    previous = t;
    // ERROR=1e-9 on a smooth conservative system: BDF's numerical dissipation and the
    // index-3 constraint drift lose about 1e-6 of the energy (11.1 J) per second (measured
    // 1.2e-6 at 1.7 s); 3e-6 bounds it with margin over the run.
    const double e = energy();
    EXPECT_NEAR(e, e0, 3e-6 * std::abs(e0)) << "t=" << t;
    worst = std::max(worst, std::abs(e - e0));
    turned = std::max(turned, std::abs(theta));
    ++compared;
  }
  EXPECT_EQ(compared, 12);
  EXPECT_GT(turned, 0.5);  // the cam moved: the contact point travelled on both curves
  Eigen::VectorXd y = run.y(), yp = run.yp();
  for (int c = 0; c < yp.size(); ++c) yp(c) += 0.01 * std::cos(2.0 + c);
  Eigen::MatrixXd jac;
  const double diff = testing::checkNewtonMatrix(run.system(), 1.2, y, yp, 19.0, "CVCV", &jac);
  const int nonzeros = testing::expectPatternCovers(run.system(), jac);
  EXPECT_GT(nonzeros, 40);
  int rows = 0;
  for (const auto& eq : run.system().constraints().equations())
    if (eq.cvcv == 0) ++rows;
  EXPECT_EQ(rows, 2);
  std::printf(
      "CVCV free cam over 1.2 s: |E - E0| <= %.2e (E0 = %.4f, cam turned %.2f rad); Newton "
      "matrix largest relative difference %.2e, %d nonzeros covered\n",
      worst, e0, turned, diff, nonzeros);
}

std::vector<std::string> buildErrors(const std::string& body) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      "bad\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2, ZP=1,0,0\n"
      "MATRIX/1, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=0,0,0, 1,0,0, 2,0,0, 3,0,0\n"
      "MATRIX/2, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=0,0,0, 1,0,0, 2,0,1, 3,0,0\n"
      "CURVE/1, OPEN, MATRIX=1, CURVE_POINTS\nCURVE/2, OPEN, MATRIX=2, CURVE_POINTS\n" +
          body + "END\n",
      "bad.adm", ds, d);
  model::Model m;
  model::buildModel(ds, m, d);
  std::vector<std::string> out;
  for (const auto& x : d.all())
    if (x.severity == Severity::Error) out.push_back(format(x));
  return out;
}

TEST(CurveCurve, BadInputIsLocatedAndNamed) {
  int checked = 0;
  auto one = [&](const std::string& body, const std::string& expected) {
    const auto errors = buildErrors(body);
    ASSERT_EQ(errors.size(), 1u) << body;
    EXPECT_NE(errors[0].find(expected), std::string::npos) << errors[0];
    ++checked;
  };
  const std::string ok = "CVCV/5, ICURVE=1, IRM=10, IFLOAT=11, JCURVE=1, JRM=20, JFLOAT=20";
  one(ok + ", IVEL=2\n", "bad.adm:12:67: error: CVCV/5: IVEL (the initial speed along the curve)");
  one("CVCV/5, ICURVE=7, IRM=10, IFLOAT=11, JCURVE=1, JRM=20, JFLOAT=20\n",
      "bad.adm:12:9: error: CVCV/5: CURVE/7 does not exist");
  one("CVCV/5, ICURVE=1, IRM=10, IFLOAT=11, JCURVE=2, JRM=20, JFLOAT=20\n",
      "bad.adm:12:38: error: CVCV/5: CURVE/2 is not planar");
  one("CVCV/5, ICURVE=1, IRM=10, IFLOAT=20, JCURVE=1, JRM=20, JFLOAT=20\n",
      "bad.adm:12:27: error: CVCV/5: IFLOAT=20 is not on the part of IRM");
  one("CVCV/5, ICURVE=1, IRM=10, IFLOAT=11, JCURVE=1, JRM=11, JFLOAT=10\n",
      "bad.adm:12:1: error: CVCV/5: IRM and JRM are on the same part");
  one("CVCV/5, ICURVE=1, IRM=10, IFLOAT=11, JCURVE=1, JRM=21, JFLOAT=20\n",
      "bad.adm:12:1: error: CVCV/5: the x-y planes of IRM and JRM are not one plane");
  EXPECT_EQ(checked, 6);
}

}  // namespace
}  // namespace openmss::analysis
