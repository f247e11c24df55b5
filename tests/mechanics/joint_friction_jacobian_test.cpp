// FRICTION's Newton matrix (docs/theory.md, "Joint friction") against central differences of
// the residual: the friction force reads the joint's multipliers (normal force), the relative
// velocity (slip) and the creep since the stiction anchor, so every regime of the law and every
// joint kind is checked — dynamic, transition (STEP between mu_s and mu_d), static with the
// creep spring inside and at its saturation, EFFECT=SLIDING below the transition velocity and
// EFFECT=STICTION in its band — and the structural sparse pattern must cover every nonzero.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "mechanics/expression_run_state.hpp"
#include "mechanics/friction/joint_friction.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/multibody_system.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

// Two free bodies joined by one joint with FRICTION; J on part 2, I on part 3.
model::Model frictionModel(const std::string& joint, const std::string& extra) {
  return test::buildModelFromText(
      "friction jacobian\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,2,3, QG=0.1,0.2,0.3\nMARKER/20, PART=2\n"
      "MARKER/21, PART=2, QP=0.5,-0.2,0.1, REULER=10D,20D,30D\n"
      "PART/3, MASS=3, CM=30, IP=2,1,1.5, QG=0.7,0.1,0.4\nMARKER/30, PART=3\n"
      "MARKER/31, PART=3, QP=-0.1,-0.1,0.0, REULER=10D,20D,30D\n"
      "JOINT/1, " +
          joint +
          ", I=31, J=21\n"
          "FRICTION/1, JOINT=1, MU_STATIC=0.5, MU_DYNAMIC=0.3" +
          extra +
          "\n"
          "ACCGRAV/ JGRAV=-9.81\nEND\n",
      "f.adm");
}

// |slip| over the joint's free channels at y (no anchor).
double slipMagnitude(const model::Model& m, const Eigen::VectorXd& y) {
  MultibodySystem s(m);
  const friction::FrictionKinematics<double> k =
      friction::frictionKinematics(m, s.layout(), m.frictions[0], y.data(), nullptr);
  double s2 = 0.0;
  for (int c = 0; c < 6; ++c)
    if (k.channels.free[c]) s2 += k.slip[c] * k.slip[c];
  return std::sqrt(s2);
}

struct Case {
  const char* name;
  int regime;          // expected: 0 static, 1 transition, 2 dynamic
  double vsOverSlip;   // STICTION_TRANSITION_VELOCITY / |slip|
  double deformation;  // MAX_STICTION_DEFORMATION
  model::Friction::Effect effect;
};

// A random state near the data set's configuration y0: velocities and multipliers of order
// one, positions 1/20 of randomState's offsets (so that the creep can stay inside the spring).
Eigen::VectorXd nearState(const MultibodySystem& s, int seed) {
  std::mt19937 rng(seed);
  const Eigen::VectorXd y0 = s.initialState();
  Eigen::VectorXd y = testing::randomState(s, rng);
  for (int b = 0; b < s.layout().bodies; ++b) {
    const int o = s.layout().body(b);
    for (int k = 0; k < 7; ++k) y(o + k) = y0(o + k) + 0.05 * (y(o + k) - y0(o + k));
    y.segment<4>(o + StateLayout::kE).normalize();
  }
  return y;
}

