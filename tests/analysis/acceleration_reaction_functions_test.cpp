// Force and VARIABLE functions that read accelerations, joint reactions and ORIENT
// (docs/theory.md §4b), against closed forms and an independent integration:
//   (a) an added-mass SFORCE -ma * ACCZ on a mass-spring: frequency sqrt(k / (m + ma));
//   (b) a VARIABLE reading a pendulum's revolute reaction: the rod tension m (g cos a + L w^2),
//       and a torque proportional to it, against RK4 on the pendulum's own equation;
//   (c) ORIENT in VARIABLEs against the Euler parameters and 1-2-3 angles of a spinning body;
// and the Newton matrix of every such model against central differences, with the structural
// sparse pattern covering it.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

model::Model build(const std::string& text) { return test::buildModelFromText(text, "dyn.adm"); }

// Initial conditions as a run makes them, then GSTIFF-style BDF; outputs made consistent.
class DynamicRun : public test::BdfRun {
 public:
  DynamicRun(const model::Model& m, double error) : BdfRun(m, error, 0.01, true) {}
};

using testing::expectPatternCovers;

const double kMass = 2.0, kAdded = 2.0, kStiffness = 8.0, kStart = 0.5;

// A mass on a vertical translational joint, a spring -k z and an added-mass force -ma z''
// (action-only SFORCE along z_J): (m + ma) z'' = -k z, z(0) = 0.5, z'(0) = 0, so
// z = 0.5 cos(w t), w = sqrt(k / (m + ma)) = sqrt(2). Without the added mass w would be 2.
std::string addedMassModel() {
  return "added mass\n"
         "UNITS/ SYSTEM=NONE\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1\n"
         "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,0.5\n"
         "MARKER/20, PART=2\n"
         "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
         "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=-8*DZ(20,10) - 2*ACCZ(20)\n"
         "VARIABLE/1, FUNCTION=ACCZ(20,10,10)\n"
         "END\n";
}

TEST(AccelerationFunctions, AddedMassGivesTheLowerFrequency) {
  const model::Model m = build(addedMassModel());
  DynamicRun run(m, 1e-8);
  EXPECT_TRUE(mechanics::readsAccelerationsOrReactions(m));
  // The coupled initial solve: z''(0) = -k z0 / (m + ma) = -1, exactly (a linear system).
  EXPECT_NEAR(run.variable(0), -kStiffness * kStart / (kMass + kAdded), 1e-12);
  run.start();
  const double w = std::sqrt(kStiffness / (kMass + kAdded));
  double worst = 0.0;
  for (double t : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0}) {
    run.advanceTo(t);
    const double z = run.body(0, mechanics::StateLayout::kR + 2);
    worst = std::max(worst, std::abs(z - kStart * std::cos(w * t)));
    // ERROR = 1e-8 holds the global error over 5 s (about 1.1 periods) below 1e-6.
    EXPECT_NEAR(z, kStart * std::cos(w * t), 1e-6) << "t=" << t;
    EXPECT_NEAR(run.variable(0), -kStart * w * w * std::cos(w * t), 1e-5) << "t=" << t;
  }
  std::printf("added mass: largest |z - 0.5 cos(sqrt(2) t)| over 5 s = %.2e\n", worst);
}

TEST(AccelerationFunctions, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = build(addedMassModel());
  DynamicRun run(m, 1e-8);
  Eigen::VectorXd y = run.y(), yp = run.yp();
  y(run.system().layout().body(0) + mechanics::StateLayout::kV + 2) = 0.3;
  yp(run.system().layout().body(0) + mechanics::StateLayout::kV + 2) = -0.7;
  Eigen::MatrixXd jac;
  const double worst = testing::checkNewtonMatrix(run.system(), 0.0, y, yp, 37.0, "added mass",
                                                  &jac);
  std::printf("added mass Newton matrix: largest relative difference %.2e\n", worst);
  // The SFORCE row reads z'' through y' of the velocity: cj * ma in the z force row.
  const auto& l = run.system().layout();
  const int vz = l.body(0) + mechanics::StateLayout::kV + 2;
  EXPECT_NEAR(jac(vz, vz), 37.0 * (kMass + kAdded), 1e-9);
  expectPatternCovers(run.system(), jac);
}

