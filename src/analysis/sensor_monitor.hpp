#pragma once
// SENSOR events in a dynamic analysis (docs/theory.md, "Sensors"). After every accepted
// integrator step the monitor evaluates each sensor at the step's end; a sensor whose test
// starts to hold inside the step has its event time located on the integrator's own
// interpolant (Illinois secant, or bisection with BISECTION) to a small fraction of its ERROR.
// The caller (analysis/dynamic_run.cpp) then carries out the output-side actions (PRINT, HALT,
// RETURN, DT); the monitor itself restarts the integrator at the event when the actions need
// it (RESTART, STEPSIZE, DT, EVALUATE, HALT, RETURN) and stores the EVALUATE values that
// SENVAL(id) reads.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

// What the sensors that fired together ask for, and the consistent state at the event.
struct SensorEvent {
  double time = 0.0;
  Eigen::VectorXd y, yp;     // positions, velocities, accelerations and forces consistent
  std::vector<int> sensors;  // indices into Model::sensors, in data-set order
  std::vector<double> functionValues;  // each fired sensor's FUNCTION at the event
  bool halt = false, returnToCommands = false, print = false, restarted = false;
  std::optional<double> outputInterval;  // DT (the smallest when several fire)
  std::optional<double> stepSize;        // STEPSIZE (the smallest when several fire)
  bool stepSizeHonoured = true;          // false: the integrator has no step-size control
  bool endsSimulation() const { return halt || returnToCommands; }
};

class SensorMonitor {
 public:
  // `run` receives the EVALUATE values (SENVAL) at events.
  SensorMonitor(const mechanics::MultibodySystem& system, mechanics::ExpressionRunState& run);

  bool active() const { return !sensors_.empty(); }
  // Records which tests hold at the start of the run: a sensor acts only when its test starts
  // to hold, so one that already holds waits until it has stopped holding.
  void start(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp);
  // Steps `integrator` towards tout, checking the sensors after every accepted step. Returns
  // false when the integrator failed; otherwise the integrator is at tout, or an event
  // happened first (event() is set and the integrator is at the event, or past it when the
  // actions need no restart; the next call checks the rest of that step first).
  bool advanceTo(solvers::Integrator& integrator, double tout);
  const SensorEvent* event() const { return event_ ? &*event_ : nullptr; }

  // Value of sensor k's FUNCTION on a state (accelerations and forces from yp and y).
  double functionValue(int k, double t, const Eigen::VectorXd& y,
                       const Eigen::VectorXd& yp) const;

 private:
  // Negative or zero when sensor k's test holds; positive before (EQ crossing: see the .cpp).
  double distance(int k, double f, int mode) const;
  // The state at s on the interpolant (consistent accelerations when a function reads them).
  void stateAt(const solvers::Integrator& integrator, double s, Eigen::VectorXd& y,
               Eigen::VectorXd& yp) const;
  std::vector<double> functionValues(double t, const Eigen::VectorXd& y,
                                     const Eigen::VectorXd& yp) const;
  bool holds(int k, double f) const;
  // Checks (checkedTime_, integrator.t()]; returns true when an event was found and acted on.
  bool checkLastStep(solvers::Integrator& integrator);
  void consistentState(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) const;

  const mechanics::MultibodySystem& system_;
  mechanics::ExpressionRunState& run_;
  std::vector<int> sensors_;  // all of Model::sensors
  bool needsDynamics_ = false;
  std::vector<bool> holds_;     // test state at checkedTime_
  std::vector<double> values_;  // FUNCTION values at checkedTime_
  double checkedTime_ = 0.0;
  std::optional<SensorEvent> event_;
};

// The .msg lines of an event: which sensors fired, when, their function values and what they
// did.
std::vector<std::string> describeSensorEvent(const model::Model& model, const SensorEvent& event,
                                             const mechanics::ExpressionRunState& run);

// The output times of one SIMULATE: base + k * step, the last one exactly END. A sensor's
// DT= moves the base to the event and changes the step for the rest of the command.
struct OutputGrid {
  double base = 0.0, step = 1.0, end = 1.0;
  long first = 0;  // index of the output at `base`
  long count = 1;  // index of the output at END
  double time(long i) const;
  // From output index `next` on: event + k * dt (k = 1, 2, ...), END last.
  void reschedule(long next, double event, double dt);
};

}  // namespace openmss::analysis
