#pragma once
// DEBUG/EPRINT (docs/theory.md §9, "DEBUG/EPRINT"): for every integration step its
// number, order, start time and step size, and for every corrector iteration the largest
// equation residual and the largest variable change, each named by its data-set element
// (MultibodyDae::equationName / variableName). Written to the .msg only.

#include "analysis/run_report.hpp"
#include "solvers/bdf_integrator.hpp"
#include "solvers/dae_problem.hpp"

namespace openmss::analysis {

class EprintLog {
 public:
  EprintLog(RunReport& log, const solvers::DaeProblem& problem) : log_(log), problem_(problem) {}
  // Registers the step and iteration observers on `integrator` (which must not outlive this).
  void attach(solvers::Integrator& integrator);

 private:
  static void onStep(const solvers::BdfStepInfo& info, void* self);
  static void onIteration(const solvers::BdfIterationInfo& info, void* self);
  RunReport& log_;
  const solvers::DaeProblem& problem_;
};

}  // namespace openmss::analysis
