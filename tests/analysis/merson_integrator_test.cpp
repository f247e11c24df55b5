// MERSON (explicit Kutta-Merson 4(3) on the index-1 equations with projection) against
// independent answers: the index-3 pendulum of the DAE test sets (and its error falling with
// ERROR), a mass on a spring-damper (closed form, at steps and inside them), the energy and
// constraints of an undamped planar chain, GSTIFF at tight tolerance on a spatial chain, the
// refusal of DIFF states, the stiffness warning on a spring of k/m = 1e8 and its absence on an
// undamped 20-link chain, the warm-started spectral radius against the eigenvalues of the full
// Jacobian, and two CLI runs that must write the same .req byte for byte.

#include "analysis/merson_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/index_one_dynamics.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "support/integrator_test_models.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/cli_run.hpp"

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

// N unit links (1 kg, slender: I = 1/12 about the transverse axes) along x from the origin,
// gravity 9.81 along -y. Planar: revolute joints about z. Spatial: spherical joints, and the
// links start with a transverse velocity along z growing down the chain (made consistent by
// the initial-condition analysis), so the motion leaves the plane.
std::string chainDataset(int links, bool spatial) {
  std::string text = std::string(spatial ? "spatial" : "planar") + " pendulum chain\n" +
                     "UNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n";
  char buf[256];
  for (int i = 1; i <= links; ++i) {
    const int part = i + 1;
    std::snprintf(buf, sizeof buf,
                  "PART/%d, MASS=1, CM=%d01, IP=1e-4,0.0833333333333333,0.0833333333333333%s\n"
                  "MARKER/%d01, PART=%d, QP=%g,0,0\nMARKER/%d02, PART=%d, QP=%d,0,0\n"
                  "MARKER/%d03, PART=%d, QP=%d,0,0\n"
                  "JOINT/%d, %s, I=%d02, J=%d\n",
                  part, part, spatial ? (", VZ=" + std::to_string(0.5 * i)).c_str() : "", part,
                  part, i - 0.5, part, part, i - 1, part, part, i, i,
                  spatial ? "SPHERICAL" : "REVOLUTE", part, i == 1 ? 10 : (part - 1) * 100 + 3);
    text += buf;
  }
  text += "ACCGRAV/ JGRAV=-9.81\nEND\n";
  return text;
}


MersonSettings settingsFor(double error, double hmax) {
  MersonSettings s;
  s.error = error;
  s.hmax = hmax;
  s.hinit = 1e-4;
  return s;
}

struct PendulumResult {
  double dx, dy;
  solvers::IntegratorStatistics stats;
};

PendulumResult pendulumAt(double error, double hmax) {
  auto m = assemble(kPendulum);
  MersonIntegrator merson(*m->system, settingsFor(error, hmax));
  merson.start(0.0, m->y, m->yp);
  EXPECT_TRUE(merson.advanceTo(1.0)) << merson.failure().reason;
  EXPECT_DOUBLE_EQ(merson.t(), 1.0);
  EXPECT_FALSE(merson.stiffnessDetected());
  return {merson.y()(StateLayout::kR) - kX1, merson.y()(StateLayout::kR + 1) - kY1,
          merson.statistics()};
}

// With HMAX = 0.1 (as the other integrators' pendulum tests) the end point is within 1e-6 of
// the test-set value at every ERROR: the model's own offset (-9.2e-7 in y, docs/integrators.md,
// "The pendulum model's own offset") leaves 8e-8 of that.
TEST(Merson, PendulumMatchesTheTestSet) {
  for (const double error : {1e-3, 1e-8}) {
    const PendulumResult r = pendulumAt(error, 0.1);
    std::printf(
        "MERSON pendulum ERROR=%.0e HMAX=0.1: x(1) error %.2e, y(1) error %.2e, %ld "
        "steps, %ld evaluations\n",
        error, r.dx, r.dy, r.stats.steps, r.stats.residualEvaluations);
    EXPECT_NEAR(r.dx, 0.0, 1e-6);
    EXPECT_NEAR(r.dy, 0.0, 1e-6);
    EXPECT_EQ(r.stats.jacobianEvaluations, 0);
  }
}

