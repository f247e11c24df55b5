// Expression run state (docs/theory.md §11a) end to end: cumulative AZ in a REQUEST, a VARIABLE
// and an SFORCE against closed forms past pi, 3 pi, ...; the Newton matrix of a force reading
// a cumulative angle against central differences; a run repeated gives a bit-identical .req;
// and a delayed-feedback DIFF x' = -x(t - 1) against the method of steps.

#include "mechanics/expression_run_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "mechanics/multibody_system.hpp"
#include "output/request_file_reader.hpp"
#include "support/bdf_run.hpp"
#include "support/cli_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;  // scratch, run, slurp, write

// PART/2 turns about ground z at 3 rad/s (MOTION), so AZ(20, 10) = 3t unwrapped. PART/3 (mass 2)
// slides along z pushed by SFORCE = AZ(20, 10): 2 z'' = 3t, z = t^3 / 4.
const char* kSpinner =
    "spinner\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1, 1, 1\nMARKER/20, PART=2\n"
    "JOINT/1, REVOLUTE, I=20, J=10\nMOTION/1, JOINT=1, ROTATION, FUNCTION=3*TIME\n"
    "PART/3, MASS=2, CM=30, IP=1, 1, 1\nMARKER/30, PART=3\n"
    "JOINT/2, TRANSLATIONAL, I=30, J=11\n"
    "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=30, J=11, FUNCTION=AZ(20, 10)\n"
    "VARIABLE/1, FUNCTION=AZ(20, 10)\n"
    "REQUEST/1, F2=AZ(20, 10), F3=VARVAL(1), F4=DZ(30, 11)\n"
    "OUTPUT/REQSAVE\nEND\n";

