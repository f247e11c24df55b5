// DSTIFF (solvers/ida_integrator.hpp) on problems with closed-form or published answers, written
// directly as DaeProblems so that nothing but the integrator is under test.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solvers/ida_integrator.hpp"

namespace openmss::solvers {
namespace {

// The index-3 pendulum of the DAE test sets in Cartesian coordinates (x, y, u, v, lambda):
// x' = u, y' = v, u' = -lambda x, v' = -lambda y - 1, 0 = x^2 + y^2 - 1. Released at (1, 0)
// with velocity (0, 1). Reference at t = 1 from the test set.
constexpr double kX1 = 0.867348640604551746;
constexpr double kY1 = 0.497701050476373918;

class CartesianPendulum final : public DaeProblem {
 public:
  int size() const override { return 5; }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(5);
    g << yp(0) - y(2), yp(1) - y(3), yp(2) + y(4) * y(0), yp(3) + y(4) * y(1) + 1.0,
        y(0) * y(0) + y(1) * y(1) - 1.0;
  }
  void newtonMatrix(double, const Eigen::VectorXd& y, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac.setZero(5, 5);
    jac(0, 0) = cj, jac(0, 2) = -1.0;
    jac(1, 1) = cj, jac(1, 3) = -1.0;
    jac(2, 2) = cj, jac(2, 0) = y(4), jac(2, 4) = y(0);
    jac(3, 3) = cj, jac(3, 1) = y(4), jac(3, 4) = y(1);
    jac(4, 0) = 2.0 * y(0), jac(4, 1) = 2.0 * y(1);
  }
  bool differential(int i) const override { return i < 4; }
  bool errorControlled(int i) const override { return i < 2; }
  int rowScaleExponent(int i) const override { return i == 4 ? 2 : 0; }
  int unknownScaleExponent(int i) const override { return i == 4 ? 2 : 0; }
  std::string equationName(int row) const override { return "eq" + std::to_string(row); }
  std::string variableName(int i) const override { return "var" + std::to_string(i); }
};

struct PendulumRun {
  double x, y;
  IntegratorStatistics stats;
};

// The same pendulum in the stabilised index-2 form (Gear, Gupta, Leimkuhler): the kinematic
// rows gain -G^T eta (G = (2x, 2y), eta a new multiplier, zero on the solution) and the velocity
// constraint 0 = G (u, v) joins the position constraint. Positions and velocities are under
// error control; both constraint rows and multipliers are index 2 (scale exponent 1).
class CartesianPendulumSi2 final : public DaeProblem {
 public:
  int size() const override { return 6; }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(6);
    g << yp(0) - y(2) + 2.0 * y(0) * y(5), yp(1) - y(3) + 2.0 * y(1) * y(5),
        yp(2) + y(4) * y(0), yp(3) + y(4) * y(1) + 1.0, y(0) * y(0) + y(1) * y(1) - 1.0,
        2.0 * (y(0) * y(2) + y(1) * y(3));
  }
  void newtonMatrix(double, const Eigen::VectorXd& y, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac.setZero(6, 6);
    jac(0, 0) = cj + 2.0 * y(5), jac(0, 2) = -1.0, jac(0, 5) = 2.0 * y(0);
    jac(1, 1) = cj + 2.0 * y(5), jac(1, 3) = -1.0, jac(1, 5) = 2.0 * y(1);
    jac(2, 2) = cj, jac(2, 0) = y(4), jac(2, 4) = y(0);
    jac(3, 3) = cj, jac(3, 1) = y(4), jac(3, 4) = y(1);
    jac(4, 0) = 2.0 * y(0), jac(4, 1) = 2.0 * y(1);
    jac(5, 0) = 2.0 * y(2), jac(5, 1) = 2.0 * y(3), jac(5, 2) = 2.0 * y(0), jac(5, 3) = 2.0 * y(1);
  }
  bool differential(int i) const override { return i < 4; }
  bool errorControlled(int i) const override { return i < 4; }
  int rowScaleExponent(int i) const override { return i >= 4 ? 1 : 0; }
  int unknownScaleExponent(int i) const override { return i >= 4 ? 1 : 0; }
  std::string equationName(int row) const override { return "eq" + std::to_string(row); }
  std::string variableName(int i) const override { return "var" + std::to_string(i); }
};

