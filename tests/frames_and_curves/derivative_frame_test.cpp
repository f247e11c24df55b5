// The derivative-frame argument l of VX..VZ, VM, VR, ACCX..ACCM and WDTX..WDTM (docs/theory.md
// §11b) against independent truth:
//   (a) closed forms on a driven mechanism: a turntable turning by phi(t) = 2t + t^2/2 about
//       ground z, a slider on a slot of the turntable at s(t) = 0.5 + 0.3t + 0.2t^2, a disc
//       spinning at 3 rad/s about the slot: seen from the turntable, a point fixed on it has no
//       velocity or acceleration, the slider moves with s' and s'' along the slot, and the
//       disc's angular acceleration is the turntable's, phi'' z;
//   (b) central differences in time of the measures expressed in frame l (the components of
//       a vector in l's axes are differentiated in l): d/dt DX(i,j,l) = VX(i,j,l,l),
//       d/dt VX(i,j,l,l) = ACCX(i,j,l,l), d/dt WX(i,j,l) = WDTX(i,j,l,l);
//   (c) the Newton matrix of a free model whose forces read them against central differences.
// Each value is checked through both paths that evaluate it: REQUEST columns (the output
// code) and VARIABLEs (the DAE's functions).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "analysis/request_values.hpp"
#include "mechanics/initial_conditions.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

// Ground marker 10; turntable (part 2) on a revolute at the origin; slot marker 22 on it with
// z along (cos 30°, sin 30°, 0) (3-1-3 angles 120°, 90°, 0); point 23 fixed on the turntable
// at (1, 0, 0); slider (part 3) with marker 30 on the slot; disc (part 4) spinning about the slot.
const char* kMechanism =
    "frames\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=21, IP=1,1,1\n"
    "MARKER/21, PART=2\n"
    "MARKER/22, PART=2, REULER=120D,90D,0D\n"
    "MARKER/23, PART=2, QP=1,0,0\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1\n"
    "MARKER/30, PART=3, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "MARKER/31, PART=3, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "PART/4, MASS=1, CM=40, IP=1,2,3\n"
    "MARKER/40, PART=4, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, TRANSLATIONAL, I=30, J=22\n"
    "JOINT/3, REVOLUTE, I=40, J=31\n"
    "MOTION/1, JOINT=1, ROTATION, FUNCTION=2*TIME+0.5*TIME**2\n"
    "MOTION/2, JOINT=2, TRANSLATION, FUNCTION=0.5+0.3*TIME+0.2*TIME**2\n"
    "MOTION/3, JOINT=3, ROTATION, FUNCTION=3*TIME\n"
    // (a) point 23 seen from the turntable, and from ground for contrast.
    "REQUEST/1, F1=ACCM(23,10,22)\\F2=VX(23,10,22,22)\\F3=VY(23,10,22,22)\\F4=VZ(23,10,22,22)\\"
    "F5=ACCM(23,10)\\F6=ACCX(23,10,22,22)\\F7=ACCY(23,10,22,22)\\F8=ACCZ(23,10,22,22)\n"
    // (a) the slider along the slot.
    "REQUEST/2, F1=VM(30,22,22)\\F2=VX(30,22,22,22)\\F3=VY(30,22,22,22)\\F4=VZ(30,22,22,22)\\"
    "F5=ACCM(30,22,22)\\F6=ACCX(30,22,22,22)\\F7=ACCY(30,22,22,22)\\F8=ACCZ(30,22,22,22)\n"
    // (a) the disc's angular acceleration seen from the turntable, ground axes.
    "REQUEST/3, F1=WDTM(40,0,22)\\F2=WDTX(40,0,0,22)\\F3=WDTY(40,0,0,22)\\F4=WDTZ(40,0,0,22)\\"
    "F5=WDTM(40)\\F6=VR(30,10,22)\\F7=VR(30,10)\\F8=VM(23,10,22)\n"
    // (b) the same through the DAE's functions, with j and k not l: the slider from ground.
    "VARIABLE/1, FUNCTION=VZ(30,0,22,22)\n"
    "VARIABLE/2, FUNCTION=ACCZ(30,0,22,22)\n"
    "VARIABLE/3, FUNCTION=ACCX(30,0,22,22)\n"
    "VARIABLE/4, FUNCTION=WDTZ(40,0,0,22)\n"
    "VARIABLE/5, FUNCTION=WDTX(40,0,0,22)\n"
    "END\n";

struct Kinematic {
  model::Model model = test::buildModelFromText(kMechanism, "frames.adm");
  mechanics::MultibodySystem system{model};
  Eigen::VectorXd y, yp;
  // The fully driven mechanism's state at time t: positions, velocities and accelerations of
  // the motions, to the assembly's 1e-12.
  void at(double t) {
    y = system.initialState();
    ASSERT_TRUE(mechanics::assemblePositions(system, t, y, 1e-13, 50).converged);
    mechanics::solveVelocities(system, t, y);
    ASSERT_TRUE(mechanics::solveAccelerations(system, t, y, yp));
  }
  std::array<double, 8> request(int r, double t) const {
    return requestColumns(system, model.requests[r], t, y, yp);
  }
  double variable(int k) const { return y(system.layout().userAlg(k)); }
};