// One check: the state's slip sets the transition velocity of the case; the anchor is the data
// set's configuration (accepted first), so the creep is the displacement from it.
double checkCase(const std::string& joint, const std::string& extra, const Case& c, int seed,
                 int* compared) {
  model::Model m = frictionModel(joint, extra);
  {
    const MultibodySystem probe(m);
    const double slip = slipMagnitude(m, nearState(probe, seed));
    m.frictions[0].stictionVelocity = c.vsOverSlip * slip;
    m.frictions[0].maxStictionDeformation = c.deformation;
    m.frictions[0].effect = c.effect;
  }
  MultibodySystem s(m);
  ExpressionRunState run(m);
  s.setRunState(&run);
  const Eigen::VectorXd y0 = s.initialState();
  run.accept(s, 0.0, y0, Eigen::VectorXd::Zero(y0.size()));
  const Eigen::VectorXd y = nearState(s, seed);
  std::mt19937 again(seed + 1000);
  Eigen::VectorXd yp(y.size());
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < yp.size(); ++i) yp(i) = u(again);
  const friction::FrictionResult<double> r =
      friction::frictionLoads(m, s.layout(), &s.constraints(), 0, y.data(), run.frictionAnchor(0),
                              run.status().mode);
  EXPECT_EQ(r.regime, c.regime) << joint << " " << c.name;
  EXPECT_GT(r.normal, 0.0) << joint << " " << c.name;
  Eigen::MatrixXd jac;
  const double worst = testing::checkNewtonMatrix(s, 0.0, y, yp, 23.0, joint + " " + c.name, &jac);
  // The structural pattern covers every nonzero, with no dense row.
  const JacobianPattern p = newtonMatrixPattern(s);
  EXPECT_EQ(p.denseRows, 0);
  Eigen::MatrixXi in = Eigen::MatrixXi::Zero(p.size, p.size);
  for (int col = 0; col < p.size; ++col)
    for (int k = p.columnStart[col]; k < p.columnStart[col + 1]; ++k) in(p.rowIndex[k], col) = 1;
  for (int row = 0; row < p.size; ++row)
    for (int col = 0; col < p.size; ++col)
      if (jac(row, col) != 0.0) {
        EXPECT_EQ(in(row, col), 1) << joint << " " << row << "," << col;
      }
  *compared += static_cast<int>(jac.size());
  return worst;
}

TEST(JointFrictionJacobian, EveryRegimeAndJointKindMatchesCentralDifferences) {
  using E = model::Friction::Effect;
  const Case cases[] = {
      {"dynamic", 2, 0.2, 0.01, E::All},
      {"transition", 1, 0.8, 0.01, E::All},
      {"static, creep inside the spring", 0, 1e3, 1e3, E::All},
      {"static, creep saturated", 0, 2.0, 1e-4, E::All},
      {"sliding below the transition velocity", 1, 2.0, 0.01, E::Sliding},
      {"stiction in its band", 1, 0.8, 0.01, E::Stiction},
  };
  const std::pair<std::string, std::string> joints[] = {
      {"TRANSLATIONAL", ", FRICTION_FORCE_PRELOAD=3, INITIAL_OVERLAP=0.4, FRICTION_ARM=0.2"},
      {"REVOLUTE", ", PIN_RADIUS=0.3, FRICTION_ARM=0.2, BENDING_REACTION_ARM=0.5"},
      {"CYLINDRICAL", ", PIN_RADIUS=0.3, INITIAL_OVERLAP=0.4, FRICTION_FORCE_PRELOAD=1"},
      {"SPHERICAL", ", BALL_RADIUS=0.2"},
      {"HOOKE", ", PIN_RADIUS=0.3, FRICTION_ARM=0.2, BENDING_REACTION_ARM=0.5"},
      {"UNIVERSAL", ", PIN_RADIUS=0.3, INPUTS=REACTION_FORCE:BENDING_MOMENT"},
  };
  double worst = 0.0;
  int compared = 0, seed = 11;
  for (const auto& [joint, extra] : joints)
    for (const Case& c : cases)
      worst = std::max(worst, checkCase(joint, extra, c, seed++, &compared));
  // 6 joint kinds x 6 regimes, each a full (2 bodies x 14 + multipliers)^2 matrix.
  EXPECT_GE(compared, 36 * 28 * 28);
  std::printf("joint friction Newton matrices: %d entries, largest relative difference %.2e\n",
              compared, worst);
}

}  // namespace
}  // namespace openmss::mechanics
