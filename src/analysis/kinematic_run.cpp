// SIMULATE/KINEMATICS (and TRANSIENT of a model without degrees of freedom): at each output
// time the positions are predicted to first order and closed by Newton on the constraints,
// then the velocities and the accelerations with the constraint forces follow from the linear
// phases (docs/theory.md, "Analyses"). The KINEMATICS statement and command set the controls
// (model::KinematicSettings, docs/language.md "KINEMATICS").

#include <cmath>

#include "analysis/initial_conditions_run.hpp"
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
  // The KINEMATICS statement's controls (docs/language.md, "KINEMATICS").
  const model::KinematicSettings& k = m.kinematics;
  mechanics::AssemblyOptions o;
  o.tolerance = k.error;
  o.maxIterations = k.maxit;
  o.translationLimit = k.translationLimit;
  o.angleLimit = k.angleLimit;
  o.pattern = k.pattern.evaluate;
  for (long i = 1; i <= nOut; ++i) {
    const double t = (i == nOut) ? end : t0 + static_cast<double>(i) * outStep;
    // HMAX: the output interval is cut into equal steps no longer than HMAX, each closed by
    // Newton from the first-order prediction of the previous one (a closer starting guess).
    const long nSub =
        k.hmax ? std::max(1L, static_cast<long>(std::ceil((t - s.t) / *k.hmax - 1e-12))) : 1L;
    const double tStart = s.t;
    for (long j = 1; j <= nSub; ++j) {
      const double tj =
          j == nSub ? t
                    : tStart + (t - tStart) * static_cast<double>(j) / static_cast<double>(nSub);
      s.y += (tj - s.t) * s.yp;
      const auto r = mechanics::assemblePositions(run.system, tj, s.y, o);
      s.summary.kinematicIterations += r.iterations;
      if (!r.converged) {
        run.error(nullptr,
                  "kinematic analysis failed at time " + formatNumber("%.6E", tj) + ": " +
                      run.system.constraints().describe(r.worstEquation, m) +
                      " cannot be satisfied (residual " + formatNumber("%.3E", r.residual) +
                      " after " + std::to_string(r.iterations) + " iterations; KINEMATICS ERROR " +
                      formatNumber("%.3E", k.error) + ", MAXIT " + std::to_string(k.maxit) + ")",
                  "The mechanism may lock up or pass a singular position; check the motion "
                  "functions, or raise KINEMATICS/MAXIT.");
        return false;
      }
      if (j < nSub) {
        mechanics::solveVelocities(run.system, tj, s.y);
        if (!mechanics::solveAccelerations(run.system, tj, s.y, s.yp)) {
          run.error(nullptr, "singular constraint matrix at time " + formatNumber("%.6E", tj),
                    "The mechanism passes a singular configuration.");
          return false;
        }
        s.t = tj;
        // A converged sub-step is an accepted state: COUPLER/GEAR turns counted from it.
        s.expressions->commitCoupledAngles(run.system, s.y);
      }
    }
    mechanics::solveVelocities(run.system, t, s.y);
    if (!mechanics::solveAccelerations(run.system, t, s.y, s.yp)) {
      run.error(nullptr, "singular constraint matrix at time " + formatNumber("%.6E", t),
                "The mechanism passes a singular configuration.");
      return false;
    }
    // AERROR: the force balance of the acceleration phase (docs/language.md, "KINEMATICS").
    s.t = t;
    double verr = 0.0, aerr = 0.0;
    phaseResiduals(run, verr, aerr);
    if (aerr > k.accelerationError) {
      run.error(nullptr,
                "kinematic analysis at time " + formatNumber("%.6E", t) + ": force balance error " +
                    formatNumber("%.3E", aerr) + " exceeds KINEMATICS AERROR " +
                    formatNumber("%.3E", k.accelerationError),
                "The constraint matrix is nearly singular here; raise AERROR to accept it.");
      return false;
    }
    ++s.summary.steps;
    s.expressions->accept(run.system, s.t, s.y, s.yp);  // each output is an accepted state
    if (!run.writeOutputStep(s.t, s.y, s.yp, OutputKind::Kinematic)) return false;
    run.report.progress(s.t, t0, end, s.summary.steps);
  }
  endTransient(run);
  return true;
}

}  // namespace openmss::analysis
