// SIMULATE/KINEMATICS (and TRANSIENT of a model without degrees of freedom): at each output
// time the positions are predicted to first order and closed by Newton on the constraints,
// then the velocities and the accelerations with the constraint forces follow from the linear
// phases (docs/theory.md, "Analyses").

#include "analysis/transient_run.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {

bool runKinematics(const AnalysisContext& run, const TransientRun& settings) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  const long nOut = std::max(1L, settings.outputSteps);
  if (!beginTransient(run, /*kinematic=*/true)) return false;
  const double t0 = s.t, end = settings.end;
  const double outStep = (end - t0) / static_cast<double>(nOut);
  run.report.line("  ****** Performing Kinematic Analysis ******");
  for (long i = 1; i <= nOut; ++i) {
    const double t = (i == nOut) ? end : t0 + static_cast<double>(i) * outStep;
    // First-order prediction of the positions, then Newton on the constraints.
    const double dt = t - s.t;
    s.y += dt * s.yp;
    auto r = mechanics::assemblePositions(run.system, t, s.y, 1e-12, 25);
    if (!r.converged) {
      run.error(nullptr,
                "kinematic analysis failed at time " + formatNumber("%.6E", t) + ": " +
                    run.system.constraints().describe(r.worstEquation, m) +
                    " cannot be satisfied (residual " + formatNumber("%.3E", r.residual) + ")",
                "The mechanism may lock up or pass a singular position; check the motion "
                "functions.");
      return false;
    }
    mechanics::solveVelocities(run.system, t, s.y);
    if (!mechanics::solveAccelerations(run.system, t, s.y, s.yp)) {
      run.error(nullptr, "singular constraint matrix at time " + formatNumber("%.6E", t),
                "The mechanism passes a singular configuration.");
      return false;
    }
    s.t = t;
    ++s.summary.steps;
    s.expressions->accept(run.system, s.t, s.y, s.yp);  // each output is an accepted state
    if (!run.writeOutputStep(s.t, s.y, s.yp)) return false;
    run.report.progress(s.t, t0, end, s.summary.steps);
  }
  endTransient(run);
  return true;
}

}  // namespace openmss::analysis
