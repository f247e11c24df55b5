#pragma once
// Values of the analysis variables MODE, HSIZE, ORDER, NJAC and NRHS: reads of the session's
// AnalysisStatus (in the run state, expression_run_state.hpp), constant with respect to the
// state (zero derivatives). Without a run state they read as before any analysis.

#include "mechanics/expression_run_state.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// Returns false when `ms` is not an analysis variable.
template <class T>
bool analysisStatusMeasure(const model::Measure& ms, T* out, const ExpressionRunState* run) {
  using K = model::MeasureKind;
  static const model::AnalysisStatus kNone;
  const model::AnalysisStatus& s = run ? run->status() : kNone;
  switch (ms.kind) {
    case K::AnalysisMode:
      *out = T(static_cast<double>(static_cast<int>(s.mode)));
      return true;
    case K::StepSize:
      *out = T(s.stepSize);
      return true;
    case K::IntegratorOrder:
      *out = T(static_cast<double>(s.order));
      return true;
    case K::JacobianCount:
      *out = T(static_cast<double>(s.jacobianEvaluations));
      return true;
    case K::ResidualCount:
      *out = T(static_cast<double>(s.residualEvaluations));
      return true;
    default:
      return false;
  }
}

}  // namespace openmss::mechanics
