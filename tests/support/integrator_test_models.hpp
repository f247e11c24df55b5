#pragma once
// The small mechanisms the integrator tests share (GSTIFF-family, DSTIFF, ABAM, MERSON), each
// with a closed form or a published value, and their assembly to a consistent initial state.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "analysis/multibody_dae.hpp"
#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::test {

// The DAE test-set pendulum (as tests/analysis/dae_pendulum_test.cpp): a unit point mass
// (inertia 1e-10) on a unit rod; its position at t = 1 is (kPendulumX1, kPendulumY1).
inline constexpr double kPendulumX1 = 0.867348640604551746;
inline constexpr double kPendulumY1 = 0.497701050476373918;
inline const char* const kPendulum =
    "DAE test-set pendulum\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1e-10,1e-10,1e-10, VX=0, VY=1, VZ=0\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-1\n"
    "END\n";

// m = 2 on a translational joint along z, spring-damper k = 200, c = 4 (as
// force_elements_dynamics_test.cpp): x(t) = e^{-t} x0 (cos wd t + sin(wd t) / wd), wd^2 = 99.
inline const char* const kSpringDamper =
    "mass on a spring-damper\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,1.1\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=200, C=4, LENGTH=1\n"
    "END\n";

// The same with k/m = 1e8 and critical damping (c = 2 sqrt(k m)): eigenvalues -1e4 (double);
// after a transient of a few 1e-4 s the mass rests, which makes the model stiff for any
// explicit-like method over runs of 0.01 s and more.
inline const char* const kStiffSpring =
    "stiff spring-damper\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0,0,1.001\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=1e8, C=2e4, LENGTH=1\n"
    "END\n";

// `text`, a data set of this file (it ends in END), with `statements` inserted before its END:
// the same line numbers for the mechanism and the added statements right after it.
inline std::string beforeEnd(const std::string& text, const std::string& statements) {
  const std::string end = "END\n";
  EXPECT_TRUE(text.size() >= end.size() &&
              text.compare(text.size() - end.size(), end.size(), end) == 0)
      << "the data set must end in END";
  return text.substr(0, text.size() - end.size()) + statements + end;
}

struct Mechanism {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y, yp;
};

// The data set built into a system at a consistent state: redundant equations removed,
// positions assembled, velocities and accelerations solved (every step must succeed).
inline std::unique_ptr<Mechanism> assemble(const std::string& text) {
  auto m = std::make_unique<Mechanism>();
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "model.adm", ds, d);
  EXPECT_TRUE(model::buildModel(ds, m->model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  m->system = std::make_unique<mechanics::MultibodySystem>(m->model);
  m->y = m->system->initialState();
  mechanics::removeRedundantConstraints(*m->system, m->y);
  EXPECT_TRUE(mechanics::assemblePositions(*m->system, 0.0, m->y, 1e-12, 25).converged);
  mechanics::solveVelocities(*m->system, 0.0, m->y);
  EXPECT_TRUE(mechanics::solveAccelerations(*m->system, 0.0, m->y, m->yp));
  return m;
}

// The DAE test-set pendulum integrated to t = 1 by BdfIntegrator with `settings`: its position
// there, the steps and the residual evaluations (the runs of the corrector tests).
struct PendulumOutcome {
  double x = 0, y = 0;
  long steps = 0, residuals = 0;
};

inline PendulumOutcome integratePendulum(const solvers::MultistepSettings& settings) {
  const auto mechanism = assemble(kPendulum);
  analysis::MultibodyDae dae(*mechanism->system);
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, mechanism->y, mechanism->yp);
  EXPECT_TRUE(bdf.advanceTo(1.0)) << bdf.failure().reason;
  return {bdf.y()(0), bdf.y()(1), bdf.statistics().steps, bdf.statistics().residualEvaluations};
}

}  // namespace openmss::test