TEST(DerivativeFrame, ClosedFormsOnTheDrivenMechanism) {
  auto k = std::make_unique<Kinematic>();
  int compared = 0;
  for (double t : {0.0, 0.35, 0.8}) {
    k->at(t);
    const double w = 2.0 + t, alpha = 1.0, sd = 0.3 + 0.4 * t;
    // Assembly to 1e-12 and the linear velocity/acceleration solves: 1e-9 is round-off margin.
    const double tol = 1e-9;
    const auto p = k->request(0, t);
    EXPECT_NEAR(p[0], 0.0, tol);
    for (int c : {1, 2, 3, 5, 6, 7}) EXPECT_NEAR(p[c], 0.0, tol) << "t=" << t << " col " << c;
    // From ground the point has |a| = r sqrt(alpha^2 + w^4), r = 1.
    EXPECT_NEAR(p[4], std::sqrt(alpha * alpha + std::pow(w, 4)), tol);
    const auto q = k->request(1, t);
    EXPECT_NEAR(q[0], sd, tol);
    EXPECT_NEAR(q[1], 0.0, tol);
    EXPECT_NEAR(q[2], 0.0, tol);
    EXPECT_NEAR(q[3], sd, tol);
    EXPECT_NEAR(q[4], 0.4, tol);
    EXPECT_NEAR(q[5], 0.0, tol);
    EXPECT_NEAR(q[6], 0.0, tol);
    EXPECT_NEAR(q[7], 0.4, tol);
    const auto r = k->request(2, t);
    EXPECT_NEAR(r[0], alpha, tol);
    EXPECT_NEAR(r[1], 0.0, tol);
    EXPECT_NEAR(r[2], 0.0, tol);
    EXPECT_NEAR(r[3], alpha, tol);
    // From ground the spin axis turns: w' = alpha z + 3 w (z x e), |w'| = sqrt(alpha^2 + 9 w^2).
    EXPECT_NEAR(r[4], std::sqrt(alpha * alpha + 9.0 * w * w), tol);
    // VR does not depend on the frame: the slider's distance from the origin is s.
    EXPECT_NEAR(r[5], sd, tol);
    EXPECT_NEAR(r[6], sd, tol);
    EXPECT_NEAR(r[7], 0.0, tol);  // VM of the turntable's own point seen from it
    // The DAE's functions: from the ground origin (on the turntable's axis) the slider is at
    // s along the slot, so the same closed forms hold.
    EXPECT_NEAR(k->variable(0), sd, tol);
    EXPECT_NEAR(k->variable(1), 0.4, tol);
    EXPECT_NEAR(k->variable(2), 0.0, tol);
    EXPECT_NEAR(k->variable(3), alpha, tol);
    EXPECT_NEAR(k->variable(4), 0.0, tol);
    compared += 29;
  }
  EXPECT_EQ(compared, 87);
}

// Components in l's axes of a vector measured between I and J: DX(i,j,l) and its derivative.
double component(const Kinematic& k, model::MeasureKind kind, int i, int j, int kl, int frame,
                 double t) {
  model::Measure ms;
  ms.kind = kind;
  ms.i = k.model.markerIndex.at(i);
  ms.j = j > 0 ? k.model.markerIndex.at(j) : -1;
  ms.k = k.model.markerIndex.at(kl);
  ms.l = frame > 0 ? k.model.markerIndex.at(frame) : -1;
  return measureValue(k.system, ms, t, k.y, k.yp);
}

