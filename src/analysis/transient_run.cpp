#include "analysis/transient_run.hpp"

#include "analysis/discrete_sampler.hpp"
#include "analysis/initial_conditions_run.hpp"

namespace openmss::analysis {

bool runTransient(const AnalysisContext& run, const TransientRun& settings) {
  const model::Model& m = run.model;
  const int dof = run.state.degreesOfFreedom;
  const bool kin = settings.kind == TransientKind::Kinematics;
  // DIFF, LSE and TFSISO states must be integrated: a 0-DOF model with them runs dynamics.
  const bool userStates =
      run.system.layout().userDifferential > 0 || DiscreteSampler(run.system).active();
  // SENSORs are monitored on the integrator's steps: a 0-DOF model with them runs dynamics.
  const bool kinematic = kin || (settings.kind == TransientKind::Transient && dof == 0 &&
                                 !userStates && m.sensors.empty());
  if (kin && !m.sensors.empty()) {
    run.error(&settings.origin,
              "SENSOR events are detected in dynamic analyses only; this model has " +
                  std::to_string(m.sensors.size()) + " sensor(s)",
              "Use SIMULATE/TRANSIENT or SIMULATE/DYNAMICS.");
    return false;
  }
  if (kin && userStates) {
    run.error(&settings.origin,
              "a kinematic analysis does not integrate DIFF, LSE or TFSISO states; this model "
              "has " +
                  std::to_string(run.system.layout().userDifferential),
              "Use SIMULATE/TRANSIENT or SIMULATE/DYNAMICS.");
    return false;
  }
  if (kin && dof != 0) {
    run.error(&settings.origin,
              "a kinematic analysis needs a model with zero degrees of freedom; this one has " +
                  std::to_string(dof),
              "Add motions or joints until the model is fully determined, or use "
              "SIMULATE/DYNAMICS.");
    return false;
  }
  if (settings.kind == TransientKind::Dynamics && dof == 0 && !userStates)
    run.warning(&settings.origin,
                "the model has zero degrees of freedom; a kinematic analysis "
                "(SIMULATE/KINEMATICS) would be more efficient. As requested, the simulation "
                "goes on with a dynamic analysis");
  return kinematic ? runKinematics(run, settings) : runDynamics(run, settings);
}

bool beginTransient(const AnalysisContext& run, bool kinematic) {
  RunState& s = run.state;
  // MODE of this analysis (its first output step included); HSIZE, ORDER, NJAC and NRHS count
  // from zero for each SIMULATE, as the integrator's statistics do.
  const auto enterAnalysisMode = [&]() {
    run.state.expressions->status().mode =
        kinematic ? model::AnalysisMode::Kinematics : model::AnalysisMode::Dynamics;
    run.state.expressions->status().clearIntegrator();
  };
  if (!s.initialized) {
    // A new run: no turns counted, no DELAY history; after a reprocessing the history
    // carried over from the model before continues (docs/theory.md §11c).
    if (!s.historyCarried) s.expressions->reset();
    s.historyCarried = false;
    if (!solveInitialConditions(run)) return false;
    s.expressions->accept(run.system, s.t, s.y, s.yp);
    enterAnalysisMode();
    if (!run.writeOutputStep(s.t, s.y, s.yp, OutputKind::InitialConditions)) return false;
  }
  enterAnalysisMode();
  run.report.line("");
  run.report.line(" Begin Simulation");
  s.summary.analysis = kinematic ? "kinematic" : "dynamic";
  run.report.progressStart();
  return true;
}

void endTransient(const AnalysisContext& run) {
  run.report.progressDone();
  run.state.summary.time = run.state.t;
  run.report.line(" End Simulation");
}

}  // namespace openmss::analysis
