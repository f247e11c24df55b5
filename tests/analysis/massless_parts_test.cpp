// Parts as ADAMS accepts them (docs/theory.md, "Parts as ADAMS accepts them"): a massless part
// without CM or IP held by constraints, a point mass with zero principal moments, through
// every integrator; and a massless motion no constraint holds, named at its PART.
//
// Truths, independent of the solver:
// - a bob on a massless rod, hinged at the bob's CM (the bob's spin decouples, so it moves as
//   a point mass): released from rest at a0, its quarter period is sqrt(L/g) K(sin(a0/2));
// - a point mass (IP = 0) on a rod held by a UNIVERSAL joint at the pivot, started on the
//   conical-pendulum orbit: its height stays -L cos(alpha) and it turns about the vertical at
//   Omega = sqrt(g / (L cos alpha)). WX is given with VY: the rate about the ground pin that
//   the joint needs for that velocity, so the initial-velocity analysis has nothing to change
//   (without it, its least change trades ~1e-6 of the given VY against the rate).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/analysis_context.hpp"
#include "analysis/eigen_analysis.hpp"
#include "analysis/linearization.hpp"
#include "analysis/model_summary.hpp"
#include "analysis/run_state.hpp"
#include "analysis/transient_run.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "support/recorded_run.hpp"