TEST(DerivativeFrame, DerivativesOfTheComponentsInFrameL) {
  using K = model::MeasureKind;
  auto k = std::make_unique<Kinematic>();
  const double t = 0.6, h = 1e-5;
  // (position kind, its derivative in l) for each axis, of the disc's point 40 from ground
  // marker 10, and the disc's angular velocity, all in the axes of the slot marker 22.
  const K pos[3] = {K::DX, K::DY, K::DZ}, vel[3] = {K::VX, K::VY, K::VZ};
  const K acc[3] = {K::ACCX, K::ACCY, K::ACCZ}, ang[3] = {K::WX, K::WY, K::WZ};
  const K wdt[3] = {K::WDTX, K::WDTY, K::WDTZ};
  double worst = 0.0;
  int compared = 0;
  // The point 23 of the turntable seen from the slider's marker 31 (a moving, turning frame on
  // another part), so that d, d' and w_l are all non-trivial.
  for (int c = 0; c < 3; ++c) {
    auto rate = [&](K kind, int i, int j) {
      k->at(t + h);
      const double up = component(*k, kind, i, j, 31, 0, t + h);
      k->at(t - h);
      const double down = component(*k, kind, i, j, 31, 0, t - h);
      return (up - down) / (2 * h);
    };
    auto rateL = [&](K kind, int i, int j) {
      k->at(t + h);
      const double up = component(*k, kind, i, j, 31, 31, t + h);
      k->at(t - h);
      const double down = component(*k, kind, i, j, 31, 31, t - h);
      return (up - down) / (2 * h);
    };
    const double dPos = rate(pos[c], 23, 10), dVel = rateL(vel[c], 23, 10),
                 dAng = rate(ang[c], 40, 0);
    k->at(t);
    const double v = component(*k, vel[c], 23, 10, 31, 31, t);
    const double a = component(*k, acc[c], 23, 10, 31, 31, t);
    const double wd = component(*k, wdt[c], 40, 0, 31, 31, t);
    // h = 1e-5: truncation h^2/6 |f'''| ~ 1e-9, round-off 1e-13/h = 1e-8; 1e-7 leaves margin.
    EXPECT_NEAR(v, dPos, 1e-7) << "component " << c;
    EXPECT_NEAR(a, dVel, 1e-7) << "component " << c;
    EXPECT_NEAR(wd, dAng, 1e-7) << "component " << c;
    worst = std::max({worst, std::abs(v - dPos), std::abs(a - dVel), std::abs(wd - dAng)});
    compared += 3;
    // In ground the same components differ (the frame turns) except along 31's y axis, which is
    // ground z, the turning axis: the check can fail.
    const double vGround = component(*k, vel[c], 23, 10, 31, 0, t);
    if (c != 1) {
      EXPECT_GT(std::abs(vGround - v), 1e-1) << "component " << c;
    }
  }
  EXPECT_EQ(compared, 9);
  std::printf("frame-l derivatives vs central differences: largest difference %.2e\n", worst);
}

// A free model: a turntable with a torque, a slider on its slot held by a spring and a damper
// on the slot-frame velocity, an added-mass term on the slot-frame acceleration, and a disc
// whose spin torque reads its angular acceleration seen from the turntable.
const char* kFree =
    "frames free\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=21, IP=1,1,1\n"
    "MARKER/21, PART=2\n"
    "MARKER/22, PART=2, REULER=120D,90D,0D\n"
    // The slider starts at 0.5 along the slot (its magnitudes VM, ACCM in the turntable's frame
    // stay well away from 0, where central differences of |v| lose their accuracy).
    "PART/3, MASS=1, CM=30, IP=1,1,1, VX=0.4330127018922193, VY=0.25\n"
    "MARKER/30, PART=3, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "MARKER/31, PART=3, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "PART/4, MASS=1, CM=40, IP=1,2,3\n"
    "MARKER/40, PART=4, QP=0.4330127018922193,0.25,0, REULER=120D,90D,0D\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, TRANSLATIONAL, I=30, J=22\n"
    "JOINT/3, REVOLUTE, I=40, J=31\n"
    "SFORCE/1, ROTATIONAL, ACTIONONLY, I=21, J=10, FUNCTION=1-0.1*WZ(21)\n"
    "SFORCE/2, TRANSLATIONAL, I=30, J=22, FUNCTION=-4*(DZ(30,22,22)-0.5)-0.3*VZ(30,22,22,22)"
    "-0.5*ACCZ(30,22,22,22)+0.2*VX(30,10,22,22)\n"
    "SFORCE/3, ROTATIONAL, I=40, J=31, FUNCTION=-0.2*WDTZ(40,0,22,22)-0.1*ACCY(40,10,0,21)\n"
    "VARIABLE/1, FUNCTION=VM(30,10,22)+ACCM(30,10,22)+WDTM(40,0,22)\n"
    "END\n";

TEST(DerivativeFrame, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = test::buildModelFromText(kFree, "free.adm");
  test::BdfRun run(m, 1e-6, 0.01, true);
  run.start();
  run.advanceTo(0.3);  // a generic state: the turntable turning, the slider moving
  Eigen::VectorXd y = run.y(), yp = run.yp();
  // Perturb y' off the solution so that every acceleration term has a nonzero value.
  for (int c = 0; c < yp.size(); ++c) yp(c) += 0.01 * std::sin(1.0 + c);
  Eigen::MatrixXd jac;
  const double worst = testing::checkNewtonMatrix(run.system(), 0.3, y, yp, 23.0, "frame l", &jac);
  const int nonzeros = testing::expectPatternCovers(run.system(), jac);
  EXPECT_GT(nonzeros, 50);
  std::printf("frame-l Newton matrix: largest relative difference %.2e, %d nonzeros covered\n",
              worst, nonzeros);
}

}  // namespace
}  // namespace openmss::analysis
