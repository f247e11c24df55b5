#pragma once
// Values of the user-equation measures VARVAL, DIF, DIF1, ARYVAL, PINVAL and POUVAL: plain
// reads of the state vector (docs/theory.md §4a), templated on the scalar so that functions
// reading them get exact derivatives.

#include "mechanics/expression_run_state.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// The value of VARIABLE k (index into Model::variables).
template <class T>
T variableValue(const StateLayout& l, int k, const T* y) {
  return y[l.userAlg(k)];
}

// Output `row` of LSE/TFSISO e: (C x + D u)_row.
template <class T>
T linearStateOutput(const model::Model& m, const StateLayout& l, int e, int row, const T* y) {
  const model::LinearStateElement& el = m.linearStates[e];
  T out(0.0);
  for (int c = 0; c < el.c.cols(); ++c) out = out + el.c(row, c) * y[l.userDiff(el.firstState + c)];
  if (el.uArray >= 0) {
    const model::DataArray& u = m.arrays[el.uArray];
    for (int c = 0; c < el.d.cols(); ++c)
      out = out + el.d(row, c) * variableValue(l, u.variables[c], y);
  }
  return out;
}

// Entry n (0-based) of ARRAY k. A GSE's discrete states are the run state's (their ICD
// without one).
template <class T>
T arrayValue(const model::Model& m, const StateLayout& l, int k, int n, const T* y,
             const ExpressionRunState* run) {
  const model::DataArray& a = m.arrays[k];
  if (a.gse >= 0) {  // a GSE's states (XD: discrete, constant between samples) or outputs
    const model::GeneralStateElement& e = m.generalStates[a.gse];
    if (a.kind == model::DataArray::Kind::Y) return y[l.userAlg(e.firstOutput + n)];
    if (a.discrete) return T(run ? run->gseDiscrete(a.gse)[static_cast<std::size_t>(n)] : e.icd(n));
    return y[l.userDiff(e.firstState + n)];
  }
  switch (a.kind) {
    case model::DataArray::Kind::X:
      return y[l.userDiff(m.linearStates[a.owner].firstState + n)];
    case model::DataArray::Kind::U:
      return variableValue(l, a.variables[n], y);
    case model::DataArray::Kind::Y:
      return linearStateOutput(m, l, a.owner, n, y);
    case model::DataArray::Kind::IC:
    case model::DataArray::Kind::Constants:
      break;
  }
  return T(a.numbers[n]);
}

// Returns false when `ms` is not a user-equation measure.
template <class T>
bool userMeasure(const model::Model& m, const StateLayout& l, const model::Measure& ms, const T* y,
                 T* out, const ExpressionRunState* run) {
  using K = model::MeasureKind;
  switch (ms.kind) {
    case K::VarVal:
      *out = variableValue(l, ms.element, y);
      return true;
    case K::Dif:
      *out = y[l.userDiff(ms.element)];
      return true;
    case K::Dif1:
      *out = y[l.userAlg(static_cast<int>(m.variables.size()) + ms.element)];
      return true;
    case K::AryVal:
      *out = arrayValue(m, l, ms.element, ms.component - 1, y, run);
      return true;
    case K::PinVal:
      *out = variableValue(l, m.pinputs[ms.element].variables[ms.component - 1], y);
      return true;
    case K::PouVal:
      *out = variableValue(l, m.poutputs[ms.element].variables[ms.component - 1], y);
      return true;
    case K::SenVal:  // a constant between sensor events (run state): no derivative
      *out = T(run ? run->sensorValue(ms.element) : 0.0);
      return true;
    default:
      return false;
  }
}

}  // namespace openmss::mechanics
