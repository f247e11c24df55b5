// GCON (docs/theory.md §5c): a general constraint's equation, row, Newton matrix and rates
// against central differences on random states; GCONs that restate a JPRIM INPLANE and a
// spherical joint give the same rows as those elements; degrees of freedom (rank, Gruebler,
// redundancy); and the data-set checks.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/constraint_derivative_check.hpp"
#include "support/random_state.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;
using testing::turned;
using testing::randomState;


model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "gcon.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

std::string errorsOf(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "gcon.adm", ds, d);
  model::Model m;
  model::buildModel(ds, m, d);
  std::string out;
  for (const auto& x : d.all()) out += format(x) + "\n";
  return out;
}

const char* kTwoParts =
    "gcon\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0.5,0.2,0.1, REULER=20D,10D,5D\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=1.2,-1.6,0\n"
    "MARKER/21, PART=2, QP=1,-1,0.2, REULER=30D,15D,-10D\n"
    "PART/3, MASS=2, CM=30, IP=1,2,3\n"
    "MARKER/30, PART=3, QP=2,-1,0.5\n"
    "MARKER/31, PART=3, QP=2.2,-0.8,0.4, REULER=-40D,25D,30D\n";

// Rows, Newton matrix and rates of every equation against central differences.
void checkDerivatives(const MultibodySystem& s, const model::Model& m, unsigned seed) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 3; ++trial)
    testing::checkConstraintRows(s, m, randomState(s, rng), 0.0);
  const int n = s.layout().size();
  const Eigen::VectorXd y = randomState(s, rng);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
  const double worst = testing::checkNewtonMatrix(s, 0.2, y, yp, 21.0, "gcon");
  std::printf("GCON Newton matrix vs central differences: worst %.2e\n", worst);
  testing::checkConstraintRates(s, m, y, 0.0);
}

TEST(Gcon, NonlinearFunctionsOfPositionsAndAnglesHaveExactDerivatives) {
  // Every position measure a GCON may read, on three markers and two moving parts, composed
  // with non-linear functions (powers, SIN, a product of two angles, a spline-free IF-free mix).
  const model::Model m = build(
      std::string(kTwoParts) +
      "GCON/1, I=20, FUNCTION=DX(20,10)**2+DY(20,10)**2-4+0.3*DZ(20,11,11)\n"
      "GCON/2, I=21, FUNCTION=AZ(21,31)+0.3*SIN(AX(21,31))-0.2*AY(31,21)*PSI(21,11)\n"
      "GCON/3, FUNCTION=DM(21,30)*COS(YAW(21,30))-PITCH(31)+ROLL(21,31)*THETA(30,11)"
      "+PHI(31,21)**2\n"
      "END\n");
  ASSERT_EQ(m.gcons.size(), 3u);
  MultibodySystem s(m);
  ASSERT_EQ(s.constraints().size(), 3);
  EXPECT_EQ(s.constraints().describe(1, m), "GCON/2 equation FUNCTION=0");
  checkDerivatives(s, m, 7);
}

