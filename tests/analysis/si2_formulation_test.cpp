// The SI2 (stabilised index-2) equations of analysis/multibody_dae_si2.hpp: their Newton matrix
// against central differences of their residual at a state off the solution (eta != 0, a
// tilted, spinning body, a MOTION), and their velocity rows against C u = 0 at a consistent
// state.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/multibody_dae_si2.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

// A crank (revolute, driven) and a free link hung from it by a spherical joint.
const char* kDataSet =
    "SI2 check\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=0.3,0.4,0.5, QG=0.2,0.1,0, REULER=10D,20D,30D\n"
    "MARKER/20, PART=2, QP=0.2,0.1,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "MARKER/22, PART=2, QP=1,0.3,0\n"
    "PART/3, MASS=1, CM=30, IP=0.1,0.2,0.3, QG=1.5,0.3,0.1, WX=1, WY=-2, WZ=0.5\n"
    "MARKER/30, PART=3, QP=1.5,0.3,0.1\n"
    "MARKER/31, PART=3, QP=1,0.3,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, SPHERICAL, I=31, J=22\n"
    "MOTION/1, JOINT=1, FUNCTION=0.7*TIME+0.1*TIME**2\n"
    "ACCGRAV/ JGRAV=-9.81\n"
    "END\n";

struct Fixture {
  model::Model m;
  std::unique_ptr<mechanics::MultibodySystem> s;
  Eigen::VectorXd y, yp;
  Fixture() {
    language::Dataset ds;
    Diagnostics d;
    language::readDatasetText(kDataSet, "si2.adm", ds, d);
    EXPECT_TRUE(model::buildModel(ds, m, d));
    for (const auto& x : d.all()) ADD_FAILURE() << format(x);
    s = std::make_unique<mechanics::MultibodySystem>(m);
    y = s->initialState();
    mechanics::removeRedundantConstraints(*s, y);
    EXPECT_TRUE(mechanics::assemblePositions(*s, 0.3, y, 1e-12, 25).converged);
    mechanics::solveVelocities(*s, 0.3, y);
    EXPECT_TRUE(mechanics::solveAccelerations(*s, 0.3, y, yp));
  }
};

TEST(Si2Formulation, VelocityRowsVanishAtAConsistentState) {
  Fixture f;
  MultibodyDaeSi2 dae(*f.s);
  const int n = dae.baseSize(), m = dae.size();
  ASSERT_GT(m, n);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(m), yp = Eigen::VectorXd::Zero(m), g;
  y.head(n) = f.y;
  yp.head(n) = f.yp;
  dae.residual(0.3, y, yp, g);
  EXPECT_LT(g.tail(m - n).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_LT(g.head(n).lpNorm<Eigen::Infinity>(), 1e-8);  // the I3 rows, untouched at eta = 0
}

TEST(Si2Formulation, NewtonMatrixMatchesCentralDifferences) {
  Fixture f;
  MultibodyDaeSi2 dae(*f.s);
  const int n = dae.baseSize(), m = dae.size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(m), yp = Eigen::VectorXd::Zero(m);
  y.head(n) = f.y;
  yp.head(n) = f.yp;
  for (int k = n; k < m; ++k) y(k) = 0.05 * (k - n + 1);  // eta off the solution
  for (int i = 0; i < n; ++i)
    if (dae.differential(i)) y(i) += 1e-3 * std::sin(1.0 + i);  // and the state too
  const double cj = 37.0, t = 0.3;
  Eigen::MatrixXd jac;
  dae.newtonMatrix(t, y, yp, cj, jac);
  double worst = 0.0;
  for (int c = 0; c < m; ++c) {
    const double h = 1e-6 * std::max(1.0, std::abs(y(c)));
    Eigen::VectorXd yA = y, yB = y, pA = yp, pB = yp, gA, gB;
    yA(c) += h;
    yB(c) -= h;
    if (dae.differential(c)) {
      pA(c) += cj * h;
      pB(c) -= cj * h;
    }
    dae.residual(t, yA, pA, gA);
    dae.residual(t, yB, pB, gB);
    const Eigen::VectorXd fd = (gA - gB) / (2 * h);
    for (int r = 0; r < m; ++r) {
      // Both sides difference the stabilisation terms (step 1e-6): 1e-5 leaves margin.
      EXPECT_NEAR(jac(r, c), fd(r), 1e-5 * (1.0 + std::abs(fd(r)))) << "row " << r << " col " << c;
      worst = std::max(worst, std::abs(jac(r, c) - fd(r)) / (1.0 + std::abs(fd(r))));
    }
  }
  std::printf("SI2 Newton matrix vs central differences: worst %.2e (%d x %d)\n", worst, m, m);
}

}  // namespace
}  // namespace openmss::analysis