// Order check without HMAX: the error against a run at ERROR = 1e-12 (the model's offset
// cancels) falls with ERROR, at least 10x per 100x, and stays within ERROR.
TEST(Merson, PendulumErrorFallsWithError) {
  const double inf = std::numeric_limits<double>::infinity();
  const PendulumResult reference = pendulumAt(1e-12, inf);
  double previous = 1.0;
  for (const double error : {1e-3, 1e-5, 1e-7, 1e-9}) {
    const PendulumResult r = pendulumAt(error, inf);
    const double e = std::hypot(r.dx - reference.dx, r.dy - reference.dy);
    std::printf(
        "MERSON pendulum ERROR=%.0e: error %.2e against ERROR=1e-12, %ld steps, %ld "
        "rejected, %ld evaluations\n",
        error, e, r.stats.steps, r.stats.rejectedSteps, r.stats.residualEvaluations);
    EXPECT_LT(e, error);
    EXPECT_LT(e, 0.1 * previous);
    previous = e;
  }
}

double springDamperExact(double t) {
  const double wd = std::sqrt(99.0);
  return 0.1 * std::exp(-t) * (std::cos(wd * t) + std::sin(wd * t) / wd);
}

// ERROR = 1e-8 per step on positions and velocities; over ~2 s of steps the global error stays
// near ERROR. The midpoints use the cubic Hermite, third order: its error ~h^4 |x''''| / 384
// is of the order of the step's own error at these steps (measured below).
TEST(Merson, SpringDamperFollowsTheClosedFormAtStepsAndInside) {
  auto m = assemble(kSpringDamper);
  MersonIntegrator merson(*m->system, settingsFor(1e-8, 0.01));
  merson.start(0.0, m->y, m->yp);
  double worstStep = 0.0, worstInside = 0.0;
  while (merson.t() < 2.0) {
    ASSERT_TRUE(merson.step(2.0)) << merson.failure().reason;
    worstStep = std::max(
        worstStep, std::abs(merson.y()(StateLayout::kR + 2) - 1.0 - springDamperExact(merson.t())));
    const double s = 0.5 * (merson.previousTime() + merson.t());
    Eigen::VectorXd y, yp;
    merson.interpolate(s, y, yp);
    worstInside =
        std::max(worstInside, std::abs(y(StateLayout::kR + 2) - 1.0 - springDamperExact(s)));
  }
  std::printf(
      "MERSON spring-damper: worst error at steps %.2e, at step midpoints %.2e, "
      "%ld steps\n",
      worstStep, worstInside, merson.statistics().steps);
  EXPECT_LT(worstStep, 1e-7);
  EXPECT_LT(worstInside, 1e-6);
  EXPECT_FALSE(merson.stiffnessDetected());
}

double chainEnergy(const mechanics::MultibodySystem& system, const Eigen::VectorXd& y) {
  const StateLayout& l = system.layout();
  const Eigen::Vector3d inertia(1e-4, 1.0 / 12.0, 1.0 / 12.0);
  double energy = 0.0;
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    const Eigen::Vector3d v = y.segment<3>(o + StateLayout::kV);
    const Eigen::Vector3d w = y.segment<3>(o + StateLayout::kW);
    energy += 0.5 * v.squaredNorm() + 0.5 * w.dot(inertia.cwiseProduct(w)) +
              9.81 * y(o + StateLayout::kR + 1);
  }
  return energy;
}

