// SIMULATE/DYNAMICS (and TRANSIENT of a model that can move): the integrator the INTEGRATOR
// settings choose (analysis/integrator_factory.hpp) steps over the output times; SENSOR events
// (analysis/sensor_monitor.hpp) and GSE samples (analysis/discrete_sampler.hpp) stop it on the
// way. Accepted steps update the expression run state (analysis/run_state_integrator.hpp).

#include <cmath>
#include <cstdio>
#include <memory>

#include "analysis/contact_events.hpp"
#include "analysis/discrete_sampler.hpp"
#include "analysis/eprint_log.hpp"
#include "analysis/integration_failure.hpp"
#include "analysis/integrator_factory.hpp"
#include "analysis/multibody_dae.hpp"
#include "analysis/run_state_integrator.hpp"
#include "analysis/sensor_monitor.hpp"
#include "analysis/transient_run.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {
namespace {

void writeBanner(const AnalysisContext& run, const IntegratorPlan& plan) {
  run.report.line("  ****** Performing Dynamic Simulation using " + integratorBanner(plan) +
                  " Integrator ******");
  run.report.line(integratorParameters(plan));
  run.report.line("");
  run.report.line("   Simulation      Step        Function    Cumulative   Integration");
  run.report.line("      Time         Size       Evaluations  Steps Taken    Order");
}

// Integrator statistics (docs/integrators.md compares the integrators by these).
void writeStatistics(const AnalysisContext& run, const solvers::IntegratorStatistics& st) {
  run.report.line("   Integrator statistics: " + std::to_string(st.steps) + " steps, " +
                  std::to_string(st.rejectedSteps) + " rejected, " +
                  std::to_string(st.newtonFailures) + " corrector failures, " +
                  std::to_string(st.jacobianEvaluations) + " Jacobian evaluations, " +
                  std::to_string(st.residualEvaluations) + " residual evaluations");
  // The sparse Newton matrices' cost drivers (docs/performance.md, "Contact pile").
  if (st.fullFactorizations + st.refactorizations > 0)
    run.report.line("   Sparse Newton matrices: " + std::to_string(st.sparseAnalyses) +
                    " pattern analyses, " + std::to_string(st.fullFactorizations) +
                    " full factorisations, " + std::to_string(st.refactorizations) +
                    " refactorisations");
}

// HSIZE, ORDER, NJAC, NRHS read by REQUEST functions: the numbers the .msg prints.
void publishStatus(model::AnalysisStatus& status, const solvers::IntegratorStatistics& st) {
  status.stepSize = st.stepSize;
  status.order = st.order;
  status.jacobianEvaluations = st.jacobianEvaluations;
  status.residualEvaluations = st.residualEvaluations;
}

}  // namespace

