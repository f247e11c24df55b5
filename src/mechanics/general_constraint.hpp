#pragma once
// The equation of a GCON (docs/theory.md §5c): its FUNCTION evaluated on the frames of the
// markers it reads. The measures (DX, DM, AZ, ...) are computed on the scalar S of the caller
// and the expression is chained on top of them:
//  * S = double: the value;
//  * S = Dual<double> (constraint rows, Newton matrix): the expression's exact partials with
//    respect to its measures (reverse mode) times the measures' directional derivatives;
//  * S = Dual<Dual<double>> (virtual displacements inside the Newton matrix, constraint rates):
//    first derivatives along two directions a, b and the mixed second derivative, from two
//    second-order jet passes along a + b and a - b (polarisation):
//      f_a = (f'(+) + f'(-)) / 2,  f_b = (f'(+) - f'(-)) / 2,  f_ab = (f''(+) - f''(-)) / 4,
//    where the measure jets are h' = h_a +- h_b and h'' = +-2 h_ab. No allocation.

#include <type_traits>

#include "common/dual.hpp"
#include "mechanics/constraint_set.hpp"
#include "mechanics/position_measures.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

template <class S>
S generalConstraintValue(const ConstraintEquation& eq, const Frame<S>* frames) {
  constexpr int kMax = model::GeneralConstraint::kMaxMeasures;
  const model::BoundExpression& f = *eq.function;
  const int n = static_cast<int>(f.measures.size());
  M3<S> identity;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) identity.c[r][c] = S(r == c ? 1.0 : 0.0);
  Frame<S> ground{V3<S>(S(0.0), S(0.0), S(0.0)), identity};
  S host[kMax];
  for (int k = 0; k < n; ++k) {
    const auto& slots = eq.measureSlots[k];
    const Frame<S>& i = slots[0] >= 0 ? frames[slots[0]] : ground;
    const Frame<S>& j = slots[1] >= 0 ? frames[slots[1]] : ground;
    const Frame<S>& axes = slots[2] >= 0 ? frames[slots[2]] : ground;
    positionMeasure(f.measures[k].kind, i.p, i.a, j.p, j.a, axes.a, &host[k]);
  }
  if constexpr (std::is_same_v<S, double>) {
    return f.expression.evaluate(host, 0.0);
  } else if constexpr (std::is_same_v<S, Dual<double>>) {
    double values[kMax] = {}, grad[kMax] = {};
    for (int k = 0; k < n; ++k) values[k] = host[k].v;
    double dTime = 0.0;
    S out(f.expression.evaluate(values, 0.0, grad, &dTime), 0.0);
    for (int k = 0; k < n; ++k) out.d += grad[k] * host[k].d;
    return out;
  } else {
    static_assert(std::is_same_v<S, Dual<Dual<double>>>,
                  "GCON equations are differentiated to second order at most");
    expr::TimeJet plus[kMax], minus[kMax];
    for (int k = 0; k < n; ++k) {
      const double a = host[k].v.d, b = host[k].d.v, ab = host[k].d.d;
      plus[k] = {host[k].v.v, a + b, 2.0 * ab};
      minus[k] = {host[k].v.v, a - b, -2.0 * ab};
    }
    const expr::TimeJet p = f.expression.evaluateJet(plus, 0.0);
    const expr::TimeJet m = f.expression.evaluateJet(minus, 0.0);
    return S(Dual<double>(p.value, 0.5 * (p.d1 + m.d1)),
             Dual<double>(0.5 * (p.d1 - m.d1), 0.25 * (p.d2 - m.d2)));
  }
}

}  // namespace openmss::mechanics
