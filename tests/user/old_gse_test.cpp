// The old GSE interface (GSESUB with GSEXX, GSEXU, GSEYX, GSEYU) from the test libraries
// (tests/user/explicit_routines.c and .f): the second-order system x'' + 2 zeta w x' + w^2 x =
// w^2 u as GSE/1 (C, its own partials), GSE/2 (FORTRAN, GSESUB only: the solver differences it)
// and LSE/3 (the same matrices as constants), against the closed-form step response; the
// Newton matrix against central differences.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss {
namespace {

const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;

std::string model() {
  return "old gse\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "VARIABLE/1, FUNCTION=1\nARRAY/1, U, VARIABLES=1\nARRAY/2, X\nARRAY/3, Y\n"
         "GSE/1, NS=2, NO=1, X=2, U=1, Y=3, FUNCTION=USER(2, 0.3), ROUTINE=\"" +
         kC + "::\"\nARRAY/4, X\nARRAY/5, Y\n" +
         "GSE/2, NS=2, NO=1, X=4, U=1, Y=5, FUNCTION=USER(2, 0.3), ROUTINE=\"" + kF77 +
         "::\"\nARRAY/6, X\nARRAY/7, Y\n"
         "MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=2, VALUES=0, 1, -4, -1.2\n"
         "MATRIX/2, FULL=RORDER, ROWS=2, COLUMNS=1, VALUES=0, 4\n"
         "MATRIX/3, FULL=RORDER, ROWS=1, COLUMNS=2, VALUES=1, 0\n"
         "LSE/3, X=6, A=1, B=2, U=1, C=3, Y=7\nEND\n";
}

model::Model built() {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(model(), "g.adm", ds, d);
  model::Model m;
  const bool ok = model::buildModel(ds, m, d) && !d.hasErrors();
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  EXPECT_TRUE(ok) << all;
  return m;
}

TEST(OldGse, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = built();
  ASSERT_EQ(m.generalStates.size(), 2u);
  const mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
  for (int i = 0; i < y.size(); ++i) {
    y(i) += 0.3 * std::sin(1.7 * i + 0.4);
    yp(i) = 0.2 * std::cos(0.9 * i);
  }
  int checked = 0;
  for (double cj : {0.0, 25.0}) {
    const double worst = testing::checkNewtonMatrix(s, 0.7, y, yp, cj, "old GSE rows");
    std::printf("old GSE Newton matrix (cj = %g): largest relative difference %.2e\n", cj, worst);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

// Step response from rest: y(t) = 1 - exp(-zeta w t) (cos wd t + zeta w / wd sin wd t). ERROR =
// 1e-9: asserted at 1e-6 against the closed form (as gse_test.cpp); the forms share the
// integrator's steps: asserted at 1e-9 against the LSE.
TEST(OldGse, StepResponseMatchesClosedFormAndLse) {
  const model::Model m = built();
  ASSERT_EQ(m.generalStates.size(), 2u);
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  ASSERT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-12, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  ASSERT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  const auto& l = s.layout();
  const int x1 = l.userDiff(m.generalStates[0].firstState);
  const int x2 = l.userDiff(m.generalStates[1].firstState);
  const int x3 = l.userDiff(m.linearStates[0].firstState);
  solvers::MultistepSettings settings;
  settings.error = 1e-9;
  settings.hmax = 0.05;
  settings.hinit = 1e-4;
  analysis::MultibodyDae dae(s);
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, y, yp);
  const double w = 2.0, zeta = 0.3, wd = w * std::sqrt(1.0 - zeta * zeta);
  double worst = 0.0, worstForms = 0.0;
  int compared = 0;
  for (double t : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    ASSERT_TRUE(bdf.advanceTo(t)) << bdf.failure().reason;
    const Eigen::VectorXd& v = bdf.y();
    const double exact =
        1.0 - std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
    worst = std::max({worst, std::abs(v(x1) - exact), std::abs(v(x2) - exact)});
    for (int c = 0; c < 2; ++c, ++compared)
      worstForms =
          std::max({worstForms, std::abs(v(x1 + c) - v(x3 + c)), std::abs(v(x2 + c) - v(x3 + c))});
  }
  EXPECT_EQ(compared, 10);
  EXPECT_LE(worst, 1e-6);
  EXPECT_LE(worstForms, 1e-9);
  std::printf("old GSE step response: error %.2e against the closed form, %.2e against the LSE\n",
              worst, worstForms);
}

}  // namespace
}  // namespace openmss
