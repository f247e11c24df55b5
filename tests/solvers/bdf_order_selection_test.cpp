// Order and step selection of the BDF integrator (GSTIFF and WSTIFF) on undamped oscillators
// whose frequencies spread over decades, the situation of the benchmark chains: BDF orders 3-6
// are not A-stable and their stability regions miss a band along the imaginary axis
// (docs/integrators.md, "Order selection"). Truth: the closed form of the linear system through
// its eigen decomposition.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "solvers/bdf_integrator.hpp"

namespace openmss::solvers {
namespace {

// x'' + K x = 0 with K = Q diag(w^2) Q^T, written as the first-order system x' = v,
// v' = -K x. Only positions are under error control, as the index-3 multibody form has it.
class SpringModes : public DaeProblem {
 public:
  SpringModes(const Eigen::VectorXd& omega, const Eigen::MatrixXd& q) : omega_(omega), q_(q) {
    stiffness_ = q * omega.array().square().matrix().asDiagonal() * q.transpose();
  }
  int size() const override { return 2 * modes(); }
  int modes() const { return static_cast<int>(omega_.size()); }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    const int m = modes();
    g.resize(2 * m);
    g.head(m) = yp.head(m) - y.tail(m);
    g.tail(m) = yp.tail(m) + stiffness_ * y.head(m);
  }
  void newtonMatrix(double, const Eigen::VectorXd&, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    const int m = modes();
    jac.setZero(2 * m, 2 * m);
    jac.topLeftCorner(m, m).diagonal().setConstant(cj);
    jac.topRightCorner(m, m).diagonal().setConstant(-1.0);
    jac.bottomLeftCorner(m, m) = stiffness_;
    jac.bottomRightCorner(m, m).diagonal().setConstant(cj);
  }
  bool differential(int) const override { return true; }
  bool errorControlled(int i) const override { return i < modes(); }
  int rowScaleExponent(int) const override { return 0; }
  int unknownScaleExponent(int) const override { return 0; }
  std::string equationName(int row) const override { return "row " + std::to_string(row); }
  std::string variableName(int i) const override { return "y" + std::to_string(i); }

  // Positions and velocities at t from modal amplitudes a (x = Q (a cos wt)).
  Eigen::VectorXd exact(double t, const Eigen::VectorXd& a) const {
    const int m = modes();
    Eigen::VectorXd y(2 * m);
    const Eigen::ArrayXd wt = omega_.array() * t;
    y.head(m) = q_ * (a.array() * wt.cos()).matrix();
    y.tail(m) = q_ * (-a.array() * omega_.array() * wt.sin()).matrix();
    return y;
  }

