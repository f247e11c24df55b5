#pragma once
// Values of bound function expressions (FUNCTION=, FX=, ...) on the state, templated on the
// scalar: for dual numbers the derivative is chained through the expression's exact partial
// derivatives with respect to the measures it reads (DM, VR, ...).

#include <type_traits>
#include <vector>

#include "common/dual.hpp"
#include "mechanics/dynamic_measures.hpp"
#include "mechanics/measures.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// Expression value on the scalar T: the chain rule through the host measures for duals.
// `run` supplies the history DELAY reads (expression_run_state.hpp).
template <class T>
T evaluateBound(const model::BoundExpression& b, const T* hostValues, double t,
                std::vector<double>& values, std::vector<double>& grad,
                const ExpressionRunState* run = nullptr) {
  const size_t n = b.measures.size();
  values.resize(n);
  grad.resize(n);
  if constexpr (std::is_same_v<T, double>) {
    return b.expression.evaluate(hostValues, t, run);
  } else {
    for (size_t k = 0; k < n; ++k) values[k] = valueOf(hostValues[k]);
    double dTime = 0.0;
    const double v = b.expression.evaluate(values.data(), t, grad.data(), &dTime, run);
    T out(v);
    out.d = 0.0 * hostValues[0].d;  // zero of the right type
    for (size_t k = 0; k < n; ++k) out.d = out.d + grad[k] * hostValues[k].d;
    return out;
  }
}

// The function's value at state y: its measures evaluated on T, then the expression.
// Accelerations and reactions (dynamic_measures.hpp) come from `reads`: the residual passes
// y' and the constraint set; without it they read as zero. `run` is the analysis's run state
// (cumulative angles, DELAY history); without it those read as at the start of a run.
template <class T>
T evaluateFunction(const model::Model& m, const StateLayout& l, const model::BoundExpression& f,
                   double t, const T* y, std::vector<double>& scratchValues,
                   std::vector<double>& scratchGrad, const DynamicReads<T>* reads = nullptr,
                   const ExpressionRunState* run = nullptr) {
  const size_t n = f.measures.size();
  T host[16];
  std::vector<T> big;
  T* hv = host;
  if (n > 16) {
    big.resize(n);
    hv = big.data();
  }
  for (size_t k = 0; k < n; ++k)
    if (!kinematicMeasure(m, l, f.measures[k], y, &hv[k], run) &&
        !dynamicMeasure(m, l, f.measures[k], y, reads, &hv[k]) &&
        !(reads != nullptr && reads->forceReadBack != nullptr &&
          reads->forceReadBack(reads->forces, f.measures[k], t, y, reads, &hv[k])))
      hv[k] = T(0.0);  // kinds the model builder refuses in functions; never uninitialised
  if (n == 0) {
    T zero(0.0);
    return evaluateBound(f, &zero, t, scratchValues, scratchGrad, run);
  }
  return evaluateBound(f, hv, t, scratchValues, scratchGrad, run);
}

}  // namespace openmss::mechanics
