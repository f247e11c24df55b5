#include "analysis/initial_conditions_run.hpp"

#include <cmath>

#include "analysis/multibody_dae.hpp"
#include "mechanics/massless_motions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::analysis {
namespace {

const char* kCoordinateNames[6] = {"X", "Y", "Z", "PSI", "THETA", "PHI"};

// A redundant equation (not solved for) violated by more than this after assembly means the
// model cannot close: its data contradict the equations kept.
constexpr double kRedundantTolerance = 1e-6;

}  // namespace

// The residuals of the velocity and acceleration phases at the run state: the largest velocity
// constraint error and the largest force-balance error (docs/theory.md §7).
void phaseResiduals(const AnalysisContext& run, double& verr, double& aerr) {
  const model::Model& m = run.model;
  const mechanics::MultibodySystem& system = run.system;
  const RunState& s = run.state;
  std::vector<int> rows;
  const Eigen::MatrixXd cj = mechanics::activeConstraintJacobian(system, s.y.data(), &rows);
  Eigen::VectorXd u(6 * m.bodyCount());
  for (int b = 0; b < m.bodyCount(); ++b) {
    u.segment<3>(6 * b) = s.y.segment<3>(system.layout().body(b) + mechanics::StateLayout::kV);
    u.segment<3>(6 * b + 3) = s.y.segment<3>(system.layout().body(b) + mechanics::StateLayout::kW);
  }
  verr = 0.0;
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& eq = system.constraints().equations()[rows[r]];
    const double target = eq.motion >= 0 ? system.motionJet(rows[r], s.t).d1 : 0.0;
    verr = std::max(verr, std::abs(cj.row(static_cast<Eigen::Index>(r)).dot(u) - target));
  }
  Eigen::VectorXd g(s.y.size());
  system.residual(s.t, s.y.data(), s.yp.data(), g.data());
  aerr = 0.0;
  for (int b = 0; b < m.bodyCount(); ++b)
    for (int k = 0; k < 6; ++k)
      aerr = std::max(aerr, std::abs(g(system.layout().body(b) + mechanics::StateLayout::kV + k)));
}

mechanics::AssemblyResult assembleForInitialConditions(const AnalysisContext& run) {
  const model::Model& m = run.model;
  mechanics::MultibodySystem& system = run.system;
  RunState& s = run.state;
  const model::InitialConditionSettings& ic = m.initialConditions;
  mechanics::AssemblyOptions o;
  o.tolerance = ic.error;
  o.maxIterations = ic.maxit;
  o.translationLimit = ic.translationLimit;
  o.angleLimit = ic.angleLimit;
  o.pattern = ic.pattern.evaluate;
  o.honourExact = true;
  o.holdJointInitialConditions = true;  // JOINT IC=, ICTRAN=, ICROT=
  mechanics::AssemblyResult r = mechanics::assemblePositions(system, s.t, s.y, o);
  // Equations found redundant at the data set's configuration are not solved for; a model whose
  // redundant equations disagree with the rest (a link too short to reach) cannot close either.
  if (r.converged) {
    const auto& eqs = system.constraints().equations();
    for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
      if (eqs[k].active) continue;
      const double value = std::abs(system.constraintValue(k, s.t, s.y.data()));
      if (value > kRedundantTolerance && value > r.residual) {
        r.converged = false;
        r.residual = value;
        r.worstEquation = k;
      }
    }
  }
  for (const auto& x : r.exactChanged) {
    const model::Part& p = m.parts[m.movingParts[x.body]];
    Diagnostic d;
    d.severity = Severity::Warning;
    d.where = p.where;
    d.subject = "PART/" + std::to_string(p.id);
    d.message = std::string("EXACT=") + kCoordinateNames[x.coordinate] +
                " could not be held: the constraints changed it by " +
                formatNumber("%.6E", x.change) + (x.coordinate < 3 ? "" : " rad");
    d.hint =
        "The joints or motions demand another value; correct the part's position or "
        "remove the coordinate from EXACT.";
    run.report.diagnostic(d);
  }
  return r;
}

bool reportAssembly(const AnalysisContext& run, const mechanics::AssemblyResult& r) {
  const model::Model& m = run.model;
  for (int b = 0; b < m.bodyCount(); ++b)
    if (r.partMoves[b] > 1e-9 || r.partTurns[b] > 1e-9)
      run.report.line("   PART/" + std::to_string(m.parts[m.movingParts[b]].id) + " moved by " +
                      formatNumber("%.6E", r.partMoves[b]) + " and turned by " +
                      formatNumber("%.6E", r.partTurns[b]) + " rad to satisfy the constraints");
  if (r.converged) return true;
  run.error(
      nullptr,
      "the model cannot be assembled: " + run.system.constraints().describe(r.worstEquation, m) +
          " is still violated by " + formatNumber("%.6E", r.residual) + " after " +
          std::to_string(r.iterations) + " iterations",
      "Check the positions and orientations of that joint's I and J markers.");
  return false;
}

