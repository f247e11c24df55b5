#pragma once
// The arguments every analysis driver takes (analysis/*_run.hpp): the model, the equations
// built over it, the run state the analysis advances and the report it writes to. The
// helpers here are what every driver shares: located diagnostics and the output step (the
// redundant-equation check, then the request rows).

#include <Eigen/Dense>
#include <string>

#include "analysis/run_report.hpp"
#include "analysis/run_state.hpp"
#include "common/source_location.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model.hpp"
#include "output/output_frame.hpp"
#include "solvers/pivot_order.hpp"

namespace openmss::analysis {

// Where the request for an analysis came from (a command's location and "SIMULATE/..."), so
// that the analysis names it in its diagnostics. Empty for a request made through the API.
struct RunOrigin {
  SourceLocation where;
  std::string subject;
};

struct AnalysisContext {
  const model::Model& model;
  mechanics::MultibodySystem& system;
  RunState& state;
  RunReport& report;
  // KLU's pivot order for the multistep integrators' sparse Newton matrices: the default
  // except where a test or bench asks for another (solvers/pivot_order.hpp).
  solvers::PivotOrder pivotOrder = solvers::PivotOrder::Default;

  // An error or warning located at `origin`, or at the model's file when `origin` is null.
  void error(const RunOrigin* origin, std::string message, std::string hint = {}) const;
  void warning(const RunOrigin* origin, std::string message, std::string hint = {}) const;

  // One output step at (t, y, yp) of an analysis of the given kind: a redundant equation that
  // has come apart stops the run before the step is written (mechanics/redundancy_check.hpp);
  // otherwise, when the model writes a request file (OUTPUT/REQSAVE), the request rows go to
  // the report, and when a writer wants it (RESULTS), the whole output snapshot
  // (output/output_frame.hpp). Every output step of every analysis passes here.
  bool writeOutputStep(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                       output::OutputKind kind) const;
};

// printf-style formatting of one number for the message file ("%.6E", "%.3E", "%g").
std::string formatNumber(const char* format, double value);

}  // namespace openmss::analysis