// A GCON's row is that of the element it restates: DZ(I, J, J) = 0 is the JPRIM INPLANE
// equation zJ.(P_I - P_J) = 0, and DX, DY, DZ of I relative to J in ground are the three
// equations of a spherical joint.
TEST(Gcon, RestatedJointsHaveTheJointsRows) {
  const model::Model m = build(std::string(kTwoParts) +
                               "JPRIM/1, INPLANE, I=20, J=11\n"
                               "GCON/1, I=20, FUNCTION=DZ(20,11,11)\n"
                               "JOINT/2, SPHERICAL, I=30, J=21\n"
                               "GCON/2, I=30, FUNCTION=DX(30,21)\n"
                               "GCON/3, I=30, FUNCTION=DY(30,21)\n"
                               "GCON/4, I=30, FUNCTION=DZ(30,21)\n"
                               "END\n");
  MultibodySystem s(m);
  ASSERT_EQ(s.constraints().size(), 8);
  // Equation order: joints, primitives, ..., GCONs last.
  const auto& eqs = s.constraints().equations();
  std::vector<int> joint, jprim, gcon;
  for (int k = 0; k < s.constraints().size(); ++k) {
    if (eqs[k].joint >= 0) joint.push_back(k);
    if (eqs[k].jprim >= 0) jprim.push_back(k);
    if (eqs[k].gcon >= 0) gcon.push_back(k);
  }
  ASSERT_EQ(joint.size(), 3u);
  ASSERT_EQ(jprim.size(), 1u);
  ASSERT_EQ(gcon.size(), 4u);
  std::mt19937 rng(11);
  const int nb = s.layout().bodies;
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd y = randomState(s, rng);
    std::vector<double> a(6 * nb), b(6 * nb);
    auto same = [&](int ka, int kb) {
      EXPECT_NEAR(s.constraintValue(ka, 0.0, y.data()), s.constraintValue(kb, 0.0, y.data()),
                  1e-14);
      s.constraintRow(ka, y.data(), a.data());
      s.constraintRow(kb, y.data(), b.data());
      for (int c = 0; c < 6 * nb; ++c) EXPECT_NEAR(a[c], b[c], 1e-14) << ka << " " << kb;
      double fa, sa, fb, sb;
      s.constraintRates(ka, y.data(), &fa, &sa);
      s.constraintRates(kb, y.data(), &fb, &sb);
      EXPECT_NEAR(fa, fb, 1e-13);
      EXPECT_NEAR(sa, sb, 1e-13);
    };
    same(jprim[0], gcon[0]);
    for (int c = 0; c < 3; ++c) same(joint[c], gcon[1 + c]);
  }
  // Each restatement duplicates its element: the four GCON equations are redundant, removed
  // (later statements give way), and the DOF are those of the joint and primitive alone.
  const Eigen::VectorXd y0 = s.initialState();
  const auto red = removeRedundantConstraints(s, y0);
  EXPECT_EQ(red.removed, gcon);
  EXPECT_EQ(12 - red.rank, 12 - 4);
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 12 - 8);
}

TEST(Gcon, DistancePendulumHasOneDegreeOfFreedomInItsPlane) {
  const model::Model m = build(
      "pendulum by GCON\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=0.59104,-1.91067,0\n"
      "GCON/1, I=20, FUNCTION=DX(20,10)**2+DY(20,10)**2-4\n"
      "GCON/2, I=20, FUNCTION=DZ(20,10)\n"
      "END\n");
  MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState();
  const auto red = removeRedundantConstraints(s, y);
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(red.rank, 2);
  // 6 - 2: the swing and the three free rotations of the body about its CM.
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 4);
  checkDerivatives(s, m, 5);
}

TEST(Gcon, DataSetChecks) {
  const std::string base = std::string(kTwoParts);
  std::string e = errorsOf(base + "GCON/1, I=20, FUNCTION=DX(20,10)-VX(20,10)\nEND\n");
  EXPECT_NE(e.find("GCON/1: VX at column 11 of the expression cannot appear in a GCON"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("gcon.adm:11:34: error"), std::string::npos) << e;
  e = errorsOf(base + "GCON/1, FUNCTION=DX(20,10)-TIME\nEND\n");
  EXPECT_NE(e.find("GCON/1: the FUNCTION depends on TIME"), std::string::npos) << e;
  e = errorsOf(base + "GCON/1, I=20, J=10, FUNCTION=DX(20,10)\nEND\n");
  EXPECT_NE(e.find("GCON/1: GCON has no J marker"), std::string::npos) << e;
  e = errorsOf(base + "GCON/1, I=99, FUNCTION=DX(20,98)\nEND\n");
  EXPECT_NE(e.find("I=99: marker 99 does not exist"), std::string::npos) << e;
  EXPECT_NE(e.find("DX: marker 98 does not exist"), std::string::npos) << e;
  e = errorsOf(base + "GCON/1, FUNCTION=USER(1,2)\nEND\n");
  EXPECT_NE(e.find("(GCOSUB) is not supported yet"), std::string::npos) << e;
  e = errorsOf(base + "GCON/1, FUNCTION=2.5\nEND\n");
  EXPECT_NE(e.find("the FUNCTION reads no marker"), std::string::npos) << e;
  // Outside a GCON, AX/AY/AZ are cumulative (mechanics/expression_run_state.hpp) and accepted.
  e = errorsOf(base + "SFORCE/1, ROTATION, I=21, J=11, FUNCTION=-AZ(21,11)\nEND\n");
  EXPECT_EQ(e.find("AZ"), std::string::npos) << e;
}

}  // namespace
}  // namespace openmss::mechanics