PendulumRun runPendulumSi2(double error) {
  CartesianPendulumSi2 problem;
  MultistepSettings settings;
  settings.error = error;
  settings.hmax = 0.1;
  IdaIntegrator ida(problem, settings);
  Eigen::VectorXd y0(6), yp0(6);
  y0 << 1.0, 0.0, 0.0, 1.0, 1.0, 0.0;
  yp0 << 0.0, 1.0, -1.0, -1.0, 0.0, 0.0;
  ida.start(0.0, y0, yp0);
  EXPECT_TRUE(ida.advanceTo(1.0)) << ida.failure().reason;
  return {ida.y()(0), ida.y()(1), ida.statistics()};
}

// The criterion: 1e-6 at ERROR = 1e-8, within ERROR at 1e-3 (measured 4.8e-8 and
// 1.2e-4).
TEST(IdaIntegrator, StabilisedIndexTwoPendulumMatchesTheTestSet) {
  for (double error : {1e-3, 1e-8}) {
    const PendulumRun r = runPendulumSi2(error);
    std::printf("DSTIFF SI2 ERROR=%.0e: x error %.2e, y error %.2e, %ld steps, %ld Jacobians\n",
                error, r.x - kX1, r.y - kY1, r.stats.steps, r.stats.jacobianEvaluations);
    EXPECT_NEAR(r.x, kX1, error > 1e-6 ? error : 1e-6);
    EXPECT_NEAR(r.y, kY1, error > 1e-6 ? error : 1e-6);
  }
}


PendulumRun runPendulum(double error) {
  CartesianPendulum problem;
  MultistepSettings settings;
  settings.error = error;
  settings.hmax = 0.1;
  IdaIntegrator ida(problem, settings);
  Eigen::VectorXd y0(5), yp0(5);
  // Consistent start: u' = -lambda x, v' = -lambda y - 1 with lambda = (u^2 + v^2 - y)/1 = 1.
  y0 << 1.0, 0.0, 0.0, 1.0, 1.0;
  yp0 << 0.0, 1.0, -1.0, -1.0, 0.0;
  ida.start(0.0, y0, yp0);
  EXPECT_TRUE(ida.advanceTo(1.0)) << ida.failure().reason;
  EXPECT_DOUBLE_EQ(ida.t(), 1.0);
  return {ida.y()(0), ida.y()(1), ida.statistics()};
}

// IDA on the index-3 form converges, but its accuracy does not follow ERROR: with velocities
// and multipliers outside the error test (as they must be at index 3), the corrector's velocity
// errors feed the positions, and the global error stalls at 1e-6..1e-5 whatever the tolerance
// (measured over tolerance scalings 1, 0.3, 0.1, 0.01 and initial steps 1e-9..1e-6). This is why
// DSTIFF runs on the SI2 form (docs/theory.md, "DSTIFF"). The test records that the I3 run
// completes with that floor, and no better claim.
TEST(IdaIntegrator, IndexThreePendulumRunsWithAnAccuracyFloor) {
  const PendulumRun r = runPendulum(1e-8);
  std::printf("DSTIFF I3 ERROR=1e-8: x error %.2e, y error %.2e, %ld steps, %ld Jacobians\n",
              r.x - kX1, r.y - kY1, r.stats.steps, r.stats.jacobianEvaluations);
  EXPECT_NEAR(r.x, kX1, 1e-4);
  EXPECT_NEAR(r.y, kY1, 1e-4);
}