// 4 s at 3 rad/s is 12 rad: AZ passes pi, 3 pi (9.42). Tolerances are the .req's 6 digits
// (1e-5 relative) plus the integration error of z at ERROR = 1e-8 (below 1e-6).
TEST(ExpressionRunState, CumulativeAzGrowsLinearlyPastPiInRequestVariableAndForce) {
  const fs::path dir = scratch("spinner");
  write(dir / "s.adm", kSpinner);
  write(dir / "s.acf",
        "s\ns\nintegrator/gstiff, error=1e-8\nsimulate/dynamics, end=4, steps=40\nstop\n");
  const Result r = run("run s.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "s.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = openmss::output::lastStepPerTime(req->steps);
  ASSERT_EQ(steps.size(), 41u);
  double largest = 0.0;
  for (const auto& step : steps) {
    const double t = step.time;
    const auto& row = step.rows[0];  // F2 F3 F4 F6 F7 F8
    EXPECT_NEAR(row[0], 3.0 * t, 1e-5 * 3.0 * t + 1e-9) << "AZ at t=" << t;
    EXPECT_NEAR(row[1], 3.0 * t, 1e-5 * 3.0 * t + 1e-9) << "VARVAL at t=" << t;
    EXPECT_NEAR(row[2], t * t * t / 4.0, 1e-5 * t * t * t / 4.0 + 1e-6) << "DZ at t=" << t;
    largest = std::max(largest, row[0]);
  }
  EXPECT_GT(largest, 3.0 * std::numbers::pi);

  // The same input again: a bit-identical request file.
  const fs::path again = scratch("spinner2");
  write(again / "s.adm", kSpinner);
  write(again / "s.acf", slurp(dir / "s.acf"));
  ASSERT_EQ(run("run s.acf --quiet", again).status, 0);
  EXPECT_EQ(slurp(dir / "s.req"), slurp(again / "s.req"));
  fs::remove_all(dir);
  fs::remove_all(again);
}

// A state of PART/2 turned by `angle` about z.
Eigen::VectorXd turned(const openmss::mechanics::MultibodySystem& s, double angle) {
  Eigen::VectorXd y = s.initialState();
  const int o = s.layout().body(0) + openmss::mechanics::StateLayout::kE;
  y(o) = std::cos(angle / 2);
  y(o + 1) = 0.0;
  y(o + 2) = 0.0;
  y(o + 3) = std::sin(angle / 2);
  return y;
}

// After an accepted state at 2.9 rad, PART/2 at 3.3 rad (principal value -2.98) reads 3.3, and
// the Newton matrix of the SFORCE and VARIABLE rows matches central differences (the turns
// counted are constant near the state, so the derivative is the principal angle's).
TEST(ExpressionRunState, CumulativeAngleValueAndNewtonMatrix) {
  const openmss::model::Model m = openmss::test::buildModelFromText(kSpinner, "s.adm");
  openmss::mechanics::MultibodySystem s(m);
  openmss::mechanics::ExpressionRunState run(m);
  EXPECT_EQ(run.angleCount(), 1u);  // one distinct AZ(20, 10) in three functions
  s.setRunState(&run);
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(s.layout().size());
  run.accept(s, 0.0, turned(s, 2.9), yp);
  const Eigen::VectorXd y = turned(s, 3.3);
  const openmss::model::Measure& az = m.variables[0].function.measures[0];
  double value = 0.0;
  openmss::mechanics::kinematicMeasure(m, s.layout(), az, y.data(), &value, &run);
  EXPECT_NEAR(value, 3.3, 1e-12);
  openmss::mechanics::kinematicMeasure(m, s.layout(), az, y.data(), &value);
  EXPECT_NEAR(value, 3.3 - 2 * std::numbers::pi, 1e-12);  // no run state: principal
  EXPECT_LT(checkNewtonMatrix(s, 0.0, y, yp, 10.0, "cumulative AZ"), 1e-6);
  // A rejected step or corrector iteration cannot change it: only accept() does.
  run.reset();
  openmss::mechanics::kinematicMeasure(m, s.layout(), az, y.data(), &value, &run);
  EXPECT_NEAR(value, 3.3 - 2 * std::numbers::pi, 1e-12);
}

// x' = -x(t - 1), x = 1 for t <= 0, by the method of steps: on [k, k + 1], with u = t - k,
// p_k(u) = p_{k-1}(1) - integral_0^u p_{k-1}, p_{-1} = 1 (polynomial coefficients in u).
double methodOfSteps(double t) {
  std::vector<double> p{1.0};
  const int segments = static_cast<int>(std::floor(t)) + 1;
  for (int k = 0; k < segments; ++k) {
    double atOne = 0.0;
    for (double c : p) atOne += c;
    std::vector<double> next(p.size() + 1, 0.0);
    next[0] = atOne;
    for (std::size_t j = 0; j < p.size(); ++j) next[j + 1] = -p[j] / static_cast<double>(j + 1);
    p = next;
  }
  const double u = t - std::floor(t);
  double value = 0.0;
  for (std::size_t j = p.size(); j-- > 0;) value = value * u + p[j];
  return value;
}

// Tolerance 5e-5 for x: its second derivative jumps by 1 at t = 1 (the third at t = 2), and
// neither the integrator nor the history's cubic stencil locates that corner (ADAMS refines
// at corners; OpenMSS does not yet), so the error there is O(h^2) of the local steps: 2e-5
// observed at t = 2. The delayed sine is smooth: the 6 printed digits plus O(h^4), 2e-6.
TEST(ExpressionRunState, DelayedFeedbackMatchesTheMethodOfSteps) {
  EXPECT_NEAR(methodOfSteps(0.5), 0.5, 1e-15);
  EXPECT_NEAR(methodOfSteps(1.5), -0.375, 1e-15);  // p_1(u) = -u + u^2 / 2
  const fs::path dir = scratch("dde");
  write(dir / "d.adm",
        "dde\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "DIFF/1, FUNCTION=-DELAY(DIF(1), 1, 1), IC=1\n"
        "REQUEST/1, F2=DIF(1), F3=DELAY(SIN(TIME), 0.5, 0)\nOUTPUT/REQSAVE\nEND\n");
  write(dir / "d.acf",
        "d\nd\nintegrator/gstiff, error=1e-8\nsimulate/transient, end=4, steps=40\nstop\n");
  const Result r = run("run d.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "d.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = openmss::output::lastStepPerTime(req->steps);
  ASSERT_EQ(steps.size(), 41u);
  for (const auto& step : steps) {
    const double t = step.time;
    EXPECT_NEAR(step.rows[0][0], methodOfSteps(t), 5e-5) << "x at t=" << t;
    EXPECT_NEAR(step.rows[0][1], t < 0.5 ? 0.0 : std::sin(t - 0.5), 2e-6) << "t=" << t;
  }
  fs::remove_all(dir);
}

}  // namespace