 private:
  Eigen::VectorXd omega_;
  Eigen::MatrixXd q_, stiffness_;
};

struct RunResult {
  bool ok = false;
  IntegratorStatistics stats;
  double positionError = 0.0;  // largest position error against the closed form at the ends
};

// Frequencies 1, 4, 40 and 400 rad/s; the fast modes start with small amplitudes, as the
// high modes of a released chain. Q: a fixed rotation that couples every mode to every mass.
RunResult runModes(double error, bool fixedCoefficients, double end, int kmax = 6) {
  Eigen::VectorXd omega(4), a(4);
  omega << 1.0, 4.0, 40.0, 400.0;
  a << 1.0, 0.3, 1e-3, 1e-5;
  const Eigen::MatrixXd q =
      Eigen::HouseholderQR<
          Eigen::MatrixXd>(Eigen::MatrixXd::NullaryExpr(4, 4, [](Eigen::Index i, Eigen::Index j) {
        return std::cos(1.0 + 3.0 * static_cast<double>(i) + 7.0 * static_cast<double>(j * j));
      })).householderQ();
  SpringModes problem(omega, q);
  MultistepSettings settings;
  settings.error = error;
  settings.hinit = 1e-4;
  settings.fixedCoefficients = fixedCoefficients;
  settings.kmax = kmax;
  BdfIntegrator bdf(problem, settings);
  const Eigen::VectorXd y0 = problem.exact(0.0, a);
  Eigen::VectorXd yp0(y0.size());
  Eigen::VectorXd g;
  // yp0 from the equations: x' = v, v' = -K x.
  problem.residual(0.0, y0, Eigen::VectorXd::Zero(y0.size()), g);
  yp0 = -g;
  bdf.start(0.0, y0, yp0);
  RunResult r;
  const int m = problem.modes();
  for (int out = 1; out <= 10; ++out) {
    const double t = end * out / 10.0;
    if (!bdf.advanceTo(t)) return r;
    const Eigen::VectorXd e = bdf.y() - problem.exact(t, a);
    r.positionError = std::max(r.positionError, e.head(m).cwiseAbs().maxCoeff());
  }
  r.ok = true;
  r.stats = bdf.statistics();
  return r;
}

// Before the stability-limit detection (the order chosen from the k-1, k, k+1 estimates alone)
// GSTIFF took 4149 steps at ERROR = 1e-3 and 9525 at 1e-4 over these 20 s, more than at 1e-6
// (at 1e-4: orders 3-6 throughout, 1556 rejected steps, 2525 Jacobians): the 40 and 400 rad/s
// modes, left below the tolerance by the error test, grew at orders 3-4 until they held the
// step (WSTIFF at 1e-4: 4069 steps, 1032 Jacobians). With the detection, when written: 235 and
// 1277 steps (WSTIFF 1662 steps, 470 Jacobians at 1e-4). On 2026-11-29 the step control had
// moved on to GSTIFF 290 and 1832 steps (555 Jacobians at 1e-4), WSTIFF at 1e-4 1843 steps,
// 605 Jacobians; since a matrix formed for a rejected attempt counts as an older one
// (docs/integrators.md, "Crossing a flat passage at tight tolerances") GSTIFF 1652 steps, 508
// Jacobians and WSTIFF 2101 steps, 774 Jacobians at 1e-4: the spread of the step sequence on
// this model (the next test's eight runs take 6 % fewer Jacobians in all). The bounds leave room
// for such changes and still fail the old rule at 1e-4 for both methods and at 1e-3 for GSTIFF.
TEST(BdfOrderSelection, LooseToleranceIsNotHeldByAnUnstableOrder) {
  for (bool fixed : {true, false}) {
    const RunResult loose = runModes(1e-3, fixed, 20.0);
    const RunResult medium = runModes(1e-4, fixed, 20.0);
    ASSERT_TRUE(loose.ok && medium.ok);
    EXPECT_LT(loose.stats.steps, 1000) << (fixed ? "GSTIFF" : "WSTIFF");
    EXPECT_LT(medium.stats.steps, 2500) << (fixed ? "GSTIFF" : "WSTIFF");
    EXPECT_LT(loose.stats.jacobianEvaluations, 300) << (fixed ? "GSTIFF" : "WSTIFF");
    EXPECT_LT(medium.stats.jacobianEvaluations, 900) << (fixed ? "GSTIFF" : "WSTIFF");
  }
}

// Against the closed form the error falls with ERROR. It is the global error of a 20 s run with
// 3 periods of the slowest mode, so it lies above ERROR (the local tolerance); what the test
// pins is that a looser tolerance never buys a better answer (before the detection 1e-3 gave
// 0.71, worse than 1e-4's 0.090). The factor 1.5 allows for the ratio of neighbouring
// tolerances to vary, while 1e-3 -> 1e-6 must gain a factor of 20.
TEST(BdfOrderSelection, ErrorAgainstTheClosedFormFallsWithTheTolerance) {
  for (bool fixed : {true, false}) {
    double previous = std::numeric_limits<double>::infinity(), first = 0.0;
    for (double error : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const RunResult r = runModes(error, fixed, 20.0);
      ASSERT_TRUE(r.ok) << error;
      std::printf(
          "%s ERROR %g: steps %ld, rejected %ld, Jacobians %ld, residuals %ld, error %.3e\n",
          fixed ? "GSTIFF" : "WSTIFF", error, r.stats.steps, r.stats.rejectedSteps,
          r.stats.jacobianEvaluations, r.stats.residualEvaluations, r.positionError);
      EXPECT_LT(r.positionError, 1.5 * previous) << error;
      EXPECT_LT(r.positionError, 0.5) << error;
      if (error == 1e-3) first = r.positionError;
      if (error == 1e-6) {
        EXPECT_LT(r.positionError, first / 20.0);
      }
      previous = r.positionError;
    }
  }
}

// The detection fires on the oscillators at loose tolerances and leaves a smooth, non-oscillatory
// problem alone (x' = -x: no undamped mode, orders 3-6 stay available).
TEST(BdfOrderSelection, DetectionFiresOnlyOnUndampedModes) {
  Eigen::VectorXd omega(4), a(4);
  omega << 1.0, 4.0, 40.0, 400.0;
  a << 1.0, 0.3, 1e-3, 1e-5;
  SpringModes modes(omega, Eigen::MatrixXd::Identity(4, 4));
  MultistepSettings settings;
  settings.error = 1e-4;
  settings.hinit = 1e-4;
  settings.fixedCoefficients = true;
  {
    BdfIntegrator bdf(modes, settings);
    const Eigen::VectorXd y0 = modes.exact(0.0, a);
    Eigen::VectorXd g;
    modes.residual(0.0, y0, Eigen::VectorXd::Zero(y0.size()), g);
    bdf.start(0.0, y0, -g);
    ASSERT_TRUE(bdf.advanceTo(20.0));
    EXPECT_GT(bdf.stabilityLimitDetections(), 0);
  }
  // x'' = -x x' damped hard enough to have no oscillation: x' = v, v' = -4 v - x (real
  // eigenvalues -0.27 and -3.7).
  class Damped : public DaeProblem {
   public:
    int size() const override { return 2; }
    void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                  Eigen::VectorXd& g) override {
      g.resize(2);
      g << yp(0) - y(1), yp(1) + 4.0 * y(1) + y(0);
    }
    void newtonMatrix(double, const Eigen::VectorXd&, const Eigen::VectorXd&, double cj,
                      Eigen::MatrixXd& jac) override {
      jac.resize(2, 2);
      jac << cj, -1.0, 1.0, cj + 4.0;
    }
    bool differential(int) const override { return true; }
    bool errorControlled(int) const override { return true; }
    int rowScaleExponent(int) const override { return 0; }
    int unknownScaleExponent(int) const override { return 0; }
    std::string equationName(int row) const override { return "row " + std::to_string(row); }
    std::string variableName(int i) const override { return "y" + std::to_string(i); }
  } damped;
  BdfIntegrator bdf(damped, settings);
  bdf.start(0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -1.0));
  ASSERT_TRUE(bdf.advanceTo(5.0));
  EXPECT_EQ(bdf.stabilityLimitDetections(), 0);
}

}  // namespace
}  // namespace openmss::solvers