// y1' = -y1, 0 = y2 - y1^2: y1 = exp(-t), y2 = exp(-2t). IDA's interpolant inside a step of
// order k is accurate to the local error; at ERROR = 1e-9 a midpoint value must agree with the
// closed form as well as the step values do (measured 1.2e-6, the derivative y' being the
// worst); a chord over the h ~ 0.02 steps taken would be off by h^2/8 ~ 5e-5, so 3e-6
// distinguishes the method's polynomial from linear interpolation.
class DecayWithAlgebraic final : public DaeProblem {
 public:
  int size() const override { return 2; }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(2);
    g << yp(0) + y(0), y(1) - y(0) * y(0);
  }
  void newtonMatrix(double, const Eigen::VectorXd& y, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac.resize(2, 2);
    jac << cj + 1.0, 0.0, -2.0 * y(0), 1.0;
  }
  bool differential(int i) const override { return i == 0; }
  bool errorControlled(int i) const override { return i == 0; }
  int rowScaleExponent(int) const override { return 0; }
  int unknownScaleExponent(int) const override { return 0; }
  std::string equationName(int row) const override { return "eq" + std::to_string(row); }
  std::string variableName(int i) const override { return "var" + std::to_string(i); }
};

TEST(IdaIntegrator, InterpolatesInsideAStepToTheClosedForm) {
  DecayWithAlgebraic problem;
  MultistepSettings settings;
  settings.error = 1e-9;
  IdaIntegrator ida(problem, settings);
  Eigen::VectorXd y0(2), yp0(2);
  y0 << 1.0, 1.0;
  yp0 << -1.0, -2.0;
  ida.start(0.0, y0, yp0);
  double worst = 0.0;
  int inside = 0;
  while (ida.t() < 2.0) {
    ASSERT_TRUE(ida.step(2.0)) << ida.failure().reason;
    const double a = ida.previousTime(), b = ida.t();
    ASSERT_LT(a, b);
    for (double f : {0.25, 0.5, 0.75}) {
      const double s = a + f * (b - a);
      Eigen::VectorXd y, yp;
      ida.interpolate(s, y, yp);
      worst = std::max({worst, std::abs(y(0) - std::exp(-s)), std::abs(yp(0) + std::exp(-s))});
      ++inside;
    }
  }
  std::printf("DSTIFF interpolation: %d points, worst error %.2e, %ld steps\n", inside, worst,
              ida.statistics().steps);
  EXPECT_DOUBLE_EQ(ida.t(), 2.0);
  EXPECT_LT(worst, 3e-6);
}

// A residual that turns NaN past t = 0.5 cannot be integrated through: the run fails with a
// typed outcome, the time of failure near 0.5, and names the offending equation.
class BlowsUp final : public DaeProblem {
 public:
  int size() const override { return 2; }
  void residual(double t, const Eigen::VectorXd&, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(2);
    g << yp(0) - 1.0, yp(1) - (t > 0.5 ? std::nan("") : 0.0);
  }
  void newtonMatrix(double, const Eigen::VectorXd&, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac = cj * Eigen::MatrixXd::Identity(2, 2);
  }
  bool differential(int) const override { return true; }
  bool errorControlled(int) const override { return true; }
  int rowScaleExponent(int) const override { return 0; }
  int unknownScaleExponent(int) const override { return 0; }
  std::string equationName(int row) const override { return "eq" + std::to_string(row); }
  std::string variableName(int i) const override { return "var" + std::to_string(i); }
};

TEST(IdaIntegrator, FailureIsTypedAndNamesTheEquation) {
  BlowsUp problem;
  IdaIntegrator ida(problem, MultistepSettings{});
  Eigen::VectorXd y0 = Eigen::VectorXd::Zero(2), yp0(2);
  yp0 << 1.0, 0.0;
  ida.start(0.0, y0, yp0);
  EXPECT_FALSE(ida.advanceTo(1.0));
  EXPECT_EQ(ida.outcome(), IdaOutcome::ResidualFailed);
  EXPECT_EQ(ida.failure().worstEquation, 1);
  EXPECT_NEAR(ida.failure().time, 0.5, 0.05);
  EXPECT_LE(ida.t(), 0.5);
}

}  // namespace
}  // namespace openmss::solvers
