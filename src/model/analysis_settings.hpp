#pragma once
// Solution-control parameters of the EQUILIBRIUM, IC and KINEMATICS statements and commands (docs/language.md,
// "Solution-control statements"). The statement sets them in the Model; the command changes them
// between analyses. Defaults are ADAMS/Solver (C++)'s.

#include <array>
#include <numbers>
#include <optional>


namespace openmss::model {

// PATTERN=c1:...:c10: entry j tells whether the Jacobian is re-formed at iteration j; the
// pattern repeats until MAXIT. Iteration 0 always forms it.
struct RefreshPattern {
  std::array<bool, 10> evaluate = {true, true, true, true, true, true, true, true, true, true};
  bool at(int iteration) const { return iteration == 0 || evaluate[iteration % 10]; }
};

struct EquilibriumSettings {
  double angleLimit = 10.0 * std::numbers::pi / 180.0;  // ALIMIT, rad per iteration
  double error = 1e-4;             // ERROR: largest position correction at convergence
  double imbalance = 1e-4;         // IMBALANCE: largest force/moment residual at convergence
  int maxit = 25;                  // MAXIT
  RefreshPattern pattern;         // PATTERN
  double stability = 1e-5;         // STABILITY: fraction of the mass matrix added to the stiffness
  double translationLimit = 20.0;  // TLIMIT, length units per iteration
};

struct InitialConditionSettings {
  double accelerationError = 1e-4;                      // AERROR
  double angleLimit = 30.0 * std::numbers::pi / 180.0;  // ALIMIT
  int accelerationMaxit = 25;                           // AMAXIT
  RefreshPattern accelerationPattern;                  // APATTERN
  double error = 1e-10;                                 // ERROR (positions)
  int maxit = 25;                                       // MAXIT (positions)
  RefreshPattern pattern;                              // PATTERN (positions)
  double translationLimit = 1e10;                       // TLIMIT
  double velocityError = 1e-4;                          // VERROR
};

// KINEMATICS statement and command (docs/language.md, "KINEMATICS"): the controls of
// SIMULATE/KINEMATICS (analysis/kinematic_run.cpp). Defaults are ADAMS's except ERROR: ADAMS
// takes 1e-4, OpenMSS 1e-12 on the largest |Phi| so that the outputs of a kinematic analysis are
// exact to round-off unless the user asks for less (docs/language.md).
struct KinematicSettings {
  double accelerationError = 1e-4;                      // AERROR: largest force imbalance
  double angleLimit = 30.0 * std::numbers::pi / 180.0;  // ALIMIT, rad per Newton iteration
  int accelerationMaxit = 25;                           // AMAXIT (no effect: linear solve)
  RefreshPattern accelerationPattern;                  // APATTERN (no effect: linear solve)
  double error = 1e-12;                                 // ERROR: largest |Phi| at convergence
  std::optional<double> hmax;                           // HMAX: largest step between solves
  int maxit = 25;                                       // MAXIT (positions)
  RefreshPattern pattern;                              // PATTERN (positions)
  double translationLimit = 1e10;                       // TLIMIT, length per Newton iteration
};

// INTEGRATOR statement and command (docs/integrators.md, "Defaults"). Unset optionals take
// the chosen integrator's ADAMS default when the run starts (analysis/integrator_factory.cpp,
// docs/integrators.md): several depend on the output step.
// Merson: OpenMSS's explicit Kutta-Merson on the index-1 equations (not an ADAMS method).
enum class IntegratorType {
  Gstiff, Wstiff, Dstiff, Hht, Newmark, Abam, ConstantBdf, Hastiff, Cpbdf, Merson };
enum class IntegratorFormulation { I3, Si2, Si1 };
struct IntegratorSettings {
  IntegratorType type = IntegratorType::Gstiff;
  IntegratorFormulation formulation = IntegratorFormulation::I3;
  std::optional<double> error, hinit, hmin, hmax;  // ERROR, HINIT, HMIN, HMAX
  std::optional<int> kmax;                         // KMAX
  int maxit = 10;                                  // MAXIT
  std::optional<RefreshPattern> pattern;          // PATTERN (unset: adaptive re-evaluation)
  std::optional<bool> interpolate;                 // INTERPOLATE=ON/OFF
  double alpha = -0.3;                             // ALPHA (HHT)
  std::optional<double> beta, gamma;               // BETA, GAMMA (NEWMARK; HHT derives them)
  bool modifiedCorrector = false;                  // CORRECTOR=MODIFIED (GSTIFF, WSTIFF)
  std::optional<double> adaptivity;                // ADAPTIVITY (GSTIFF, WSTIFF)
};
const char* integratorTypeName(IntegratorType type);  // "GSTIFF", "HHT", ...
const char* formulationName(IntegratorFormulation f);  // "I3", "SI2", "SI1"

}  // namespace openmss::model
