// The Newton matrix with user states present (docs/theory.md §4a) against central differences:
// VARIABLEs in an algebraic loop and reading marker measures, explicit and implicit DIFFs, an
// LSE with inputs and a TFSISO with a direct term, all feeding a torque on a pendulum.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/newton_matrix_check.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

const char* kDataSet =
    "user equations on a pendulum\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=0.1,0.2,0.3\n"
    "MARKER/20, PART=2, QP=0.6,-0.8,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-9.81\n"
    "VARIABLE/1, FUNCTION=0.5 - ATAN2(DX(20, 10), -DY(20, 10)) + 0.1*VARVAL(2)\n"
    "VARIABLE/2, FUNCTION=SIN(VARVAL(1)) + WZ(20)*DIF(1)\n"
    "DIFF/1, FUNCTION=VARVAL(1) - 0.3*DIF(1)**2, IC=0.2\n"
    "DIFF/2, IMPLICIT, FUNCTION=DIF1(2)*(2 + COS(DIF(2))) + VR(20, 10) - VARVAL(2), IC=0.1\n"
    "ARRAY/1, U, VARIABLES=1, 2\n"
    "ARRAY/2, X\n"
    "ARRAY/3, Y\n"
    "MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=2, VALUES=-1, 2, -3, -4\n"
    "MATRIX/2, FULL=RORDER, ROWS=2, COLUMNS=2, VALUES=1, 0.5, -0.25, 2\n"
    "MATRIX/3, FULL=RORDER, ROWS=1, COLUMNS=2, VALUES=0.7, -1.1\n"
    "MATRIX/4, FULL=RORDER, ROWS=1, COLUMNS=2, VALUES=0.3, 0.2\n"
    "ARRAY/4, IC, NUMBERS=0.1, -0.2\n"
    "LSE/1, X=2, A=1, B=2, U=1, C=3, D=4, Y=3, IC=4\n"
    "ARRAY/5, U, VARIABLES=2\n"
    "ARRAY/6, X\n"
    "ARRAY/7, Y\n"
    "TFSISO/2, X=6, U=5, Y=7, NUMERATOR=1, 2, 3, DENOMINATOR=5, 1, 2\n"
    "VARIABLE/3, FUNCTION=ARYVAL(3, 1) + 2*ARYVAL(7, 1) + ARYVAL(6, 2)*ARYVAL(4, 2)\n"
    "SFORCE/1, ROTATION, I=21, J=10, FUNCTION=10*VARVAL(3) - 3*DIF(2) + DIF1(1)\n"
    "END\n";

TEST(UserEquationsJacobian, NewtonMatrixMatchesCentralDifferences) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kDataSet, "user.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  const MultibodySystem s(m);
  const L& l = s.layout();
  ASSERT_EQ(l.userDifferential, 2 + 2 + 2);  // two DIFFs, LSE (2 states), TFSISO (2 states)
  ASSERT_EQ(l.userAlgebraic, 3 + 2);         // three VARIABLEs, two DIFF derivatives
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = l.size();
  double worst = 0.0;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd y = s.initialState();
    const int o = l.body(0);
    for (int c = 0; c < 3; ++c) y(o + L::kR + c) += 0.1 * u(rng);
    Eigen::Vector4d e = y.segment<4>(o + L::kE);
    for (int c = 0; c < 4; ++c) e(c) += 0.2 * u(rng);
    y.segment<4>(o + L::kE) = e.normalized();
    for (int c = 0; c < 3; ++c) {
      y(o + L::kV + c) = u(rng);
      y(o + L::kW + c) = u(rng);
    }
    for (int i = l.userDiff(0); i < l.lambda(0); ++i) y(i) = u(rng);
    for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) = 10.0 * u(rng);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
    Eigen::MatrixXd jac;
    worst = std::max(worst, testing::checkNewtonMatrix(s, 0.123, y, yp, 37.0,
                                                        "trial " + std::to_string(trial), &jac));
    // The user rows do depend on the user unknowns and on the body states.
    EXPECT_NE(jac(l.userAlg(0), l.userAlg(1)), 0.0);
    EXPECT_NE(jac(l.userAlg(0), o + L::kR), 0.0);
    EXPECT_NE(jac(o + L::kW + 2, l.userAlg(2)), 0.0);
  }
  std::printf("user equations: largest relative difference AD vs central %.2e\n", worst);
}

}  // namespace
}  // namespace openmss::mechanics
