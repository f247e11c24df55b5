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
#include "solvers/ida_integrator.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

constexpr double kX1 = 0.867348640604551746;
constexpr double kY1 = 0.497701050476373918;

// As tests/analysis/dae_pendulum_test.cpp: unit point mass (inertia 1e-10) on a unit rod.
const char* kPendulum =
    "DAE test-set pendulum\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1e-10,1e-10,1e-10, VX=0, VY=1, VZ=0\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-1\n"
    "END\n";

// m = 2 on a translational joint along z, spring-damper k = 200, c = 4 (as
// force_elements_dynamics_test.cpp): x(t) = e^{-t} x0 (cos wd t + sin(wd t) / wd), wd^2 = 99.
const char* kSpringDamper =
    "mass on a spring-damper\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,1.1\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=200, C=4, LENGTH=1\n"
    "END\n";

// The same with k/m = 1e8 and critical damping (c = 2 sqrt(k m)): after a transient of a few
// 1e-4 s the mass rests; its eigenvalues (-1e4 double) make the model stiff for any explicit-
// like method over a run of 0.05 s.
const char* kStiffSpring =
    "stiff spring-damper\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0,0,1.001\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=1e8, C=2e4, LENGTH=1\n"
    "END\n";

struct Mechanism {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y, yp;
};

std::unique_ptr<Mechanism> assemble(const char* text) {
  auto m = std::make_unique<Mechanism>();
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "model.adm", ds, d);
  EXPECT_TRUE(model::buildModel(ds, m->model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  m->system = std::make_unique<mechanics::MultibodySystem>(m->model);
  m->y = m->system->initialState();
  mechanics::removeRedundantConstraints(*m->system, m->y);
  EXPECT_TRUE(mechanics::assemblePositions(*m->system, 0.0, m->y, 1e-12, 25).converged);
  mechanics::solveVelocities(*m->system, 0.0, m->y);
  EXPECT_TRUE(mechanics::solveAccelerations(*m->system, 0.0, m->y, m->yp));
  return m;
}

solvers::BdfSettings settingsFor(double error, double hmax) {
  solvers::BdfSettings s;
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
