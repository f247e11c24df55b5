// DSTIFF (SUNDIALS IDA on the index-3 equations) and ABAM (coordinate partitioning + CVODE's
// Adams method) on mechanisms with independent answers: the index-3 pendulum of the DAE test
// sets, a mass on a spring-damper (closed form), energy conservation of the pendulum, and the
// stiffness warning of ABAM on a spring of k/m = 1e8.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "analysis/abam_integrator.hpp"
#include "analysis/multibody_dae.hpp"
#include "analysis/multibody_dae_si2.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "support/integrator_test_models.hpp"
#include "solvers/ida_integrator.hpp"

namespace openmss::analysis {
namespace {

using test::assemble;
using test::Mechanism;
using test::kPendulum;
using test::kSpringDamper;
using test::kStiffSpring;
constexpr double kX1 = test::kPendulumX1;
constexpr double kY1 = test::kPendulumY1;

using mechanics::StateLayout;

solvers::MultistepSettings settingsFor(double error, double hmax) {
  solvers::MultistepSettings s;
  s.error = error;
  s.hmax = hmax;
  s.hinit = 1e-4;
  return s;
}

struct PendulumResult {
  double x, y;
  solvers::IntegratorStatistics stats;
};

PendulumResult pendulumWith(solvers::Integrator& integrator, const Mechanism& m) {
  integrator.start(0.0, m.y, m.yp);
  EXPECT_TRUE(integrator.advanceTo(1.0)) << integrator.failure().reason;
  EXPECT_DOUBLE_EQ(integrator.t(), 1.0);
  // The CM of the point mass is the marker at the rod's end.
  return {integrator.y()(StateLayout::kR), integrator.y()(StateLayout::kR + 1),
          integrator.statistics()};
}

// DSTIFF runs on the SI2 form (docs/theory.md, "DSTIFF"): the I3 state plus one zero
// multiplier eta per constraint.
PendulumResult dstiffPendulum(double error) {
  auto m = assemble(kPendulum);
  MultibodyDaeSi2 dae(*m->system);
  const Eigen::Index n = m->y.size(), n2 = dae.size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n2), yp = Eigen::VectorXd::Zero(n2);
  y.head(n) = m->y;
  yp.head(n) = m->yp;
  solvers::IdaIntegrator ida(dae, settingsFor(error, 0.1));
  ida.start(0.0, y, yp);
  EXPECT_TRUE(ida.advanceTo(1.0)) << ida.failure().reason;
  EXPECT_DOUBLE_EQ(ida.t(), 1.0);
  return {ida.y()(StateLayout::kR), ida.y()(StateLayout::kR + 1), ida.statistics()};
}

PendulumResult abamPendulum(double error) {
  auto m = assemble(kPendulum);
  AbamIntegrator abam(*m->system, settingsFor(error, 0.1));
  const PendulumResult r = pendulumWith(abam, *m);
  EXPECT_FALSE(abam.stiffnessDetected()) << abam.warnings().front();
  EXPECT_EQ(abam.partitioning().degreesOfFreedom(), 1);
  return r;
}

TEST(Dstiff, PendulumMatchesTheTestSetAtTightTolerance) {
  const PendulumResult r = dstiffPendulum(1e-8);
  std::printf("DSTIFF ERROR=1e-8: x(1) error %.2e, y(1) error %.2e, %ld steps, %ld Jacobians\n",
              r.x - kX1, r.y - kY1, r.stats.steps, r.stats.jacobianEvaluations);
  EXPECT_NEAR(r.x, kX1, 1e-6);
  EXPECT_NEAR(r.y, kY1, 1e-6);
}

TEST(Dstiff, PendulumWithinTheRequestedErrorAtLooseTolerance) {
  const PendulumResult r = dstiffPendulum(1e-3);
  std::printf("DSTIFF ERROR=1e-3: x(1) error %.2e, y(1) error %.2e, %ld steps\n", r.x - kX1,
              r.y - kY1, r.stats.steps);
  EXPECT_NEAR(r.x, kX1, 1e-3);
  EXPECT_NEAR(r.y, kY1, 1e-3);
}

TEST(Abam, PendulumMatchesTheTestSetAtTightTolerance) {
  const PendulumResult r = abamPendulum(1e-8);
  std::printf("ABAM ERROR=1e-8: x(1) error %.2e, y(1) error %.2e, %ld steps\n", r.x - kX1,
              r.y - kY1, r.stats.steps);
  EXPECT_NEAR(r.x, kX1, 1e-6);
  EXPECT_NEAR(r.y, kY1, 1e-6);
}

TEST(Abam, PendulumWithinTheRequestedErrorAtLooseTolerance) {
  const PendulumResult r = abamPendulum(1e-3);
  std::printf("ABAM ERROR=1e-3: x(1) error %.2e, y(1) error %.2e, %ld steps\n", r.x - kX1,
              r.y - kY1, r.stats.steps);
  EXPECT_NEAR(r.x, kX1, 1e-3);
  EXPECT_NEAR(r.y, kY1, 1e-3);
}

// Over 10 s the pendulum swings through many re-partitionings (the rod turns far from its
// reference orientation): the recovered states keep the rod length to the position Newton's
// tolerance and the energy 1/2 |v|^2 + y (conserved; no damping) to the integration error.
TEST(Abam, PendulumKeepsItsConstraintAndEnergyOverManyRepartitions) {
  auto m = assemble(kPendulum);
  AbamIntegrator abam(*m->system, settingsFor(1e-8, 0.1));
  abam.start(0.0, m->y, m->yp);
  const double e0 = 0.5 * 1.0 + 0.0;  // |v0| = 1 at height 0
  double worstLength = 0.0, worstEnergy = 0.0;
  for (int k = 1; k <= 100; ++k) {
    ASSERT_TRUE(abam.advanceTo(0.1 * k)) << abam.failure().reason;
    const Eigen::VectorXd& y = abam.y();
    const Eigen::Vector3d r = y.segment<3>(StateLayout::kR);
    const Eigen::Vector3d v = y.segment<3>(StateLayout::kV);
    worstLength = std::max(worstLength, std::abs(r.norm() - 1.0));
    worstEnergy = std::max(worstEnergy, std::abs(0.5 * v.squaredNorm() + r(1) - e0));
  }
  std::printf("ABAM 10 s: %d partitions, |rod| - 1 worst %.2e, energy drift worst %.2e, %ld steps\n",
              abam.partitions(), worstLength, worstEnergy, abam.statistics().steps);
  EXPECT_GT(abam.partitions(), 1);
  EXPECT_LT(worstLength, 1e-10);
  EXPECT_LT(worstEnergy, 1e-5);
}

double springDamperExact(double t) {
  const double sigma = 1.0, wd = std::sqrt(99.0);
  return 0.1 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
}

// ABAM's output and its interpolant inside every step against the closed form. ERROR = 1e-8
// on positions and velocities: measured trajectory error ~1e-8 of the 0.1 amplitude; the
// interpolant (the Adams polynomial, order up to 12) is as accurate as the steps.
TEST(Abam, SpringDamperFollowsTheClosedFormAndInterpolatesInsideSteps) {
  auto m = assemble(kSpringDamper);
  AbamIntegrator abam(*m->system, settingsFor(1e-8, 0.01));
  abam.start(0.0, m->y, m->yp);
  double worstStep = 0.0, worstInside = 0.0;
  while (abam.t() < 2.0) {
    ASSERT_TRUE(abam.step(2.0)) << abam.failure().reason;
    worstStep = std::max(worstStep, std::abs(abam.y()(StateLayout::kR + 2) - 1.0 -
                                             springDamperExact(abam.t())));
    const double s = 0.5 * (abam.previousTime() + abam.t());
    Eigen::VectorXd y, yp;
    abam.interpolate(s, y, yp);
    worstInside = std::max(worstInside, std::abs(y(StateLayout::kR + 2) - 1.0 - springDamperExact(s)));
  }
  std::printf("ABAM spring-damper: worst error at steps %.2e, at step midpoints %.2e, %ld steps\n",
              worstStep, worstInside, abam.statistics().steps);
  EXPECT_LT(worstStep, 1e-6);
  EXPECT_LT(worstInside, 1e-6);
  EXPECT_FALSE(abam.stiffnessDetected());
}

TEST(Dstiff, SpringDamperInterpolatesInsideStepsToTheClosedForm) {
  auto m = assemble(kSpringDamper);
  MultibodyDae dae(*m->system);
  solvers::IdaIntegrator ida(dae, settingsFor(1e-8, 0.01));
  ida.start(0.0, m->y, m->yp);
  double worstStep = 0.0, worstInside = 0.0;
  while (ida.t() < 2.0) {
    ASSERT_TRUE(ida.step(2.0)) << ida.failure().reason;
    worstStep = std::max(worstStep, std::abs(ida.y()(StateLayout::kR + 2) - 1.0 -
                                             springDamperExact(ida.t())));
    const double s = 0.5 * (ida.previousTime() + ida.t());
    Eigen::VectorXd y, yp;
    ida.interpolate(s, y, yp);
    worstInside = std::max(worstInside, std::abs(y(StateLayout::kR + 2) - 1.0 - springDamperExact(s)));
  }
  std::printf("DSTIFF spring-damper: worst error at steps %.2e, at midpoints %.2e, %ld steps\n",
              worstStep, worstInside, ida.statistics().steps);
  EXPECT_LT(worstStep, 1e-6);
  EXPECT_LT(worstInside, 1e-6);
}

TEST(Abam, WarnsOnAStiffModelAndNamesTheRemedy) {
  auto m = assemble(kStiffSpring);
  AbamIntegrator abam(*m->system, settingsFor(1e-3, 0.01));
  abam.start(0.0, m->y, m->yp);
  ASSERT_TRUE(abam.advanceTo(0.05)) << abam.failure().reason;
  std::printf("ABAM stiff spring: spectral radius %.3e, %ld steps, warning: %s\n",
              abam.spectralRadius(), abam.statistics().steps,
              abam.warnings().empty() ? "(none)" : abam.warnings().front().c_str());
  // Eigenvalues of m x'' + c x' + k x = 0 at critical damping: -sqrt(k/m) = -1e4 (double).
  EXPECT_NEAR(abam.spectralRadius(), 1e4, 1e2);
  EXPECT_TRUE(abam.stiffnessDetected());
  ASSERT_EQ(abam.warnings().size(), 1u);
  EXPECT_NE(abam.warnings().front().find("GSTIFF"), std::string::npos);
  // The mass rests at the spring's length (gravity is zero here).
  EXPECT_NEAR(abam.y()(StateLayout::kR + 2), 1.0, 1e-3);
}

}  // namespace
}  // namespace openmss::analysis
