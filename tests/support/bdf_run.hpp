#pragma once
// A data set built from text, and a dynamic run over it with the initial conditions made as
// `openmss run` makes them (redundancy, positions, velocities, accelerations with the user
// unknowns), then the GSTIFF-style BDF integrator: the fixture of the tests that follow user
// equations and force functions along a motion.

#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analysis/multibody_dae.hpp"
#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::test {

// The model of a data set given as text; every diagnostic is a test failure.
inline model::Model buildModelFromText(const std::string& text, const std::string& fileName) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, fileName, ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

class BdfRun {
 public:
  // consistentOutputs: after every advanceTo, accelerations, multipliers and VARIABLEs are made
  // consistent with the reached positions and velocities, as a run does for its outputs.
  BdfRun(const model::Model& m, double error, double hmax, bool consistentOutputs)
      : system_(m), consistentOutputs_(consistentOutputs) {
    y_ = system_.initialState();
    mechanics::removeRedundantConstraints(system_, y_);
    EXPECT_TRUE(mechanics::assemblePositions(system_, 0.0, y_, 1e-12, 25).converged);
    mechanics::solveVelocities(system_, 0.0, y_);
    EXPECT_TRUE(mechanics::solveAccelerations(system_, 0.0, y_, yp_));
    settings_.error = error;
    settings_.hmax = hmax;
    settings_.hinit = 1e-4;
  }
  const mechanics::MultibodySystem& system() const { return system_; }
  const Eigen::VectorXd& y() const { return y_; }
  const Eigen::VectorXd& yp() const { return yp_; }
  void start() {
    dae_ = std::make_unique<analysis::MultibodyDae>(system_);
    bdf_ = std::make_unique<solvers::BdfIntegrator>(*dae_, settings_);
    bdf_->start(0.0, y_, yp_);
  }
  void advanceTo(double t) {
    ASSERT_TRUE(bdf_->advanceTo(t)) << bdf_->failure().reason;
    y_ = bdf_->y();
    yp_ = bdf_->yp();
    if (consistentOutputs_) {
      ASSERT_TRUE(mechanics::solveAccelerations(system_, t, y_, yp_));
    }
  }
  // Velocities projected on C u = 0 (the index-3 integrator satisfies it only to its error),
  // then accelerations and multipliers again: a state on which reaction identities are exact.
  void projectVelocities(double t) {
    mechanics::solveVelocities(system_, t, y_);
    ASSERT_TRUE(mechanics::solveAccelerations(system_, t, y_, yp_));
  }
  double variable(int k) const { return y_(system_.layout().userAlg(k)); }
  double diffState(int k) const { return y_(system_.layout().userDiff(k)); }
  double body(int b, int entry) const { return y_(system_.layout().body(b) + entry); }

 private:
  mechanics::MultibodySystem system_;
  bool consistentOutputs_;
  Eigen::VectorXd y_, yp_;
  solvers::MultistepSettings settings_;
  std::unique_ptr<analysis::MultibodyDae> dae_;
  std::unique_ptr<solvers::BdfIntegrator> bdf_;
};

// The states at `times` of a built model integrated from its initial state (velocities and
// accelerations made consistent, no position assembly) by BdfIntegrator at ERROR = 1e-9,
// HMAX = 0.05, and the run's residual evaluations: the common run of the tests that compare a
// user routine with the same model written with function expressions (tests/user).
struct Trajectory {
  std::vector<Eigen::VectorXd> states;
  long residuals = 0;
};

inline Trajectory integrateModel(const model::Model& m, std::initializer_list<double> times) {
  Trajectory out;
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  solvers::MultistepSettings settings;
  settings.error = 1e-9;
  settings.hmax = 0.05;
  analysis::MultibodyDae dae(s);
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, y, yp);
  for (double t : times) {
    EXPECT_TRUE(bdf.advanceTo(t)) << bdf.failure().reason;
    out.states.push_back(bdf.y());
  }
  out.residuals = bdf.statistics().residualEvaluations;
  return out;
}

}  // namespace openmss::test
