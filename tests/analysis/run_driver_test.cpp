// The analysis drivers called directly (analysis/*_run.hpp), without command text: a model
// built from a data set, its run state, a typed request, and a report that records in memory
// what the Session would write to the .msg and .req. Checked against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/analysis_context.hpp"
#include "analysis/model_summary.hpp"
#include "analysis/run_state.hpp"
#include "analysis/statics_run.hpp"
#include "analysis/transient_run.hpp"
#include "support/integrator_test_models.hpp"
#include "support/recorded_run.hpp"

namespace openmss {
namespace {

using mechanics::StateLayout;

using testing::load;
using testing::Loaded;
using testing::RecordingReport;

// The spring-damper of tests/support/integrator_test_models.hpp with a displacement request:
// column 3 of REQUEST/1 is the stretch plus the free length, 1 + x(t).
std::string springDamperWithRequest() {
  std::string text = test::kSpringDamper;
  text.insert(text.find("END"), "REQUEST/1, DISPLACEMENT, I=20, J=10\n");
  return text;
}

// x(t) = e^{-t} x0 (cos wd t + sin(wd t) / wd), wd^2 = k/m - (c/2m)^2 = 99, x0 = 0.1.
double springDamperExact(double t) {
  const double wd = std::sqrt(99.0);
  return 0.1 * std::exp(-t) * (std::cos(wd * t) + std::sin(wd * t) / wd);
}

TEST(RunDriver, DynamicAnalysisOfASpringDamperFollowsTheClosedForm) {
  auto l = load(springDamperWithRequest());
  ASSERT_EQ(l->state->degreesOfFreedom, 1);
  l->model.integrator.error = 1e-7;  // the INTEGRATOR setting, set directly
  analysis::TransientRun run;
  run.kind = analysis::TransientKind::Dynamics;
  run.end = 2.0;
  run.outputSteps = 200;
  ASSERT_TRUE(analysis::runTransient(l->context(), run));
  for (const auto& d : l->report.diagnostics) ADD_FAILURE() << format(d);
  // The initial step (t = 0) and one per output interval, each with the one request.
  ASSERT_EQ(l->report.steps.size(), 201u);
  double worst = 0.0;
  for (const auto& s : l->report.steps) {
    ASSERT_EQ(s.rows.size(), 1u);
    worst = std::max(worst, std::abs(s.rows[0][2] - 1.0 - springDamperExact(s.t)));
  }
  std::printf("GSTIFF ERROR=1e-7 through runTransient: worst |z - exact| %.2e over 201 outputs\n",
              worst);
  // GSTIFF at ERROR = 1e-7 keeps the global error of this lightly damped oscillator
  // (amplitude 0.1, about three periods) near ERROR: 1.6e-7 measured; 1e-6 (1e-5 of the
  // amplitude) leaves room for another platform's rounding, while a wrong period, damping or
  // output time would miss by a good fraction of the amplitude.
  EXPECT_LT(worst, 1e-6);
  EXPECT_DOUBLE_EQ(l->state->t, 2.0);
  EXPECT_TRUE(l->state->initialized);
  EXPECT_EQ(l->state->summary.analysis, "dynamic");
  EXPECT_EQ(l->state->summary.outputSteps, 201);
  EXPECT_GT(l->state->summary.steps, 0);
}

// The DAE test-set pendulum (tests/support/integrator_test_models.hpp): the point at t = 1
// against the published reference, and a second request continuing from the run state.
TEST(RunDriver, DynamicAnalysisOfThePendulumReachesTheTestSetPoint) {
  auto l = load(test::kPendulum);
  l->model.integrator.error = 1e-8;
  l->model.integrator.hmax = 0.01;
  analysis::TransientRun first;
  first.kind = analysis::TransientKind::Transient;  // 1 DOF: dynamic
  first.end = 0.5;
  first.outputSteps = 5;
  ASSERT_TRUE(analysis::runTransient(l->context(), first));
  EXPECT_EQ(l->state->summary.analysis, "dynamic");
  analysis::TransientRun second = first;
  second.end = 1.0;
  ASSERT_TRUE(analysis::runTransient(l->context(), second));
  for (const auto& d : l->report.diagnostics) ADD_FAILURE() << format(d);
  const Eigen::VectorXd& y = l->state->y;
  const double dx = y(StateLayout::kR) - test::kPendulumX1;
  const double dy = y(StateLayout::kR + 1) - test::kPendulumY1;
  std::printf("pendulum through two runTransient calls: x(1) error %.2e, y(1) error %.2e\n", dx,
              dy);
  // The model's own offset from the test-set's ideal point mass is -9.2e-7 in y
  // (docs/integrators.md, "The pendulum model's own offset"); 2e-6 leaves room for ERROR.
  EXPECT_LT(std::abs(dx), 2e-6);
  EXPECT_LT(std::abs(dy), 2e-6);
  EXPECT_DOUBLE_EQ(l->state->t, 1.0);
}

// A mass hanging on the spring: the static equilibrium stretches it by m g / k.
TEST(RunDriver, StaticEquilibriumOfAHangingSpringIsMgOverK) {
  std::string text = springDamperWithRequest();
  text.insert(text.find("END"), "ACCGRAV/ KGRAV=-9.81\n");
  auto l = load(text);
  analysis::StaticsRun run;
  ASSERT_TRUE(analysis::runStatics(l->context(), run));
  for (const auto& d : l->report.diagnostics) ADD_FAILURE() << format(d);
  ASSERT_EQ(l->report.steps.size(), 1u);
  const double stretch = l->report.steps[0].rows[0][2] - 1.0;
  // m = 2, k = 200: -0.0981. The equilibrium's ERROR is 1e-4 on positions (its default); the
  // spring is linear, so Newton lands on it to rounding.
  EXPECT_NEAR(stretch, -2.0 * 9.81 / 200.0, 1e-10);
  EXPECT_EQ(l->state->summary.analysis, "static");
}

// A request the model cannot take is refused, located at the request's origin, and the run
// state does not move.
TEST(RunDriver, AKinematicRequestForAModelThatCanMoveIsRefusedAtItsOrigin) {
  auto l = load(test::kSpringDamper);
  analysis::TransientRun run;
  run.kind = analysis::TransientKind::Kinematics;
  run.end = 1.0;
  run.origin = {{"study.acf", 7, 1}, "SIMULATE"};
  EXPECT_FALSE(analysis::runTransient(l->context(), run));
  ASSERT_EQ(l->report.diagnostics.size(), 1u);
  EXPECT_EQ(l->report.diagnostics[0].where.file, "study.acf");
  EXPECT_EQ(l->report.diagnostics[0].where.line, 7);
  EXPECT_NE(l->report.diagnostics[0].message.find("zero degrees of freedom; this one has 1"),
            std::string::npos);
  EXPECT_EQ(l->state->t, 0.0);
  EXPECT_FALSE(l->state->initialized);
  EXPECT_TRUE(l->report.steps.empty());
}

}  // namespace
}  // namespace openmss