// An undamped planar chain of 8 links over 10 s: energy (initially 0) drifts by the integration
// error only, and the constraints hold at every output to the projection threshold
// (projected after every step onto |Phi| <= 1e-4 ERROR) plus what one step adds.
TEST(Merson, PlanarChainConservesEnergyAndHoldsItsConstraints) {
  auto m = assemble(chainDataset(8, false));
  const double error = 1e-6;
  MersonIntegrator merson(*m->system, settingsFor(error, 1e30));
  mechanics::IndexOneDynamics check(*m->system);
  merson.start(0.0, m->y, m->yp);
  const double e0 = chainEnergy(*m->system, m->y);
  double worstEnergy = 0.0, worstPosition = 0.0, worstVelocity = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.1 * k;
    ASSERT_TRUE(merson.advanceTo(t)) << merson.failure().reason;
    worstEnergy = std::max(worstEnergy, std::abs(chainEnergy(*m->system, merson.y()) - e0));
    worstPosition = std::max(worstPosition, check.positionViolation(t, merson.y()));
    worstVelocity = std::max(worstVelocity, check.velocityViolation(t, merson.y()));
  }
  std::printf(
      "MERSON planar chain N=8, 10 s, ERROR=1e-6: energy drift %.2e J (of potential "
      "range %.1f J), |Phi| %.2e, |C u - nu| %.2e, %ld steps, %ld evaluations, "
      "%ld projections\n",
      worstEnergy, 9.81 * 32.0, worstPosition, worstVelocity, merson.statistics().steps,
      merson.statistics().residualEvaluations, merson.projections());
  // Energy: the chain exchanges ~300 J between potential and kinetic energy; 1e-3 J is a
  // relative 3e-6, three orders above ERROR per step over ~1000 steps of mostly cancelling
  // errors would allow more, so this is a meaningful bound.
  EXPECT_LT(worstEnergy, 1e-3);
  EXPECT_LT(worstPosition, 0.2 * error);
  EXPECT_LT(worstVelocity, 0.2 * error);
}

// A spatial chain of 5 links over 2 s: MERSON at ERROR = 1e-9 and GSTIFF (variable-order BDF
// on the index-3 DAE, an independent method and formulation) at 1e-9 agree on every body
// position to 1e-5. Measured 1.0e-6 over positions that move by metres: the two methods' global
// errors at that tolerance after ~600 and ~1800 steps; the bound leaves 10x for round-off.
TEST(Merson, SpatialChainAgreesWithGstiffAtTightTolerance) {
  auto m = assemble(chainDataset(5, true));
  MersonIntegrator merson(*m->system, settingsFor(1e-9, 1e30));
  merson.start(0.0, m->y, m->yp);
  MultibodyDae dae(*m->system);
  solvers::MultistepSettings bs;
  bs.error = 1e-9;
  bs.hmax = 0.01;
  bs.hinit = 1e-5;
  solvers::BdfIntegrator gstiff(dae, bs);
  gstiff.start(0.0, m->y, m->yp);
  double worst = 0.0, outOfPlane = 0.0;
  for (int k = 1; k <= 20; ++k) {
    const double t = 0.1 * k;
    ASSERT_TRUE(merson.advanceTo(t)) << merson.failure().reason;
    ASSERT_TRUE(gstiff.advanceTo(t)) << gstiff.failure().reason;
    for (int b = 0; b < m->system->layout().bodies; ++b) {
      const int o = m->system->layout().body(b);
      worst = std::max(worst, (merson.y().segment<3>(o) - gstiff.y().segment<3>(o)).norm());
      outOfPlane = std::max(outOfPlane, std::abs(merson.y()(o + 2)));
    }
  }
  std::printf(
      "MERSON vs GSTIFF spatial chain N=5, 2 s: worst position difference %.2e "
      "(out-of-plane excursion %.2f), MERSON %ld steps, GSTIFF %ld steps\n",
      worst, outOfPlane, merson.statistics().steps, gstiff.statistics().steps);
  EXPECT_GT(outOfPlane, 0.1);  // the motion is really spatial
  EXPECT_LT(worst, 1e-5);
}

TEST(Merson, RefusesDiffStatesNamingTheRemedy) {
  std::string text = kSpringDamper;
  text.insert(text.find("END"), "DIFF/1, IC=0, FUNCTION=-2*DIF(1)+DZ(20,10)\n");
  auto m = assemble(text);
  MersonIntegrator merson(*m->system, settingsFor(1e-6, 0.01));
  merson.start(0.0, m->y, m->yp);
  EXPECT_FALSE(merson.step(1.0));
  std::printf("MERSON on DIFF: %s\n", merson.failure().reason.c_str());
  EXPECT_NE(merson.failure().reason.find("DIFF"), std::string::npos);
  EXPECT_NE(merson.failure().reason.find("GSTIFF"), std::string::npos);
}

