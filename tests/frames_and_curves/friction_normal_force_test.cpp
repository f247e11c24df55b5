// FRICTION's normal force where reaction components vanish (docs/theory.md §13, "Normal
// force"): the Newton matrix against central differences of the residual in every column, the
// joint's multipliers included. With |v| in the normal force, a multiplier that is zero up to
// round-off gave the Newton matrix the slope sign(round-off) = +-1 in its column while the
// residual, symmetric about zero, has none (the "multiplier columns" defect); the magnitudes
// are now rounded at kNormalForceRounding. (The regimes of the law, at random states with
// multipliers of order one: tests/mechanics/joint_friction_jacobian_test.cpp.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "mechanics/multibody_system.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

// Two free bodies joined by one joint with FRICTION; J on part 2, I on part 3 (as
// joint_friction_jacobian_test.cpp).
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
          "FRICTION/1, JOINT=1, MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=0.01" +
          extra +
          "\n"
          "ACCGRAV/ JGRAV=-9.81\nEND\n",
      "f.adm");
}

// A random state near the data set's configuration: velocities and multipliers of order one.
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

// Each joint kind at a random state with STICTION_TRANSITION_VELOCITY = 0.01 (the slip, of
// order one, is in the dynamic regime) whose multipliers are all +-1e-40 but the first (which
// carries the load): every column of the Newton matrix.
TEST(FrictionNormalForce, VanishingReactionComponentsAddNoSlopeInTheirColumns) {
  const std::pair<std::string, std::string> joints[] = {
      {"TRANSLATIONAL", ", FRICTION_FORCE_PRELOAD=3, INITIAL_OVERLAP=0.4, FRICTION_ARM=0.2"},
      {"REVOLUTE", ", PIN_RADIUS=0.3, FRICTION_ARM=0.2, BENDING_REACTION_ARM=0.5"},
      {"CYLINDRICAL", ", PIN_RADIUS=0.3, INITIAL_OVERLAP=0.4"},
      {"SPHERICAL", ", BALL_RADIUS=0.2"},
      {"HOOKE", ", PIN_RADIUS=0.3, FRICTION_ARM=0.2, BENDING_REACTION_ARM=0.5"},
      {"UNIVERSAL", ", PIN_RADIUS=0.3"},
  };
  double worst = 0.0;
  int multiplierColumns = 0, seed = 101;
  for (const auto& [joint, extra] : joints) {
    const model::Model m = frictionModel(joint, extra);
    MultibodySystem s(m);
    Eigen::VectorXd y = nearState(s, seed);
    std::mt19937 rng(seed++);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd yp(y.size());
    for (int i = 0; i < yp.size(); ++i) yp(i) = u(rng);
    const StateLayout& l = s.layout();
    for (int k = 1; k < s.constraints().size(); ++k) y(l.lambda(k)) = (k % 2 == 0 ? 1e-40 : -1e-40);
    worst = std::max(worst, testing::checkNewtonMatrix(s, 0.0, y, yp, 23.0, joint));
    multiplierColumns += s.constraints().size();
  }
  // Every joint has at least 2 equations (a spherical joint 3, a translational 5).
  EXPECT_GE(multiplierColumns, 6 * 2);
  std::printf(
      "joint friction with vanishing reactions: %d multiplier columns, largest relative "
      "difference %.2e\n",
      multiplierColumns, worst);
}

// The block sliding down a 30 degree slope on a TRANSLATIONAL joint (the case that showed the
// defect): at a state the integrator reached, the joint's torque multipliers are round-off.
// Every column of the Newton matrix against central differences.
TEST(FrictionNormalForce, SlidingBlockMatchesCentralDifferencesInEveryColumn) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  char axes[96];
  std::snprintf(axes, sizeof axes, "ZP=%.17g,%.17g,0, XP=%.17g,%.17g,0", c, -s, s, c);
  const model::Model m = test::buildModelFromText(
      std::string("sliding block\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1, ") + axes +
          "\nPART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, " + axes +
          "\nJOINT/1, TRANSLATIONAL, I=20, J=10\nFRICTION/1, JOINT=1, MU_STATIC=0.3, "
          "MU_DYNAMIC=0.25, STICTION_TRANSITION_VELOCITY=0.01, MAX_STICTION_DEFORMATION=1e-4\n"
          "ACCGRAV/ JGRAV=-9.81\nEND\n",
      "block.adm");
  test::BdfRun run(m, 1e-7, 0.01, true);
  run.start();
  run.advanceTo(0.4);  // sliding at about 1.1 m/s
  const auto& sys = run.system();
  const StateLayout& l = sys.layout();
  int roundOff = 0;
  for (int k = 0; k < sys.constraints().size(); ++k)
    if (std::abs(run.y()(l.lambda(k))) < 1e-20) ++roundOff;
  EXPECT_GE(roundOff, 1);  // the degenerate case is there
  const double worst = testing::checkNewtonMatrix(sys, 0.4, run.y(), run.yp(), 23.0, "block");
  std::printf(
      "sliding block with FRICTION: %d of %d multipliers at round-off, Newton matrix "
      "over all %d columns within %.2e of central differences\n",
      roundOff, sys.constraints().size(), l.size(), worst);
}

}  // namespace
}  // namespace openmss::mechanics
