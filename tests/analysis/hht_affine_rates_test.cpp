// HHT's old-step force rows from one residual per step (DaeProblem::forceRowsAffineInRates,
// docs/integrators.md "HHT and NEWMARK"): where y' enters the force balances only as the
// constant inertia term, G(t_n, y_n, y') = G(t_n, y_n, y'_pred) + B (y' - y'_pred) exactly, so
// the run must take the same steps and reach the same state to round-off as the run that
// evaluates G(t_n, y_n, y') at every corrector iteration, with fewer residual evaluations. A
// model whose forces read accelerations must not take the shortcut.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "analysis/multibody_dae.hpp"
#include "solvers/hht_integrator.hpp"
#include "support/bdf_run.hpp"
#include "support/forwarding_problem.hpp"
#include "support/link_chain.hpp"

namespace openmss::analysis {
namespace {

// A spatial chain of six links (revolute, spherical, universal and cylindrical joints) with a
// rotation MOTION, translational spring-dampers, an SFORCE reading velocities and a DIFF whose
// state drives a torque: 6 x 14 body unknowns plus the multipliers, above the sparse threshold.
std::string chain(const std::string& extraForce) {
  std::ostringstream s;
  s << "hht affine rates\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
       "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n";
  openmss::testing::writeLinkChain(
      s, {"REVOLUTE", "SPHERICAL", "UNIVERSAL", "REVOLUTE", "CYLINDRICAL", "SPHERICAL"}, 0.2,
      "0.05,0.08,0.11", 40, 0.4);
  s << "MOTION/1, JOINT=2, FUNCTION=0.3*SIN(2*TIME)\n"
    << "SFORCE/1, TRANSLATION, I=72, J=10, FUNCTION=-10*(DM(72,10)-5)-0.2*VR(72,10)\n"
    << "DIFF/1, FUNCTION=WZ(52,10)-DIF(1), IC=0\n"
    << "SFORCE/2, ROTATION, I=51, J=42, FUNCTION=-0.5*DIF(1)\n"
    << extraForce << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// The same equations with the shortcut withheld; the sparse matrix forwarded, so that both runs
// take the KLU path.
class TwoResidualProblem final : public testing::ForwardingProblem {
 public:
  using ForwardingProblem::ForwardingProblem;
  bool sparse() const override { return inner_.sparse(); }
  const Eigen::SparseMatrix<double>* pattern() override { return inner_.pattern(); }
  void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                          Eigen::SparseMatrix<double>& jac) override {
    inner_.newtonMatrixSparse(t, y, yp, cj, jac);
  }
};

struct Outcome {
  Eigen::VectorXd y;
  long steps = 0, residuals = 0;
};

Outcome runHht(solvers::DaeProblem& problem, const test::BdfRun& ic, double end) {
  solvers::HhtSettings settings = solvers::HhtSettings::hht(-0.3);
  settings.error = 1e-6;
  settings.hmax = 0.01;
  settings.hinit = 1e-4;
  solvers::HhtIntegrator hht(problem, settings);
  hht.start(0.0, ic.y(), ic.yp());
  Outcome o;
  EXPECT_TRUE(hht.advanceTo(end)) << hht.failure().reason;
  o.y = hht.y();
  o.steps = hht.statistics().steps;
  o.residuals = hht.statistics().residualEvaluations;
  return o;
}

TEST(HhtAffineRates, OneResidualPerStepGivesTheTwoResidualRun) {
  const model::Model m = test::buildModelFromText(chain(""), "hht_affine.adm");
  test::BdfRun ic(m, 1e-6, 0.01, false);  // initial conditions as `openmss run` makes them
  MultibodyDae dae(ic.system());
  ASSERT_TRUE(dae.forceRowsAffineInRates());
  ASSERT_GE(dae.size(), solvers::BdfIntegrator::kSparseThreshold);  // the KLU path
  TwoResidualProblem twoResiduals(dae);
  const Outcome one = runHht(dae, ic, 2.0);
  const Outcome two = runHht(twoResiduals, ic, 2.0);
  // The same steps: the step-size decisions see errors that differ by round-off only.
  EXPECT_EQ(one.steps, two.steps);
  EXPECT_GT(one.steps, 100);
  // The two paths sum the old-step rows in different orders (a few ulps per iteration); over
  // ~200 steps of a mechanism whose states are of order 1-10 that stays below 1e-9.
  const double scale = 1.0 + two.y.cwiseAbs().maxCoeff();
  EXPECT_LT((one.y - two.y).cwiseAbs().maxCoeff() / scale, 1e-9);
  // One old-step residual per attempt instead of one per iteration: at least 2 iterations per
  // step, so at least a third fewer evaluations.
  EXPECT_LT(static_cast<double>(one.residuals), 0.8 * static_cast<double>(two.residuals));
}

TEST(HhtAffineRates, ForcesReadingAccelerationsKeepTwoResiduals) {
  const model::Model plain = test::buildModelFromText(chain(""), "hht_affine.adm");
  const model::Model reads = test::buildModelFromText(
      chain("SFORCE/3, TRANSLATION, I=62, J=10, FUNCTION=-0.1*ACCX(62,10)\n"), "hht_affine.adm");
  mechanics::MultibodySystem plainSystem(plain), readsSystem(reads);
  EXPECT_TRUE(MultibodyDae(plainSystem).forceRowsAffineInRates());
  EXPECT_FALSE(MultibodyDae(readsSystem).forceRowsAffineInRates());
}

}  // namespace
}  // namespace openmss::analysis
