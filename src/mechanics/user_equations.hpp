#pragma once
// The user equations (docs/theory.md §4a) as rows of the DAE residual, templated on the scalar
// like the rest of MultibodySystem::residual, so that the Newton matrix holds their exact
// derivatives (through the expressions' partials and the measures' dual numbers):
//
//   VARIABLE k:      v_k - f_k(y, t) = 0                                (algebraic)
//   DIFF k:          y_k' - z_k = 0                                     (differential)
//                    z_k - f_k(y, t) = 0      or, IMPLICIT, f_k(y, t) = 0 (algebraic)
//   LSE / TFSISO:    x' - (A x + B u) = 0                               (differential)
//   GSE:             x' - f(x, xd, u, t) = 0, y - g(x, xd, u, t) = 0    (general_state_rows.hpp)
//
// z_k is DIF1(k): an algebraic unknown equal to y_k', so that every function (and every
// output) reads y_k' from the state vector alone.

#include <vector>

#include "mechanics/bound_function.hpp"
#include "mechanics/general_state_rows.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

class UserEquations {
 public:
  explicit UserEquations(const model::Model& model) : model_(&model), gse_(model) {}
  // The owner's layout (user blocks must be set).
  void setLayout(const StateLayout& layout) {
    layout_ = layout;
    gse_.setLayout(layout);
  }
  const GeneralStateRows& generalStates() const { return gse_; }

  // `reads` lets functions read reactions (JOINT, MOTION, JPRIM) and applied forces (SFORCE,
  // BUSH, ..., FX..TM; its force evaluator); y' gives accelerations. Null: y' and nothing else.
  template <class T>
  void addToResidual(double t, const T* y, const T* yp, T* g,
                     const DynamicReads<T>* reads = nullptr) const;

  // User differential states (index among them) that STATIC_HOLD keeps fixed in statics.
  std::vector<bool> staticHold() const;
  // Initial values: DIFF IC (and IC derivative guess), LSE IC, VARIABLE IC (guess), GSE IC
  // (its discrete states start at ICD in the run state, expression_run_state.hpp).
  void initialValues(double* y) const;

 private:
  const model::Model* model_;
  StateLayout layout_;
  GeneralStateRows gse_;
  // Pure scratch, overwritten by every evaluation: no result depends on earlier contents.
  mutable std::vector<double> scratchValues_, scratchGrad_;
  const ExpressionRunState* run_ = nullptr;  // cumulative angles, DELAY history (the session's)

 public:
  void setRunState(const ExpressionRunState* run) {
    run_ = run;
    gse_.setRunState(run);
  }
};

template <class T>
void UserEquations::addToResidual(double t, const T* y, const T* yp, T* g,
                                  const DynamicReads<T>* dynamicReads) const {
  const model::Model& m = *model_;
  const StateLayout& l = layout_;
  DynamicReads<T> reads = dynamicReads != nullptr ? *dynamicReads : DynamicReads<T>{};
  reads.yp = yp;
  const int nv = static_cast<int>(m.variables.size());
  for (int k = 0; k < nv; ++k) {
    const T f = evaluateFunction(m, l, m.variables[k].function, t, y, scratchValues_,
                                 scratchGrad_, &reads, run_);
    g[l.userAlg(k)] = y[l.userAlg(k)] - f;
  }
  for (int k = 0; k < static_cast<int>(m.diffs.size()); ++k) {
    const int state = l.userDiff(k), rate = l.userAlg(nv + k);
    g[state] = yp[state] - y[rate];
    const T f = evaluateFunction(m, l, m.diffs[k].function, t, y, scratchValues_, scratchGrad_,
                                 &reads, run_);
    g[rate] = m.diffs[k].implicit ? f : y[rate] - f;
  }
  for (const model::LinearStateElement& e : m.linearStates) {
    const int n = static_cast<int>(e.a.rows());
    for (int i = 0; i < n; ++i) {
      const int row = l.userDiff(e.firstState + i);
      T rhs(0.0);
      for (int c = 0; c < n; ++c) rhs = rhs + e.a(i, c) * y[l.userDiff(e.firstState + c)];
      if (e.uArray >= 0) {
        const model::DataArray& u = m.arrays[e.uArray];
        for (int c = 0; c < e.b.cols(); ++c) rhs = rhs + e.b(i, c) * y[l.userAlg(u.variables[c])];
      }
      g[row] = yp[row] - rhs;
    }
  }
  gse_.addToResidual(t, y, yp, g);
}

}  // namespace openmss::mechanics
