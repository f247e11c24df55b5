#include "analysis/statics_run.hpp"

#include <cmath>

#include "analysis/initial_conditions_run.hpp"
#include "analysis/statics.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {
namespace {

// The diagnostics of a failed equilibrium search at time t.
void reportFailure(const AnalysisContext& run, double t, const EquilibriumResult& r) {
  const model::Model& m = run.model;
  if (r.status == EquilibriumResult::Status::Unbalanced) {
    run.error(nullptr,
              "there is no static equilibrium at time " + formatNumber("%.6E", t) + ": the " +
                  r.unbalanced->describe(m) +
                  " is a degree of freedom that nothing restrains, and a net generalised "
                  "force of " +
                  formatNumber("%.6E", std::abs(r.unbalanced->load)) +
                  " acts along it (its stiffness was zero at each of the " +
                  std::to_string(r.iterations + 1) + " configurations Newton tried)",
              "Add a spring or a motion on that degree of freedom, balance the load, or run "
              "SIMULATE/DYNAMICS to see where it goes.");
    return;
  }
  std::string text = "static equilibrium not found at time " + formatNumber("%.6E", t) + " in " +
                     std::to_string(r.iterations) + " iterations (MAXIT): largest imbalance " +
                     formatNumber("%.3E", r.imbalance) + " on PART/" +
                     std::to_string(m.parts[m.movingParts[r.worstBody]].id) + ", last correction " +
                     formatNumber("%.3E", r.correction) + ", constraint error " +
                     formatNumber("%.3E", r.constraintError);
  if (r.unbalanced) text += "; the stiffness is singular along the " + r.unbalanced->describe(m);
  run.error(nullptr, text,
            "Raise MAXIT or loosen ERROR/IMBALANCE (EQUILIBRIUM), or start the model "
            "nearer its equilibrium.");
}

// One equilibrium at time t from the run state's positions; on success the run state holds it
// (zero velocities and accelerations) and it is written as an output step.
bool staticEquilibriumAt(const AnalysisContext& run, double t) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  Eigen::VectorXd y = s.y;
  const EquilibriumResult r = solveStaticEquilibrium(run.system, t, y, m.equilibrium);
  if (r.status != EquilibriumResult::Status::Converged) {
    reportFailure(run, t, r);
    return false;
  }
  run.report.line("   Static equilibrium at time " + formatNumber("%.6E", t) + " after " +
                  std::to_string(r.iterations) + " iterations: force imbalance " +
                  formatNumber("%.3E", r.imbalance) + ", constraint error " +
                  formatNumber("%.3E", r.constraintError));
  for (int b = 0; b < m.bodyCount(); ++b) {
    const int o = run.system.layout().body(b);
    const double moved = (y.segment<3>(o) - s.y.segment<3>(o)).norm();
    const double c = std::abs(y.segment<4>(o + mechanics::StateLayout::kE)
                                  .dot(s.y.segment<4>(o + mechanics::StateLayout::kE)));
    const double turned = 2.0 * std::acos(std::min(1.0, c));
    if (moved > 1e-9 || turned > 1e-9)
      run.report.line("     PART/" + std::to_string(m.parts[m.movingParts[b]].id) + " moved by " +
                      formatNumber("%.6E", moved) + " and turned by " +
                      formatNumber("%.6E", turned) + " rad");
  }
  for (const auto& d : r.neutral)
    run.warning(nullptr,
                "the static equilibrium at time " + formatNumber("%.6E", t) + " is neutral: the " +
                    d.describe(m) +
                    " is free and unloaded, so the position along it is the "
                    "one the run started from",
                "");
  for (const auto& d : r.unstable)
    run.warning(nullptr,
                "the static equilibrium at time " + formatNumber("%.6E", t) +
                    " is unstable: its "
                    "stiffness along the " +
                    d.describe(m) + " is negative",
                "A dynamic run started here will leave it; the stable equilibrium, if any, "
                "lies elsewhere.");
  s.y = y;
  s.t = t;
  s.yp = Eigen::VectorXd::Zero(s.y.size());
  ++s.summary.steps;
  // Outputs: positions and reactions of the equilibrium, zero velocities and accelerations.
  return run.writeOutputStep(s.t, s.y, s.yp, OutputKind::Static);
}

}  // namespace

bool runStatics(const AnalysisContext& run, const StaticsRun& settings) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  const std::optional<double>& end = settings.end;
  if (!s.initialized) {
    run.report.line("");
    run.report.line(" Begin initial conditions (time " + formatNumber("%.6E", s.t) +
                    "), displacements");
    if (!reportAssembly(run, assembleForInitialConditions(run))) return false;
  }
  const auto& e = m.equilibrium;
  run.report.line("");
  run.report.line(end ? " Begin quasi-static analysis" : " Begin static equilibrium analysis");
  run.report.line("   ERROR = " + formatNumber("%.3E", e.error) + ", IMBALANCE = " +
                  formatNumber("%.3E", e.imbalance) + ", MAXIT = " + std::to_string(e.maxit) +
                  ", STABILITY = " + formatNumber("%.3E", e.stability) +
                  ", TLIMIT = " + formatNumber("%.3E", e.translationLimit) +
                  ", ALIMIT = " + formatNumber("%.3E", e.angleLimit) + " rad");
  s.summary.analysis = end ? "quasi-static" : "static";
  run.state.expressions->status().mode =
      end ? model::AnalysisMode::QuasiStatics : model::AnalysisMode::Statics;
  run.state.expressions->status().clearIntegrator();
  bool ok = staticEquilibriumAt(run, s.t);
  const double t0 = s.t;
  const long nOut = end ? settings.outputSteps : 0;
  for (long i = 1; ok && i <= nOut; ++i) {
    const double t =
        (i == nOut) ? *end : t0 + static_cast<double>(i) * (*end - t0) / static_cast<double>(nOut);
    // Motions advance: close the constraints at the new time with the least change, then
    // balance the forces.
    const mechanics::AssemblyResult r = mechanics::assemblePositions(
        run.system, t, s.y, m.initialConditions.error, m.initialConditions.maxit);
    if (!r.converged) {
      run.error(nullptr,
                "quasi-static analysis failed at time " + formatNumber("%.6E", t) + ": " +
                    run.system.constraints().describe(r.worstEquation, m) +
                    " cannot be satisfied (residual " + formatNumber("%.3E", r.residual) + ")",
                "The mechanism may lock up or pass a singular position; check the motion "
                "functions.");
      return false;
    }
    ok = staticEquilibriumAt(run, t);
    // Each converged point is an accepted state: COUPLER/GEAR turns counted from it.
    if (ok) s.expressions->commitCoupledAngles(run.system, s.y);
  }
  s.summary.time = s.t;
  if (!ok) return false;
  // A later dynamic run starts from the equilibrium with velocities the motions demand.
  mechanics::solveVelocities(run.system, s.t, s.y);
  Eigen::VectorXd yDyn = s.y, ypDyn;
  if (mechanics::solveAccelerations(run.system, s.t, yDyn, ypDyn)) {
    s.y = yDyn;
    s.yp = ypDyn;
    s.initialized = true;
  }
  run.report.line(" End static analysis");
  return true;
}

}  // namespace openmss::analysis
