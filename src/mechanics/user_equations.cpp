#include "mechanics/user_equations.hpp"

namespace openmss::mechanics {

std::vector<bool> UserEquations::staticHold() const {
  std::vector<bool> held;
  for (const model::Diff& d : model_->diffs) held.push_back(d.staticHold);
  for (const model::LinearStateElement& e : model_->linearStates)
    for (int i = 0; i < e.a.rows(); ++i) held.push_back(e.staticHold);
  for (const model::GeneralStateElement& e : model_->generalStates)
    for (int i = 0; i < e.ns; ++i) held.push_back(e.staticHold);
  return held;
}

void UserEquations::initialValues(double* y) const {
  const model::Model& m = *model_;
  const int nv = static_cast<int>(m.variables.size());
  for (int k = 0; k < nv; ++k) y[layout_.userAlg(k)] = m.variables[k].ic.value_or(0.0);
  for (int k = 0; k < static_cast<int>(m.diffs.size()); ++k) {
    y[layout_.userDiff(k)] = m.diffs[k].ic;
    y[layout_.userAlg(nv + k)] = m.diffs[k].icDerivative.value_or(0.0);
  }
  for (const model::LinearStateElement& e : m.linearStates)
    for (int i = 0; i < e.a.rows(); ++i)
      y[layout_.userDiff(e.firstState + i)] = i < e.ic.size() ? e.ic(i) : 0.0;
  for (const model::GeneralStateElement& e : m.generalStates) {
    for (int i = 0; i < e.ns; ++i) y[layout_.userDiff(e.firstState + i)] = e.ic(i);
    for (int j = 0; j < e.no; ++j) y[layout_.userAlg(e.firstOutput + j)] = 0.0;  // solved
  }
}

}  // namespace openmss::mechanics