// The warning rule (merson_integrator.cpp, kAccuracyRoom): steps held by the stability of the
// fastest mode for a window of 64 steps, while the motion would allow steps 20x larger. The
// spring comes to rest within 1e-3 s; after that only the fast mode, kept by the controller at
// an amplitude of about ERROR, moves, so the steps accuracy would allow are far beyond HMAX.
TEST(Merson, WarnsOnAStiffModelAndNamesTheRemedy) {
  auto m = assemble(kStiffSpring);
  MersonIntegrator merson(*m->system, settingsFor(1e-3, 0.1));
  merson.start(0.0, m->y, m->yp);
  ASSERT_TRUE(merson.advanceTo(0.05)) << merson.failure().reason;
  std::printf(
      "MERSON stiff spring: spectral radius %.3e (%ld estimates), %ld steps, %ld "
      "rejected, %ld evaluations, held step %.3e, accuracy step %.3e, warning: %s\n",
      merson.spectralRadius(), merson.spectralEstimates(), merson.statistics().steps,
      merson.statistics().rejectedSteps, merson.statistics().residualEvaluations, merson.heldStep(),
      merson.accuracyStep(),
      merson.warnings().empty() ? "(none)" : merson.warnings().front().c_str());
  // Eigenvalues -sqrt(k/m) = -1e4 (double, defective): power iteration on a Jordan block
  // converges like 1/k, not geometrically; after 8 iterations of J^2 it is 7 % high, hence 10 %.
  EXPECT_NEAR(merson.spectralRadius(), 1e4, 1e3);
  EXPECT_TRUE(merson.stiffnessDetected());
  ASSERT_EQ(merson.warnings().size(), 1u);
  EXPECT_NE(merson.warnings().front().find("GSTIFF"), std::string::npos);
  EXPECT_NEAR(merson.y()(StateLayout::kR + 2), 1.0, 1e-3);
}

// An undamped 20-link planar chain over 10 s is not stiff for MERSON: whether or not its steps
// touch the stability limit of the fastest mode, the motion itself needs steps of that size, so
// no warning. The accuracy step of the windows stays within a few held steps.
TEST(Merson, NoStiffnessWarningOnAnUndampedChain) {
  for (const double error : {1e-3, 1e-4}) {
    auto m = assemble(chainDataset(20, false));
    MersonIntegrator merson(*m->system, settingsFor(error, 1e30));
    merson.start(0.0, m->y, m->yp);
    ASSERT_TRUE(merson.advanceTo(10.0)) << merson.failure().reason;
    std::printf(
        "MERSON planar chain N=20, ERROR=%.0e: spectral radius %.3e, last step %.3e "
        "(h rho %.2f), %ld steps, %ld rejected, last window: held step %.3e, accuracy "
        "step %.3e\n",
        error, merson.spectralRadius(), merson.statistics().stepSize,
        merson.spectralRadius() * merson.statistics().stepSize, merson.statistics().steps,
        merson.statistics().rejectedSteps, merson.heldStep(), merson.accuracyStep());
    EXPECT_FALSE(merson.stiffnessDetected());
    EXPECT_TRUE(merson.warnings().empty());
  }
}