namespace openmss {
namespace {

using testing::load;
using testing::Loaded;
using testing::RecordingReport;

// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return std::numbers::pi / (2.0 * a);
}

struct Method {
  const char* name;
  model::IntegratorType type;
  model::IntegratorFormulation formulation;
  double periodTolerance;  // relative error of the quarter period (massless rod)
  double orbitTolerance;   // distance from the conical orbit over its radius (point mass)
};

// ERROR = 1e-8, HMAX = 1e-3 everywhere. Measured (relative period error; orbit distance):
// GSTIFF I3 5.9e-10, 8.5e-9; GSTIFF SI2 7.7e-10, 2.2e-9; WSTIFF 1.4e-8, 9.5e-9; DSTIFF 5.3e-9,
// 3.0e-9; HHT 5.4e-7, 1.3e-5 (alpha = -0.3 damps the orbit); ABAM 5.9e-11, 5.8e-8; MERSON
// 1.6e-14, 6.1e-12; the errors fall with ERROR (1e-10: GSTIFF's orbit 4.3e-11), so they are
// integration errors. The tolerances are ~10x the worst of each group; a wrong mass matrix (a
// rod with mass, a bob with inertia) moves either number by percents.
const std::vector<Method>& methods() {
  using T = model::IntegratorType;
  using F = model::IntegratorFormulation;
  static const std::vector<Method> m = {
      {"GSTIFF I3", T::Gstiff, F::I3, 2e-7, 1e-7}, {"GSTIFF SI2", T::Gstiff, F::Si2, 2e-7, 1e-7},
      {"WSTIFF I3", T::Wstiff, F::I3, 2e-7, 1e-7}, {"DSTIFF", T::Dstiff, F::I3, 2e-7, 1e-7},
      {"HHT", T::Hht, F::I3, 5e-6, 1e-4},          {"ABAM", T::Abam, F::I3, 2e-7, 6e-7},
      {"MERSON", T::Merson, F::I3, 2e-7, 1e-7}};
  return m;
}

std::string rodPendulum(double length, double a0) {
  char text[1024];
  const double x = length * std::sin(a0), y = -length * std::cos(a0);
  std::snprintf(text, sizeof text,
                "bob on a massless rod\n"
                "PART/1, GROUND\n"
                "MARKER/10, PART=1\n"
                "PART/2\n"  // the rod: no MASS, no IP, no CM (its BCS is the CM frame)
                "MARKER/21, PART=2\n"
                "MARKER/22, PART=2, QP=%.17g,%.17g,0\n"
                "PART/3, MASS=1.5, CM=30, IP=0.02,0.03,0.04\n"
                "MARKER/30, PART=3, QP=%.17g,%.17g,0\n"
                "JOINT/1, REVOLUTE, I=21, J=10\n"
                "JOINT/2, REVOLUTE, I=30, J=22\n"
                "ACCGRAV/ JGRAV=-9.80665\n"
                "REQUEST/1, DISPLACEMENT, I=30, J=10\n"
                "END\n",
                x, y, x, y);
  return text;
}

TEST(MasslessParts, BobOnAMasslessRodHasThePointMassPeriodWithEveryIntegrator) {
  const double length = 2.0, a0 = 0.3, g = 9.80665;
  const double quarter = std::sqrt(length / g) * ellipticK(std::sin(0.5 * a0));
  int compared = 0;
  for (const Method& method : methods()) {
    auto l = load(rodPendulum(length, a0));
    ASSERT_EQ(l->state->degreesOfFreedom, 2);  // the rod's angle and the bob's spin
    l->model.integrator.type = method.type;
    l->model.integrator.formulation = method.formulation;
    l->model.integrator.error = 1e-8;
    l->model.integrator.hmax = 1e-3;
    analysis::TransientRun run;
    run.kind = analysis::TransientKind::Dynamics;
    run.end = 1.25 * quarter;
    run.outputSteps = 1000;
    ASSERT_TRUE(analysis::runTransient(l->context(), run)) << method.name;
    for (const auto& d : l->report.diagnostics)
      if (d.severity == Severity::Error) ADD_FAILURE() << method.name << ": " << format(d);
    // The first downward crossing of x = 0: x'' vanishes there, so linear interpolation
    // between output steps errs by O(dt^3) (~1e-9 s here).
    double crossing = -1.0;
    const auto& steps = l->report.steps;
    for (size_t k = 1; k < steps.size() && crossing < 0.0; ++k) {
      const double x0 = steps[k - 1].rows[0][0], x1 = steps[k].rows[0][0];
      if (x0 > 0.0 && x1 <= 0.0)
        crossing = steps[k - 1].t + (steps[k].t - steps[k - 1].t) * x0 / (x0 - x1);
    }
    ASSERT_GT(crossing, 0.0) << method.name;
    const double error = std::abs(crossing - quarter) / quarter;
    std::printf("massless rod, %-10s: quarter period %.9f s (closed form %.9f), rel. error %.1e\n",
                method.name, crossing, quarter, error);
    EXPECT_LT(error, method.periodTolerance) << method.name;
    ++compared;
  }
  EXPECT_EQ(compared, 7);
}

// The linear analysis about the hanging position: the massless rod adds no inertia, so the
// swing has the point-mass frequency sqrt(g/L) (and the bob's free spin two zero eigenvalues).
// Linearisation is exact (forward AD), so 1e-8 relative is round-off room.
TEST(MasslessParts, TheLinearisedSwingOfABobOnAMasslessRodHasThePointMassFrequency) {
  const double length = 2.0, g = 9.80665;
  auto l = load(rodPendulum(length, 0.0));
  mechanics::MultibodySystem& s = *l->system;
  Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
  ASSERT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-13, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  ASSERT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  analysis::LinearSystem lin;
  std::string why;
  ASSERT_TRUE(analysis::linearize(s, 0.0, y, yp, {}, lin, &why)) << why;
  ASSERT_EQ(lin.degreesOfFreedom, 2);
  const auto modes = analysis::eigenModes(lin);
  ASSERT_EQ(modes.size(), 4u);
  int swings = 0, zeros = 0;
  for (const auto& mode : modes) {
    if (std::abs(mode.value) < 1e-9) {
      ++zeros;
      continue;
    }
    EXPECT_NEAR(std::abs(mode.value.imag()), std::sqrt(g / length), 1e-8 * std::sqrt(g / length));
    EXPECT_NEAR(mode.value.real(), 0.0, 1e-10);
    ++swings;
  }
  EXPECT_EQ(swings, 2);
  EXPECT_EQ(zeros, 2);
}

std::string conicalPendulum(double length, double alpha, double omega) {
  char text[1024];
  const double x = length * std::sin(alpha), z = -length * std::cos(alpha);
  std::snprintf(text, sizeof text,
                "point mass on a universal joint\n"
                "PART/1, GROUND\n"
                "MARKER/10, PART=1, ZP=1,0,0\n"  // pin of the ground yoke along x
                "PART/2, MASS=0.5, CM=20, IP=0,0,0, VY=%.17g, WX=%.17g\n"
                "MARKER/20, PART=2, QP=%.17g,0,%.17g\n"
                "MARKER/21, PART=2, ZP=0,1,0\n"  // pin of the rod along y
                "JOINT/1, UNIVERSAL, I=21, J=10\n"
                "ACCGRAV/ KGRAV=-9.80665\n"
                "REQUEST/1, DISPLACEMENT, I=20, J=10\n"
                "END\n",
                omega * x, omega * x / -z, x, z);
  return text;
}

TEST(MasslessParts, PointMassWithZeroInertiaFollowsTheConicalPendulumWithEveryIntegrator) {
  const double length = 1.0, alpha = 0.5, g = 9.80665;
  const double omega = std::sqrt(g / (length * std::cos(alpha)));
  const double period = 2.0 * std::numbers::pi / omega;
  int compared = 0;
  for (const Method& method : methods()) {
    auto l = load(conicalPendulum(length, alpha, omega));
    ASSERT_EQ(l->state->degreesOfFreedom, 2);
    l->model.integrator.type = method.type;
    l->model.integrator.formulation = method.formulation;
    l->model.integrator.error = 1e-8;
    l->model.integrator.hmax = 1e-3;
    analysis::TransientRun run;
    run.kind = analysis::TransientKind::Dynamics;
    run.end = period;
    run.outputSteps = 200;
    ASSERT_TRUE(analysis::runTransient(l->context(), run)) << method.name;
    for (const auto& d : l->report.diagnostics)
      if (d.severity == Severity::Error) ADD_FAILURE() << method.name << ": " << format(d);
    ASSERT_EQ(l->report.steps.size(), 201u) << method.name;
    // Worst distance from the closed-form orbit point (L sin a cos Wt, L sin a sin Wt,
    // -L cos a), relative to the orbit radius L sin a.
    const double radius = length * std::sin(alpha);
    double worst = 0.0;
    for (const auto& s : l->report.steps) {
      const double ex = radius * std::cos(omega * s.t), ey = radius * std::sin(omega * s.t);
      const double ez = -length * std::cos(alpha);
      worst = std::max(
          worst, std::hypot(s.rows[0][0] - ex, s.rows[0][1] - ey, s.rows[0][2] - ez) / radius);
    }
    std::printf("conical pendulum, %-10s: worst distance from the orbit %.1e of its radius\n",
                method.name, worst);
    EXPECT_LT(worst, method.orbitTolerance) << method.name;
    ++compared;
  }
  EXPECT_EQ(compared, 7);
}

// The set-up analysis names a massless motion that no constraint holds at the part.
TEST(MasslessParts, AFreeMasslessMotionIsNamedAtItsPart) {
  const char* text =
      "free massless part\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=0,0,0\n"  // 4: a point mass on a spherical joint
      "MARKER/20, PART=2, QP=0,-1,0\n"
      "MARKER/21, PART=2\n"
      "JOINT/1, SPHERICAL, I=21, J=10\n"
      "PART/3\n"  // 8: massless and free
      "ACCGRAV/ JGRAV=-9.80665\n"
      "END\n";
  auto l = load(text);
  analysis::TransientRun run;
  run.kind = analysis::TransientKind::Dynamics;
  run.end = 0.1;
  run.outputSteps = 1;
  EXPECT_FALSE(analysis::runTransient(l->context(), run));
  std::vector<std::string> lines;
  for (const auto& d : l->report.diagnostics) lines.push_back(format(d));
  // The point mass spins freely about its rod (the y axis); the free massless part has
  // three free translations and three free rotations.
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[0],
            "model.adm:4:1: error: PART/2: has a zero principal moment of inertia and no "
            "constraint holds a rotation about (0, 1, 0) in its CM axes: its acceleration is "
            "undetermined (singular mass matrix). Give IP=Ixx,Iyy,Izz with positive moments, "
            "or hold that rotation with a joint (a massless part must be held by "
            "constraints).");
  for (size_t k = 1; k < 7; ++k) {
    EXPECT_EQ(lines[k].rfind("model.adm:8:1: error: PART/3: has ", 0), 0u) << lines[k];
  }
  EXPECT_NE(lines[1].find("has no mass and no constraint holds a translation along"),
            std::string::npos);
}

}  // namespace
}  // namespace openmss
