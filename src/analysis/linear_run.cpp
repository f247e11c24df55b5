#include "analysis/linear_run.hpp"

#include "analysis/eigen_analysis.hpp"
#include "analysis/initial_conditions_run.hpp"
#include "analysis/linearization.hpp"
#include "analysis/state_matrices.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {
namespace {

// STATEMAT: the files, then the names of the states, inputs and outputs to the message file.
bool writeStateMatrices(const AnalysisContext& run, const LinearRun& settings,
                        const LinearSystem& linear) {
  const model::Model& m = run.model;
  std::vector<std::string> written;
  std::string err;
  const bool wrote = settings.format == StateMatrixFormat::Matlab
                         ? writeMatlabStateMatrices(settings.fileBase, linear, m, written, &err)
                         : writeMatrixxStateMatrices(settings.fileBase, linear, m, written, &err);
  if (!wrote) {
    run.error(&settings.origin, "cannot write the state matrices: " + err,
              "Check that the output directory is writable.");
    return false;
  }
  run.report.line("   States (x' = A x + B u, y = C x + D u):");
  for (size_t s = 0; s < linear.stateNames.size(); ++s)
    run.report.line("     " + std::to_string(s + 1) + "  " + linear.stateNames[s]);
  for (size_t i = 0; i < linear.inputNames.size(); ++i)
    run.report.line("   Input " + std::to_string(i + 1) + ": " + linear.inputNames[i]);
  for (size_t o = 0; o < linear.outputNames.size(); ++o)
    run.report.line("   Output " + std::to_string(o + 1) + ": " + linear.outputNames[o]);
  for (const auto& file : written) run.report.line("   Wrote " + file);
  return true;
}

}  // namespace

bool runLinear(const AnalysisContext& run, const LinearRun& settings) {
  const model::Model& m = run.model;
  RunState& s = run.state;
  // The operating point: the current state, with the initial conditions run first when no
  // analysis has run yet (a following SIMULATE still writes its initial output step).
  if (!s.initialized) {
    if (!solveInitialConditions(run)) return false;
    s.initialized = false;
  }
  run.state.expressions->status().mode = model::AnalysisMode::Linear;  // MODE = 7
  run.state.expressions->status().clearIntegrator();
  Eigen::VectorXd y = s.y, yp = s.yp;
  // Multipliers and accelerations consistent with these positions and velocities: the
  // projected linearisation is exact only where the residual vanishes.
  if (!mechanics::solveAccelerations(run.system, s.t, y, yp)) {
    run.error(&settings.origin,
              "the accelerations and constraint forces at time " + formatNumber("%.6E", s.t) +
                  " cannot be determined (singular mass or constraint matrix)",
              "Check that every moving part has mass and inertia.");
    return false;
  }
  LinearSystem linear;
  std::string why;
  if (!linearize(run.system, s.t, y, yp, settings.request, linear, &why)) {
    run.error(&settings.origin, "no linear analysis: " + why,
              linear.degreesOfFreedom == 0 && why.find("degree of freedom") != std::string::npos
                  ? "Linear analysis needs a model that can move: remove a MOTION or a JOINT."
                  : "See docs/theory.md, \"Linear analysis\".");
    return false;
  }
  run.report.line("");
  run.report.line(" Linear analysis at time " + formatNumber("%.6E", s.t) + ": " +
                  std::to_string(linear.degreesOfFreedom) + " degrees of freedom, " +
                  std::to_string(linear.userStates) + " user states, " +
                  std::to_string(linear.a.rows()) + " states");
  if (!settings.eigen) return writeStateMatrices(run, settings, linear);
  const auto modes = eigenModes(linear);
  for (const auto& line : eigenReport(modes, linear, m, s.t, settings.withoutShapes))
    run.report.line(line);
  return true;
}

}  // namespace openmss::analysis