// The spectral radius that the stiffness watch uses, after two warm-started re-estimates
// (steps 200 and 400: 2-8 power iterations from the previous dominant vector), against the
// eigenvalues of the full ODE Jacobian at the same state (central differences, 13 per body,
// EigenSolver): an independent answer. Power iteration on J^2 approaches rho from below; the
// chain's fastest modes are clustered, so it converges slowly and the bound is 10 %.
TEST(Merson, WarmStartedSpectralRadiusMatchesTheJacobianEigenvalues) {
  auto m = assemble(chainDataset(20, false));
  MersonIntegrator merson(*m->system, settingsFor(1e-4, 1e30));
  merson.start(0.0, m->y, m->yp);
  while (merson.statistics().steps < 400) ASSERT_TRUE(merson.step(100.0));
  ASSERT_EQ(merson.spectralEstimates(), 3);
  const StateLayout& l = m->system->layout();
  const int n = 13 * l.bodies;
  mechanics::IndexOneDynamics dynamics(*m->system);
  auto f = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y = merson.y(), yp(y.size());
    for (int b = 0; b < l.bodies; ++b) y.segment<13>(l.body(b)) = x.segment<13>(13 * b);
    EXPECT_TRUE(dynamics.evaluate(merson.t(), y, yp));
    Eigen::VectorXd out(n);
    for (int b = 0; b < l.bodies; ++b) out.segment<13>(13 * b) = yp.segment<13>(l.body(b));
    return out;
  };
  Eigen::VectorXd x(n);
  for (int b = 0; b < l.bodies; ++b) x.segment<13>(13 * b) = merson.y().segment<13>(l.body(b));
  Eigen::MatrixXd jacobian(n, n);
  for (int j = 0; j < n; ++j) {
    const double delta = 1e-6 * (1.0 + std::abs(x(j)));
    Eigen::VectorXd plus = x, minus = x;
    plus(j) += delta;
    minus(j) -= delta;
    jacobian.col(j) = (f(plus) - f(minus)) / (2.0 * delta);
  }
  const double rho =
      Eigen::EigenSolver<Eigen::MatrixXd>(jacobian, false).eigenvalues().cwiseAbs().maxCoeff();
  std::printf(
      "MERSON spectral radius at step 400 (t = %.3f): warm power iteration %.4e, "
      "Jacobian eigenvalues %.4e (ratio %.3f), %ld evaluations in all\n",
      merson.t(), merson.spectralRadius(), rho, merson.spectralRadius() / rho,
      merson.statistics().residualEvaluations);
  EXPECT_NEAR(merson.spectralRadius() / rho, 1.0, 0.1);
}

// Through the openmss program: the banner names the method, two runs write the same .req
// byte for byte (no state survives between runs, nothing depends on the clock), and KMAX is
// refused with a diagnostic.
TEST(MersonRun, CommandLineRunsAreReproducibleAndNameTheMethod) {
  namespace fs = std::filesystem;
  using openmss::testing::run;
  using openmss::testing::slurp;
  using openmss::testing::write;
  const fs::path dir = openmss::testing::scratch("merson");
  std::string adm = chainDataset(5, false);
  adm.insert(adm.find("END"), "REQUEST/1, DISPLACEMENT, I=603, J=10\nOUTPUT/REQSAVE\n");
  write(dir / "chain.adm", adm);
  for (const char* name : {"a", "b"})
    write(dir / (std::string(name) + ".acf"),
          std::string("chain\n") + name +
              "\nINTEGRATOR/MERSON, ERROR=1e-5\nSIMULATE/DYNAMIC, END=2, STEPS=20\nSTOP\n");
  const auto ra = run("run a.acf --quiet", dir);
  ASSERT_EQ(ra.status, 0) << ra.output;
  const auto rb = run("run b.acf --quiet", dir);
  ASSERT_EQ(rb.status, 0) << rb.output;
  const std::string reqA = slurp(dir / "a.req"), reqB = slurp(dir / "b.req");
  EXPECT_GT(reqA.size(), 1000u);
  EXPECT_EQ(reqA, reqB);
  const std::string msg = slurp(dir / "a.msg");
  EXPECT_NE(msg.find("Performing Dynamic Simulation using MERSON I3 Integrator"), std::string::npos)
      << msg;
  write(dir / "k.acf",
        "chain\nk\nINTEGRATOR/MERSON, KMAX=4\nSIMULATE/DYNAMIC, END=1, STEPS=10\n"
        "STOP\n");
  const auto rk = run("run k.acf --quiet", dir);
  EXPECT_NE(rk.output.find("KMAX does not apply"), std::string::npos) << rk.output;
}

}  // namespace
}  // namespace openmss::analysis
