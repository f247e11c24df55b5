#include "mechanics/si2_newton_pattern.hpp"

#include <algorithm>
#include <vector>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

JacobianPattern stabilisedNewtonPattern(const MultibodySystem& system, const JacobianPattern& i3) {
  using L = StateLayout;
  const StateLayout& l = system.layout();
  const int n = i3.size, m = l.constraintEquations;
  std::vector<std::vector<int>> rows(static_cast<size_t>(n + m));
  for (int c = 0; c < n; ++c)
    for (int e = i3.columnStart[c]; e < i3.columnStart[c + 1]; ++e)
      rows[i3.rowIndex[e]].push_back(c);
  std::vector<int> bodies;
  for (int k = 0; k < m; ++k) {
    const int velocityRow = n + k;
    // The bodies whose positions the equation's value row reads.
    bodies.clear();
    for (int c : rows[l.lambda(k)])
      if (c < l.userStates() && c % L::kPerBody < L::kV) {
        const int b = c / L::kPerBody;
        if (bodies.empty() || bodies.back() != b) bodies.push_back(b);
      }
    std::vector<int>& velocityForm = rows[velocityRow];
    velocityForm.push_back(velocityRow);  // eta_k = 0 when the equation is removed
    for (int b : bodies)
      for (int c = L::kR; c < L::kMu; ++c) velocityForm.push_back(l.body(b) + c);
    for (int b : bodies)
      for (int r = L::kR; r < L::kV; ++r) {
        std::vector<int>& kinematic = rows[l.body(b) + r];
        for (int other : bodies)
          for (int c = L::kR; c < L::kV; ++c) kinematic.push_back(l.body(other) + c);
        kinematic.push_back(velocityRow);
      }
  }
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  JacobianPattern p = patternFromRows(n + m, std::move(rows));
  p.denseRows = i3.denseRows;
  p.contacts = i3.contacts;
  return p;
}

}  // namespace openmss::mechanics