namespace {

// A massless part (or one with a zero principal moment) whose zero-inertia motion no
// constraint holds makes the mass matrix singular on the motions the constraints allow: its
// acceleration is undetermined. Named at the PART (docs/theory.md, "Parts as ADAMS accepts
// them") instead of a singular acceleration problem.
bool reportUnheldMasslessMotions(const AnalysisContext& run) {
  const model::Model& m = run.model;
  const auto free = mechanics::unheldMasslessMotions(run.system, run.state.y.data());
  for (const auto& u : free) {
    const model::Part& p = m.parts[m.movingParts[u.body]];
    Diagnostic d;
    d.severity = Severity::Error;
    d.where = p.where;
    d.subject = "PART/" + std::to_string(p.id);
    d.message = std::string(u.rotation ? "has a zero principal moment of inertia" : "has no mass") +
                " and no constraint holds " + mechanics::describeMotion(u) +
                ": its acceleration is undetermined (singular mass matrix)";
    d.hint = u.rotation ? "Give IP=Ixx,Iyy,Izz with positive moments, or hold that rotation "
                          "with a joint (a massless part must be held by constraints)."
                        : "Give MASS=<value> > 0, or hold that translation with a joint (a "
                          "massless part must be held by constraints).";
    run.report.diagnostic(d);
  }
  return free.empty();
}

}  // namespace

bool solveInitialConditions(const AnalysisContext& run) {
  mechanics::MultibodySystem& system = run.system;
  RunState& s = run.state;
  run.report.line("");
  run.report.line(" Begin initial conditions (time " + formatNumber("%.6E", s.t) + ")");
  run.state.expressions->status().mode = model::AnalysisMode::InitialConditions;  // MODE = 3
  const mechanics::AssemblyResult assembly = assembleForInitialConditions(run);
  if (!reportAssembly(run, assembly)) return false;
  mechanics::solveVelocities(system, s.t, s.y, /*holdJointInitialConditions=*/true);
  // VARIABLE values and DIFF derivatives (docs/theory.md §4a): a loop without a solution is
  // named here rather than reported as a singular acceleration problem.
  if (const auto user = mechanics::solveUserAlgebraic(system, s.t, s.y); !user.converged) {
    run.error(
        nullptr,
        "the user equations cannot be solved at the initial state: " +
            MultibodyDae(system).equationName(system.layout().userAlg(std::max(0, user.worstRow))) +
            " is still violated by " + formatNumber("%.3E", user.residual) +
            (user.singular ? " (their Jacobian is singular)"
                           : " after " + std::to_string(user.iterations) + " Newton iterations"),
        "Check the VARIABLE and DIFF functions for an algebraic loop without a solution "
        "(VARIABLE/1, FUNCTION=VARVAL(1)+1 has none), or give IC= starting values.");
    return false;
  }
  if (!reportUnheldMasslessMotions(run)) return false;
  if (!mechanics::solveAccelerations(system, s.t, s.y, s.yp)) {
    run.error(nullptr,
              "the accelerations and constraint forces at the initial state cannot be "
              "determined (singular mass or constraint matrix)",
              "Check that every moving part has mass and inertia, or is fully constrained.");
    return false;
  }
  run.report.line(" End initial conditions: constraints satisfied to " +
                  formatNumber("%.3E", assembly.residual));
  s.initialized = true;
  return true;
}

bool runInitialConditions(const AnalysisContext& run, const InitialConditionsRun& settings) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  s.summary.analysis = "initial conditions";
  run.state.expressions->status().mode = model::AnalysisMode::InitialConditions;  // MODE = 3
  run.state.expressions->status().clearIntegrator();
  if (settings.last == InitialConditionsPhase::Acceleration) {
    if (!solveInitialConditions(run)) return false;
    // Residual checks of the linear phases against VERROR and AERROR.
    const auto& ic = m.initialConditions;
    double verr = 0.0, aerr = 0.0;
    phaseResiduals(run, verr, aerr);
    run.report.line("   Velocity constraint error " + formatNumber("%.3E", verr) +
                    ", force balance error " + formatNumber("%.3E", aerr));
    if (verr > ic.velocityError || aerr > ic.accelerationError) {
      run.error(nullptr,
                "the initial velocities or accelerations are inconsistent: velocity error " +
                    formatNumber("%.3E", verr) + " (VERROR " +
                    formatNumber("%.3E", ic.velocityError) + "), force balance error " +
                    formatNumber("%.3E", aerr) + " (AERROR " +
                    formatNumber("%.3E", ic.accelerationError) + ")",
                "The motions or initial velocities contradict the joints.");
      return false;
    }
  } else {
    const bool velocities = settings.last == InitialConditionsPhase::Velocity;
    run.report.line("");
    run.report.line(" Begin initial conditions (time " + formatNumber("%.6E", s.t) + "), " +
                    (velocities ? "displacements and velocities" : "displacements"));
    const mechanics::AssemblyResult r = assembleForInitialConditions(run);
    if (!reportAssembly(run, r)) return false;
    if (velocities) mechanics::solveVelocities(run.system, s.t, s.y);
    // VARIABLE values and DIFF derivatives of the written step (docs/theory.md §4a).
    mechanics::solveUserAlgebraic(run.system, s.t, s.y);
    run.report.line(" End initial conditions: constraints satisfied to " +
                    formatNumber("%.3E", r.residual));
  }
  ++s.summary.steps;
  s.summary.time = s.t;
  return run.writeOutputStep(s.t, s.y, s.yp, OutputKind::InitialConditions);
}

}  // namespace openmss::analysis
