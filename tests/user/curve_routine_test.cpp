// CURSUB (CURVE with FUNCTION=USER) from user libraries in both calling styles
// (tests/user/explicit_routines.c and .f): an exact circle over MINPAR = 0 .. MAXPAR = 2 pi.
//   (a) CURVE() and GTCURV values and derivatives against the closed form;
//   (b) a bead on the circle (PTCV) is a pendulum: its angle against RK4, its radius exact;
//   (c) bad input and bad user code: located errors, and NaN stops the run naming the routine.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

#include "support/bdf_run.hpp"
#include "support/cli_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss {
namespace {

using L = mechanics::StateLayout;
const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;
const double kRadius = 0.8, kGravity = 9.81, kStart = std::numbers::pi / 3.0;

std::string userCircle(const std::string& library, const std::string& name = "",
                       const std::string& extra = "") {
  return "CURVE/1, CLOSED, MINPAR=0, MAXPAR=6.283185307179586, FUNCTION=USER(0.8" + extra +
         "), ROUTINE=\"" + library + "::" + name + "\"\n";
}

std::string beadOnCircle(const std::string& curve, const std::string& more = "") {
  std::ostringstream s;
  s.precision(17);
  s << "bead on a circular wire\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
       "MARKER/11, PART=1, FLOATING\nPART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3, QG="
    << kRadius * std::sin(kStart) << "," << -kRadius * std::cos(kStart) << ",0\n"
    << "MARKER/20, PART=2\n"
    << curve << "PTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\nACCGRAV/ JGRAV=-9.81\n"
    << "VARIABLE/1, FUNCTION=CURVE(TIME, 0, 1, 1)\nVARIABLE/2, FUNCTION=CURVE(TIME, 1, 2, 1)\n"
    << "VARIABLE/3, FUNCTION=CURVE(TIME, 2, 1, 1)\n"
    << more << "END\n";
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

// CURVE(alpha, iord, comp, id) reads the routine: exactly the closed form (the same operations),
// inside and outside MINPAR..MAXPAR (the CLOSED curve repeats with period 2 pi: 1e-14).
TEST(CurveRoutine, CurveFunctionIsTheClosedForm) {
  int compared = 0;
  for (const std::string& lib : {kC, kF77}) {
    const model::Model m = test::buildModelFromText(beadOnCircle(userCircle(lib)), "c.adm");
    ASSERT_EQ(m.variables.size(), 3u);
    for (double a : {0.0, 0.4, 2.5, 6.0, 7.1, -0.7}) {
      EXPECT_NEAR(m.variables[0].function.expression.evaluate(nullptr, a), kRadius * std::sin(a),
                  1e-14);
      EXPECT_NEAR(m.variables[1].function.expression.evaluate(nullptr, a), kRadius * std::sin(a),
                  1e-14);  // d/da of -R cos a
      EXPECT_NEAR(m.variables[2].function.expression.evaluate(nullptr, a), -kRadius * std::sin(a),
                  1e-14);
      compared += 3;
    }
  }
  EXPECT_EQ(compared, 36);
}

// The bead on an exact circle: only the integrator's error (ERROR = 1e-9) separates it from the
// pendulum (measured below 1e-7 rad over 2 s; asserted at 1e-6), and the constraint holds the
// radius to the corrector's tolerance (asserted at 1e-9 R).
TEST(CurveRoutine, BeadOnACursubCircleIsAPendulum) {
  for (const std::string& lib : {kC, kF77}) {
    const model::Model m = test::buildModelFromText(beadOnCircle(userCircle(lib)), "bead.adm");
    ASSERT_EQ(m.ptcvs.size(), 1u);
    test::BdfRun run(m, 1e-9, 0.005, true);
    run.start();
    double worstAngle = 0.0, worstRadius = 0.0;
    int compared = 0;
    for (double t = 0.1; t <= 2.0 + 1e-9; t += 0.1) {
      run.advanceTo(t);
      const double x = run.body(0, L::kR), y = run.body(0, L::kR + 1);
      worstAngle = std::max(worstAngle, std::abs(std::atan2(x, -y) - pendulumAngle(t)));
      worstRadius = std::max(worstRadius, std::abs(std::hypot(x, y) - kRadius));
      ++compared;
    }
    EXPECT_EQ(compared, 20);
    EXPECT_LE(worstAngle, 1e-6) << lib;
    EXPECT_LE(worstRadius, 1e-9 * kRadius) << lib;
    std::printf("bead on a CURSUB circle over 2 s: |theta - RK4| <= %.2e rad, |r - R| <= %.2e\n",
                worstAngle, worstRadius);
  }
}

// The PTCV rows on the CURSUB circle (their third derivative in alpha differenced from IORD 2)
// against central differences of the residual: measured 3.4e-10 relative, asserted at 1e-6 by
// the check.
TEST(CurveRoutine, NewtonMatrixOfAPtcvOnACursubCurveMatchesCentralDifferences) {
  int checked = 0;
  for (const std::string& lib : {kC, kF77}) {
    const model::Model m = test::buildModelFromText(beadOnCircle(userCircle(lib)), "bead.adm");
    const mechanics::MultibodySystem s(m);
    Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
    for (int i = 0; i < y.size(); ++i) yp(i) = 0.2 * std::cos(0.9 * i);
    for (double cj : {0.0, 25.0}) {
      const double worst = testing::checkNewtonMatrix(s, 0.3, y, yp, cj, lib);
      std::printf("PTCV on CURSUB, Newton matrix (cj = %g): largest relative difference %.2e\n", cj,
                  worst);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4);
}

TEST(CurveRoutine, BadStatementsAreLocatedErrors) {
  std::string all;
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      beadOnCircle("MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=3, VALUES=0,0,0,1,1,1\n"
                   "CURVE/1, MATRIX=1, MINPAR=1, MAXPAR=0, FUNCTION=USER(1), ROUTINE=\"" +
                   kC + "::No_cur\"\n"),
      "c.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d) && !d.hasErrors());
  for (const auto& x : d.all()) all += format(x) + "\n";
  EXPECT_NE(all.find("MATRIX with FUNCTION=USER(...): CURSUB gives the whole curve"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("CURVE/1: MAXPAR must be greater than MINPAR"), std::string::npos) << all;
}

// NaN from CURSUB stops the run naming the routine, the curve and alpha (the shared mechanism
// of docs/user-subroutines.md, "Bad user code"). PTCV's search for the starting point samples
// the whole range, so this routine stops the run before the first step: a failed run (nonzero
// status) whose message names the routine.
TEST(CurveRoutine, NanFromCursubStopsTheRun) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::scratch("bad-cursub");
  testing::write(dir / "b.adm", beadOnCircle(userCircle(kC, "Nan_cur", ", 1.4"),
                                             "REQUEST/1, F2=DX(20,10)\nOUTPUT/REQSAVE\n"));
  const testing::Result r = testing::run("run b.adm --end 2 --dtout 0.05", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("CURSUB (Nan_cur) of CURVE/1 stopped the run at ALPHA = "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("not a finite number"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace openmss
