// The Newton matrix of a small pile of spheres (docs/theory.md §6c, "Shared kinematics"): one
// CONTACT per sphere against the floor and one per pair of spheres, as bench/contact_pile.py
// writes them. The sparse matrix's compressed passes evaluate only the contacts near (shared
// broad phase) and, per pass, only those at the parts the pass seeds; the result must equal
// the dense matrix (every element in every direction) and central differences of the residual.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact/contact_support.hpp"
#include "mechanics/contact/contact_broad_phase.hpp"
#include "mechanics/jacobian_pattern.hpp"

namespace openmss::contact_test {
namespace {

// Four spheres (radius 0.05) on the floor 0.099 apart (1e-3 into the floor and into their
// neighbours; the fourth 5e-4 into the floor), a fifth resting on the four, and a sixth far
// above (its contacts are apart: the broad phase leaves them out).
std::string pileDeck() {
  const double z5 = 0.049 + 0.0700;
  const double centres[6][3] = {{0, 0, 0.049},          {0.099, 0, 0.049},    {0, 0.099, 0.049},
                                {0.099, 0.099, 0.0495}, {0.0495, 0.0495, z5}, {1, 1, 1}};
  std::string d =
      "pile jacobian\nPART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\n"
      "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n";
  for (int i = 0; i < 6; ++i) {
    const int p = 2 + i;
    char line[256];
    std::snprintf(line, sizeof line,
                  "PART/%d, MASS=0.1, CM=%d, IP=1e-4,1e-4,1e-4, QG=%.6f,%.6f,%.6f\n"
                  "MARKER/%d, PART=%d\n"
                  "GRAPHICS/%d, ELLIPSOID, CM=%d, XSCALE=0.1, YSCALE=0.1, ZSCALE=0.1\n",
                  p, 10 * p, centres[i][0], centres[i][1], centres[i][2], 10 * p, p, 10 * p,
                  10 * p);
    d += line;
  }
  const std::string law =
      "IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=2e-3, EXPONENT=1.5, COULOMB_FRICTION=ON, "
      "MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=0.1, "
      "FRICTION_TRANSITION_VELOCITY=1\n";
  int id = 1;
  for (int i = 0; i < 6; ++i)
    d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (2 + i)) +
         ", JGEOM=1, " + law;
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (2 + i)) +
           ", JGEOM=" + std::to_string(10 * (2 + j)) + ", " + law;
  return d + "ACCGRAV/KGRAV=-9.81\nEND\n";
}

TEST(ContactPile, NewtonMatrixMatchesDenseAndCentralDifferences) {
  const model::Model m = build(pileDeck());
  ASSERT_EQ(m.contacts.size(), 21u);
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;  // friction acts
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState();
  // Every sphere moving and turning, each differently (slip on every friction branch).
  for (int b = 0; b < s.layout().bodies; ++b)
    for (int c = 0; c < 3; ++c) {
      y(s.layout().body(b) + StateLayout::kV + c) = 0.3 * std::sin(1.0 + 3 * b + c);
      y(s.layout().body(b) + StateLayout::kW + c) = 2.0 * std::cos(2.0 + 5 * b + c);
    }
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());

  // What is being compared: the contacts in touch (4 on the floor, 4 between floor
  // neighbours, 4 under the top sphere) and the near ones (the far sphere's 6 are apart).
  int touching = 0;
  for (const model::Contact& c : m.contacts)
    touching +=
        mechanics::contact::contactLoads<double>(m, s.layout(), c, y.data(), true).points > 0;
  EXPECT_EQ(touching, 12);
  mechanics::contact::ContactBroadPhase broad(m, s.layout());
  // Near: the 8 pairs in touch and 5 spheres against the floor (its bounding sphere, radius 3
  // about the corner, reaches all but the far sphere); the far sphere's 6 contacts are apart.
  EXPECT_EQ(broad.near(y.data()).size(), 13u);

  // The sparse matrix (compressed passes, contacts left out per pass) against the dense one.
  const double cj = 30.0;
  const mechanics::JacobianPattern pattern = mechanics::newtonMatrixPattern(s);
  Eigen::SparseMatrix<double> sparse = pattern.matrix();
  mechanics::SparseJacobianWork work;
  Eigen::MatrixXd dense;
  s.newtonMatrix(0.0, y, yp, cj, dense);
  s.newtonMatrixSparse(0.0, y, yp, cj, pattern, sparse, work);
  const double largest = dense.cwiseAbs().maxCoeff();
  const double difference = (Eigen::MatrixXd(sparse) - dense).cwiseAbs().maxCoeff();
  std::printf("contact pile: max |sparse - dense| %.3e of largest entry %.3e\n", difference,
              largest);
  // Both are exact partials summed in different orders: round-off of the largest entry.
  EXPECT_LE(difference, 1e-12 * largest);
  EXPECT_TRUE(s.rowsOutsidePattern(0.0, y, yp, cj, sparse, work).empty());

  // dG/dy (cj = 0) against central differences of the residual, every column.
  Eigen::SparseMatrix<double> exact = pattern.matrix();
  s.newtonMatrixSparse(0.0, y, yp, 0.0, pattern, exact, work);
  const Eigen::MatrixXd e(exact);
  const int n = static_cast<int>(y.size());
  Eigen::VectorXd gp(n), gm(n);
  double worst = 0.0, scale = 0.0;
  int columns = 0;
  for (int c = 0; c < n; ++c) {
    const double h = 1e-7;
    Eigen::VectorXd a = y, b = y;
    a(c) += h;
    b(c) -= h;
    s.residual(0.0, a.data(), yp.data(), gp.data());
    s.residual(0.0, b.data(), yp.data(), gm.data());
    const Eigen::VectorXd fd = (gp - gm) / (2 * h);
    worst = std::max(worst, (fd - e.col(c)).cwiseAbs().maxCoeff());
    scale = std::max(scale, e.col(c).cwiseAbs().maxCoeff());
    ++columns;
  }
  std::printf(
      "contact pile: max |sparse - central difference| %.3e of max entry %.3e over %d "
      "columns\n",
      worst, scale, columns);
  EXPECT_EQ(columns, 6 * StateLayout::kPerBody);
  // Central differences with h = 1e-7 are good to ~1e-7 relative on these smooth branches (as
  // contact_model_test.cpp's single contacts).
  EXPECT_LT(worst, 1e-6 * scale);
}

}  // namespace
}  // namespace openmss::contact_test