// A pendulum (m = 1, L = 1, Izz = 0.1 about the CM) on a revolute joint at the origin, gravity
// -y, released at a0 = 60 degrees from the downward vertical. VARIABLE/1 is the rod tension from
// the joint reaction on the pendulum; SFORCE/1 a torque -c * VARVAL(1) about z. The pendulum's
// own equation: (m L^2 + Izz) a'' = -m g L sin a - c m (g cos a + L a'^2).
std::string pendulumModel(double c) {
  const double a0 = std::numbers::pi / 3.0;
  return "pendulum\n"
         "UNITS/ SYSTEM=NONE\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1\n"
         "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
         "MARKER/20, PART=2, QP=" +
         std::to_string(std::sin(a0)) + "," + std::to_string(-std::cos(a0)) +
         ",0\n"
         "MARKER/21, PART=2\n"
         "JOINT/1, REVOLUTE, I=21, J=10\n"
         "ACCGRAV/ JGRAV=-9.81\n"
         "VARIABLE/1, FUNCTION=-(JOINT(1,0,2,0)*DX(20,21) + JOINT(1,0,3,0)*DY(20,21))/DM(20,21)\n"
         "SFORCE/1, ROTATIONAL, I=21, J=10, FUNCTION=-" +
         std::to_string(c) +
         "*VARVAL(1)\n"
         "END\n";
}

// The angle from the downward vertical and its rate, from the CM position and velocity.
// The rod length is |CM - pivot| (1 to the 6 digits the data set is written with).
void pendulumAngle(const DynamicRun& run, double* a, double* w, double* length = nullptr) {
  using L = mechanics::StateLayout;
  const double x = run.body(0, L::kR), y = run.body(0, L::kR + 1);
  const double vx = run.body(0, L::kV), vy = run.body(0, L::kV + 1);
  *a = std::atan2(x, -y);
  *w = (x * vy - y * vx) / (x * x + y * y);
  if (length) *length = std::sqrt(x * x + y * y);
}

TEST(ReactionFunctions, VariableReadsTheRodTension) {
  const double g = 9.81;
  const model::Model m = build(pendulumModel(0.0));
  DynamicRun run(m, 1e-8);
  double a = 0.0, w = 0.0;
  pendulumAngle(run, &a, &w);
  // The input has 6 digits: a0 is 60 degrees to 1e-6.
  EXPECT_NEAR(run.variable(0), g * std::cos(a), 1e-9);
  run.start();
  double worst = 0.0;
  for (double t : {0.2, 0.5, 1.0, 1.5, 2.0}) {
    run.advanceTo(t);
    run.projectVelocities(t);
    double length = 1.0;
    pendulumAngle(run, &a, &w, &length);
    const double tension = g * std::cos(a) + length * w * w;  // m = 1
    worst = std::max(worst, std::abs(run.variable(0) - tension));
    // Exact for the state reached (the reaction is solved at the output), to round-off.
    EXPECT_NEAR(run.variable(0), tension, 1e-8) << "t=" << t;
  }
  std::printf("rod tension: largest |JOINT - m(g cos a + L w^2)| = %.2e\n", worst);
}

TEST(ReactionFunctions, TorqueFromTheReactionFollowsThePendulumEquation) {
  const double g = 9.81, c = 0.2, inertia = 1.1;  // m L^2 + Izz
  const model::Model m = build(pendulumModel(c));
  DynamicRun run(m, 1e-8);
  double a = 0.0, w = 0.0;
  pendulumAngle(run, &a, &w);
  // Independent truth: classical RK4 on a'' = (-g sin a - c (g cos a + a'^2)) / 1.1, h = 1e-4
  // (global error ~1e-13 over 2 s).
  auto rate = [&](double aa, double ww) {
    return (-g * std::sin(aa) - c * (g * std::cos(aa) + ww * ww)) / inertia;
  };
  double ra = a, rw = w, t = 0.0;
  run.start();
  double worst = 0.0;
  for (double tout : {0.5, 1.0, 1.5, 2.0}) {
    const double h = 1e-4;
    while (t < tout - 1e-12) {
      const double k1a = rw, k1w = rate(ra, rw);
      const double k2a = rw + 0.5 * h * k1w, k2w = rate(ra + 0.5 * h * k1a, rw + 0.5 * h * k1w);
      const double k3a = rw + 0.5 * h * k2w, k3w = rate(ra + 0.5 * h * k2a, rw + 0.5 * h * k2w);
      const double k4a = rw + h * k3w, k4w = rate(ra + h * k3a, rw + h * k3w);
      ra += h / 6.0 * (k1a + 2 * k2a + 2 * k3a + k4a);
      rw += h / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
      t += h;
    }
    run.advanceTo(tout);
    pendulumAngle(run, &a, &w);
    worst = std::max(worst, std::abs(a - ra));
    // BDF at ERROR = 1e-8: global angle error measured below 1e-6 over 2 s; asserted 1e-5.
    EXPECT_NEAR(a, ra, 1e-5) << "t=" << tout;
    EXPECT_NEAR(w, rw, 1e-5) << "t=" << tout;
  }
  std::printf("reaction torque: largest |a - a_RK4| over 2 s = %.2e\n", worst);
}

