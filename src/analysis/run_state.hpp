#pragma once
// What one model's run changes during and between analyses: the time, the state y and its
// derivative y', whether the initial conditions hold, the expression run state (cumulative
// angles, DELAY histories) and the run's counters. The analyses (analysis/*_run.hpp) read and
// advance it; nothing of it lives in the Model. It is the start of the single run state of
// docs/architecture.md ("Run state"), which will also take the integrator history, the sensor
// values and the analysis status.

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "mechanics/expression_run_state.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

// Counters of the analyses run so far (printed by the command-line program).
struct RunSummary {
  double time = 0.0;
  long steps = 0;
  long outputSteps = 0;
  long jacobians = 0;
  long residuals = 0;
  long kinematicIterations = 0;  // Newton iterations of the kinematic position phases
  std::string analysis;          // "dynamic", "kinematic", "static", ... of the last analysis
};

struct RunState {
  // Starts at the data set's configuration (MultibodySystem::initialState), at time 0, and
  // attaches the expression run state to `system` (MultibodySystem::setRunState).
  explicit RunState(mechanics::MultibodySystem& system);
  RunState(const RunState&) = delete;
  RunState& operator=(const RunState&) = delete;

  double t = 0.0;
  Eigen::VectorXd y, yp;
  // The initial conditions hold at (t, y, yp): a following transient starts from them without
  // a new initial-condition analysis and without writing a first output step.
  bool initialized = false;
  // Degrees of freedom from the rank of the constraint Jacobian, and the Gruebler count, as
  // found when the model was loaded (model_summary.hpp).
  int degreesOfFreedom = 0, grueblerCount = 0;
  // The output files' prefix (<prefix>.req, <prefix>.msg), named in diagnostics.
  std::string outputPrefix;
  // A SENSOR with HALT ended the last transient: the run is over.
  bool halted = false;
  // The expression run state was taken over from the model before a reprocessing (ACTIVATE,
  // DEACTIVATE, a redefinition; commands/state_carry_over.hpp): the next transient solves the
  // initial conditions again but keeps the turn counts and DELAY histories (docs/theory.md
  // §11c) instead of starting a new run's history.
  bool historyCarried = false;
  std::unique_ptr<mechanics::ExpressionRunState> expressions;
  RunSummary summary;
};

}  // namespace openmss::analysis