bool runDynamics(const AnalysisContext& run, const TransientRun& settings) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  const long nOut = std::max(1L, settings.outputSteps);
  const double t0 = s.t, end = settings.end;
  const double outStep = (end - t0) / static_cast<double>(nOut);
  // The initial conditions and first output step come before the method is checked.
  s.halted = false;
  if (!beginTransient(run, /*kinematic=*/false)) return false;
  if (const auto why = integratorUnavailable(m.integrator)) {
    run.error(&settings.origin, "the dynamic analysis cannot start: " + *why,
              "Change the INTEGRATOR setting.");
    return false;
  }
  IntegratorPlan plan = resolveIntegrator(m.integrator, outStep);
  plan.pivotOrder = run.pivotOrder;
  writeBanner(run, plan);
  MultibodyDae dae(run.system);
  const std::unique_ptr<solvers::Integrator> method = makeIntegrator(plan, run.system, dae, end);
  // CONTACT onsets restart the method at the located first touch (contact_events.hpp).
  ContactEventIntegrator contactEvents(*method, run.system);
  // Accepted steps and restarts update the expression run state (run_state_integrator.hpp).
  RunStateIntegrator integrator(contactEvents, *s.expressions, run.system);
  // Advice from the method as it appears (ABAM's stiffness warning), each line once.
  std::size_t warningsShown = 0, contactLinesShown = 0;
  auto showIntegratorWarnings = [&]() {
    const std::vector<std::string> lines = integrator.warnings();
    for (; warningsShown < lines.size(); ++warningsShown)
      run.warning(nullptr, lines[warningsShown]);
    // Contact onsets and separations, with DEBUG/EPRINT (theory §6c, "Events").
    for (; m.debug.eprint && contactLinesShown < contactEvents.events().size(); ++contactLinesShown)
      run.report.line(ContactEventIntegrator::describe(contactEvents.events()[contactLinesShown]));
  };
  EprintLog eprint(run.report, dae);           // DEBUG/EPRINT: per step and iteration, to the .msg
  if (m.debug.eprint) eprint.attach(*method);  // observers live on the method itself
  integrator.start(s.t, s.y, s.yp);
  // SENSOR events are checked after every step; a sensor's DT= moves the output grid.
  SensorMonitor sensors(run.system, *s.expressions);
  sensors.start(s.t, s.y, s.yp);
  OutputGrid grid{t0, outStep, end, 0, nOut};
  const long logEvery = std::max(1L, nOut / 10);
  // GSE discrete states: the integrator stops at each sample.
  const DiscreteSampler sampler(run.system, s.expressions.get());
  for (long i = 1; i <= grid.count; ++i) {
    const double t = grid.time(i);
    const double sampleTime = sampler.active() ? sampler.nextTime() : t + 1.0;
    const bool sampleFirst = sampleTime <= t + 1e-12 * std::max(1.0, std::abs(t));
    const double target = sampleFirst ? std::min(t, sampleTime) : t;
    const bool ok = sensors.advanceTo(integrator, target);
    const auto& st = integrator.statistics();
    publishStatus(s.expressions->status(), st);
    showIntegratorWarnings();
    if (!ok && !s.expressions->curveRunOff().empty()) {  // a PTCV/CVCV left an OPEN curve
      run.error(nullptr, "the dynamic analysis stopped: " + s.expressions->curveRunOff(),
                "Lengthen the curve (its MATRIX) or make it CLOSED, or end the simulation "
                "before that time.");
      s.t = integrator.t();
      s.summary.time = s.t;
      return false;
    }
    if (!ok) {
      // Name the request file only when one was written (OUTPUT/REQSAVE and at least one
      // output step).
      const std::string where =
          run.report.requestsWritten()
              ? "Outputs up to the last successful output step are in " + s.outputPrefix + ".req. "
              : "";
      // Without numerical damping the Newmark rule collapses on its own (the INTEGRATOR
      // warning, docs/integrators.md "Without numerical damping"): say so first.
      const bool undamped = (plan.type == model::IntegratorType::Hht ||
                             plan.type == model::IntegratorType::Newmark) &&
                            plan.gamma == 0.5;
      run.error(nullptr, describeIntegrationFailure(m, run.system, dae, integrator),
                where +
                    (undamped ? "The integrator has no numerical damping (GAMMA = 0.5): choose "
                                "ALPHA below 0 (HHT) or GAMMA above 0.5 (NEWMARK). "
                              : "") +
                    "Look for a discontinuous force or motion near that time, or tighten "
                    "HMAX.");
      s.t = integrator.t();
      s.summary.time = s.t;
      return false;
    }
    if (const SensorEvent* ev = sensors.event()) {
      for (const auto& line : describeSensorEvent(m, *ev, *s.expressions)) run.report.line(line);
      if (ev->print || ev->endsSimulation())
        if (!run.writeOutputStep(ev->time, ev->y, ev->yp, OutputKind::Dynamic)) return false;
      if (ev->endsSimulation()) {  // the integrator was restarted at the event
        s.t = ev->time;
        s.y = ev->y;
        s.halted = ev->halt;
        break;
      }
      if (ev->outputInterval) grid.reschedule(i, ev->time, *ev->outputInterval);
      --i;  // output i is still ahead
      continue;
    }
    if (sampleFirst) {  // new discrete states, then a restart from the consistent state
      Eigen::VectorXd ys = integrator.y(), yps = integrator.yp();
      sampler.sample(integrator.t(), ys, yps);
      integrator.start(integrator.t(), ys, yps);
      if (target < t) {
        --i;  // output i is still ahead
        continue;
      }
    }
    s.t = t;
    s.y = integrator.y();
    Eigen::VectorXd yOut = s.y, ypOut = integrator.yp();
    // Accelerations and reaction forces consistent with the converged positions and
    // velocities (not differenced from the integrator's history).
    mechanics::solveAccelerations(run.system, s.t, yOut, ypOut);
    if (!run.writeOutputStep(s.t, yOut, ypOut, OutputKind::Dynamic)) return false;
    s.summary.steps = st.steps;
    s.summary.jacobians = st.jacobianEvaluations;
    s.summary.residuals = st.residualEvaluations;
    if (i % logEvery == 0 || i == grid.count) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "   %12.5E %12.5E %12ld %12ld %8d", s.t, st.stepSize,
                    st.residualEvaluations, st.steps, st.order);
      run.report.line(buf);
    }
    run.report.progress(s.t, t0, end, st.steps);
  }
  s.yp = integrator.yp();
  writeStatistics(run, integrator.statistics());
  endTransient(run);
  return true;
}

}  // namespace openmss::analysis