TEST(ReactionFunctions, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = build(pendulumModel(0.2));
  DynamicRun run(m, 1e-8);
  Eigen::VectorXd y = run.y(), yp = run.yp();
  const auto& l = run.system().layout();
  y(l.body(0) + mechanics::StateLayout::kW + 2) = 1.3;  // a swinging state
  for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) += 0.1 * (k + 1);
  Eigen::MatrixXd jac;
  const double worst =
      testing::checkNewtonMatrix(run.system(), 0.0, y, yp, 23.0, "pendulum", &jac);
  std::printf("reaction Newton matrix: largest relative difference %.2e\n", worst);
  expectPatternCovers(run.system(), jac);
}

// A body spinning freely at w = 2 rad/s about the body axis n = (2, 3, 6)/7 from the identity:
// its Euler parameters are (cos(w t / 2), sin(w t / 2) n). ORIENT(27, k, 20) reads them and
// ORIENT(1, k, 20) the body 1-2-3 angles of the same rotation matrix.
std::string spinningModel() {
  return "spinning body\n"
         "UNITS/ SYSTEM=NONE\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1\n"
         "PART/2, MASS=1, CM=20, IP=1,1,1, WX=0.571428571428571, WY=0.857142857142857,"
         " WZ=1.71428571428571\n"
         "MARKER/20, PART=2\n"
         "VARIABLE/1, FUNCTION=ORIENT(27,1,20,10)\n"
         "VARIABLE/2, FUNCTION=ORIENT(27,2,20,10)\n"
         "VARIABLE/3, FUNCTION=ORIENT(27,3,20,10)\n"
         "VARIABLE/4, FUNCTION=ORIENT(27,4,20,10)\n"
         "VARIABLE/5, FUNCTION=ORIENT(1,1,20)\n"
         "VARIABLE/6, FUNCTION=ORIENT(1,2,20)\n"
         "VARIABLE/7, FUNCTION=ORIENT(1,3,20)\n"
         "SFORCE/1, ROTATIONAL, I=20, J=10, FUNCTION=-0*VARVAL(2) - 0*ORIENT(1,2,20)\n"
         "END\n";
}

TEST(OrientFunctions, VariablesMatchTheRotation) {
  const model::Model m = build(spinningModel());
  DynamicRun run(m, 1e-10);
  run.start();
  const double w = 2.0;
  const Eigen::Vector3d n(2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0);
  double worst = 0.0;
  for (double t : {0.3, 1.0, 2.0}) {
    run.advanceTo(t);
    // An isotropic body's angular velocity stays constant: q = (cos(wt/2), sin(wt/2) n).
    // ORIENT(27, ...) returns the representative with e0 >= 0 (q and -q are one rotation).
    const double sign = std::cos(w * t / 2) < 0.0 ? -1.0 : 1.0;
    const Eigen::Vector4d q = sign * Eigen::Vector4d(std::cos(w * t / 2), std::sin(w * t / 2) * n(0),
                                                     std::sin(w * t / 2) * n(1),
                                                     std::sin(w * t / 2) * n(2));
    for (int k = 0; k < 4; ++k) {
      worst = std::max(worst, std::abs(run.variable(k) - q(k)));
      EXPECT_NEAR(run.variable(k), q(k), 1e-7) << "t=" << t << " e" << k;
    }
    const Eigen::Matrix3d r = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).toRotationMatrix();
    // Body 1-2-3: R = Rx(a) Ry(b) Rz(c): b = asin R13, a = atan2(-R23, R33), c = atan2(-R12, R11).
    EXPECT_NEAR(run.variable(4), std::atan2(-r(1, 2), r(2, 2)), 1e-7) << "t=" << t;
    EXPECT_NEAR(run.variable(5), std::asin(r(0, 2)), 1e-7) << "t=" << t;
    EXPECT_NEAR(run.variable(6), std::atan2(-r(0, 1), r(0, 0)), 1e-7) << "t=" << t;
  }
  std::printf("ORIENT: largest Euler-parameter error over 2 s = %.2e\n", worst);
  // The exact partials of ORIENT in VARIABLE and SFORCE rows.
  Eigen::MatrixXd jac;
  const double diff =
      testing::checkNewtonMatrix(run.system(), 2.0, run.y(), run.yp(), 11.0, "orient", &jac);
  std::printf("ORIENT Newton matrix: largest relative difference %.2e\n", diff);
  expectPatternCovers(run.system(), jac);
}

}  // namespace
}  // namespace openmss::analysis
