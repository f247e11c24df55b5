// The BDF integrator through the common Integrator interface, on the undamped oscillator
// x'' = -x written as a first-order DAE (x' = v, v' = -x): step(), advanceTo() and the
// interpolant inside a step against the closed form x = cos t, v = -sin t.
#include "solvers/bdf_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace openmss::solvers {
namespace {

class Oscillator : public DaeProblem {
 public:
  int size() const override { return 2; }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(2);
    g(0) = yp(0) - y(1);
    g(1) = yp(1) + y(0);
  }
  void newtonMatrix(double, const Eigen::VectorXd&, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac.resize(2, 2);
    jac << cj, -1.0, 1.0, cj;
  }
  bool differential(int) const override { return true; }
  bool errorControlled(int) const override { return true; }
  int rowScaleExponent(int) const override { return 0; }
  int unknownScaleExponent(int) const override { return 0; }
  std::string equationName(int row) const override { return "row " + std::to_string(row); }
  std::string variableName(int i) const override { return "y" + std::to_string(i); }
};

TEST(BdfIntegrator, StepsNeverPassTheOutputTimeAndLandOnIt) {
  Oscillator problem;
  MultistepSettings settings;
  settings.error = 1e-8;
  settings.hinit = 1e-4;
  BdfIntegrator bdf(problem, settings);
  Integrator& integrator = bdf;
  integrator.start(0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -1.0));
  int steps = 0;
  while (integrator.t() < 0.5) {
    const double before = integrator.t();
    ASSERT_TRUE(integrator.step(0.5));
    EXPECT_GT(integrator.t(), before);
    EXPECT_LE(integrator.t(), 0.5);
    EXPECT_EQ(integrator.previousTime(), before);
    ++steps;
  }
  EXPECT_EQ(integrator.t(), 0.5);
  EXPECT_EQ(integrator.statistics().steps, steps);
}

// The oscillator at ERROR 1e-9, HINIT 1e-4, HMAX 0.05: steps short enough for the
// interpolation tests below to look inside a step of a mature (higher-order) history.
MultistepSettings fineSettings() {
  MultistepSettings settings;
  settings.error = 1e-9;
  settings.hinit = 1e-4;
  settings.hmax = 0.05;
  return settings;
}

TEST(BdfIntegrator, InterpolantInsideAStepMatchesTheClosedForm) {
  Oscillator problem;
  BdfIntegrator bdf(problem, fineSettings());
  bdf.start(0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -1.0));
  ASSERT_TRUE(bdf.advanceTo(2.0));
  ASSERT_TRUE(bdf.step(3.0));  // one more step; interpolate inside it
  const double a = bdf.previousTime(), b = bdf.t();
  ASSERT_LT(a, b);
  Eigen::VectorXd y, yp;
  for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double s = a + f * (b - a);
    bdf.interpolate(s, y, yp);
    // Tolerance: the step's own accuracy (ERROR 1e-9 per step, a few hundred steps so far)
    // plus the interpolant's error of the same order; 1e-6 leaves a wide margin.
    EXPECT_NEAR(y(0), std::cos(s), 1e-6) << "at " << s;
    EXPECT_NEAR(y(1), -std::sin(s), 1e-6) << "at " << s;
    EXPECT_NEAR(yp(0), -std::sin(s), 1e-5) << "at " << s;
    EXPECT_NEAR(yp(1), -std::cos(s), 1e-5) << "at " << s;
  }
  bdf.interpolate(b, y, yp);
  EXPECT_EQ(y, bdf.y());  // the end of the step is the accepted solution itself
}

// interpolateComponents (the contact locator's per-contact bisection, docs/theory.md §6c
// "Events") against interpolate: the listed entry to the bit, the others left as they were, on
// the first step from a start (the order-1 path), inside a later step and at its two ends.
TEST(BdfIntegrator, InterpolateComponentsIsInterpolateToTheBit) {
  Oscillator problem;
  BdfIntegrator bdf(problem, fineSettings());
  bdf.start(0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -1.0));
  Eigen::VectorXd y, yp, part;
  int compared = 0;
  for (const double until : {0.0, 2.0}) {
    if (until > 0.0) {
      ASSERT_TRUE(bdf.advanceTo(until));
    }
    ASSERT_TRUE(bdf.step(3.0));
    const double a = bdf.previousTime(), b = bdf.t();
    for (double f : {0.0, 0.3, 0.5, 0.9, 1.0}) {
      const double s = a + f * (b - a);
      bdf.interpolate(s, y, yp);
      part = Eigen::Vector2d(7.0, 7.0);  // sentinels: entry 0 must stay as it is
      bdf.interpolateComponents(s, {1}, part);
      EXPECT_EQ(part(0), 7.0) << "at " << s;
      EXPECT_EQ(part(1), y(1)) << "at " << s;  // exact equality: the same operations
      ++compared;
    }
  }
  EXPECT_EQ(compared, 10);
}

}  // namespace
}  // namespace openmss::solvers
