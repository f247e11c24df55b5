#pragma once
// Typed requests for one analysis each, as the command layer builds them from SIMULATE and
// LINEAR commands (commands/simulate_command.cpp, commands/linear_command.cpp) and as a test
// or another program builds them directly. Times are absolute; the output count is resolved
// (STEPS=, or END and DTOUT).

#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis_context.hpp"
#include "analysis/linearization.hpp"

namespace openmss::analysis {

// SIMULATE/TRANSIENT, /DYNAMICS, /KINEMATICS (docs/theory.md, "Analyses").
enum class TransientKind {
  Transient,   // kinematic when the model has no degree of freedom and no state to integrate
  Dynamics,    // integrate the equations of motion
  Kinematics,  // position, velocity and acceleration analyses at each output time
};
struct TransientRun {
  TransientKind kind = TransientKind::Transient;
  double end = 1.0;      // absolute time of the last output, after RunState::t
  long outputSteps = 1;  // output intervals up to `end` (>= 1)
  RunOrigin origin;
};

// SIMULATE/STATICS: one equilibrium at the current time, or (with `end`) a quasi-static
// sequence of equilibria at `outputSteps` equally spaced times after it.
struct StaticsRun {
  std::optional<double> end;
  long outputSteps = 0;
  RunOrigin origin;
};

// SIMULATE/INITIAL_CONDITIONS [, DISPLACEMENT | VELOCITY]: the phases up to the one named.
enum class InitialConditionsPhase { Displacement = 1, Velocity = 2, Acceleration = 3 };
struct InitialConditionsRun {
  InitialConditionsPhase last = InitialConditionsPhase::Acceleration;
  RunOrigin origin;
};

// LINEAR/EIGENSOL and LINEAR/STATEMAT about the current operating point.
enum class StateMatrixFormat { Matlab, Matrixx };
struct LinearRun {
  bool eigen = true;             // EIGENSOL (else STATEMAT)
  bool withoutShapes = false;    // NOVECTOR
  LinearizationRequest request;  // basis, PINPUT/POUTPUT variables, NODAMPIN
  StateMatrixFormat format = StateMatrixFormat::Matlab;
  std::string fileBase;  // STATEMAT: path of the files without extension
  RunOrigin origin;
};

}  // namespace openmss::analysis
