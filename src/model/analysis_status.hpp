#pragma once
// What the running analysis is doing, as the function-expression variables MODE, HSIZE, ORDER,
// NJAC and NRHS read it (docs/expressions.md, "Analysis variables"). The session writes it
// before it evaluates expressions; every value is a deterministic counter or setting, so
// outputs stay bit-identical from run to run. CPU time is deliberately absent: the model
// builder refuses CPU for that reason.

namespace openmss::model {

// ADAMS's MODE codes (2 is reserved there, 9 is CONSUB initialisation: neither occurs here).
enum class AnalysisMode : int {
  Kinematics = 1,
  InitialConditions = 3,
  Dynamics = 4,
  Statics = 5,
  QuasiStatics = 6,
  Linear = 7,
};

struct AnalysisStatus {
  AnalysisMode mode = AnalysisMode::InitialConditions;  // nothing evaluates before set-up
  // Integrator statistics of the current SIMULATE command after its last accepted step (the
  // numbers the .msg prints); all zero outside a dynamic analysis.
  double stepSize = 0.0;          // HSIZE
  int order = 0;                  // ORDER
  long jacobianEvaluations = 0;   // NJAC
  long residualEvaluations = 0;   // NRHS

  void clearIntegrator() {
    stepSize = 0.0;
    order = 0;
    jacobianEvaluations = 0;
    residualEvaluations = 0;
  }
};

}  // namespace openmss::model
