#include "expr/delay_history.hpp"

#include <algorithm>

namespace openmss::expr {

void DelayHistory::record(double t, double v) {
  const auto keep = std::lower_bound(times_.begin(), times_.end(), t) - times_.begin();
  times_.resize(static_cast<std::size_t>(keep));
  values_.resize(static_cast<std::size_t>(keep));
  times_.push_back(t);
  values_.push_back(v);
}

void DelayHistory::clear() {
  times_.clear();
  values_.clear();
}

DelayLookup DelayHistory::at(double s) const {
  const auto n = static_cast<std::ptrdiff_t>(times_.size());
  // First record after s; the stencil takes two records on each side of s when it can.
  const std::ptrdiff_t upper = std::upper_bound(times_.begin(), times_.end(), s) - times_.begin();
  const std::ptrdiff_t points = std::min<std::ptrdiff_t>(4, n);
  const std::ptrdiff_t first = std::clamp<std::ptrdiff_t>(upper - 2, 0, n - points);
  const double* t = times_.data() + first;
  const double* v = values_.data() + first;
  // Lagrange basis: L_i(s) = prod_{j != i} (s - t_j) / (t_i - t_j), and its derivative.
  DelayLookup out;
  for (std::ptrdiff_t i = 0; i < points; ++i) {
    double numerator = 1.0, denominator = 1.0, derivative = 0.0;
    for (std::ptrdiff_t j = 0; j < points; ++j) {
      if (j == i) continue;
      denominator *= t[i] - t[j];
      // d/ds of the running product: product rule, one factor at a time.
      derivative = derivative * (s - t[j]) + numerator;
      numerator *= s - t[j];
    }
    out.value += v[i] * numerator / denominator;
    out.slope += v[i] * derivative / denominator;
  }
  return out;
}

}  // namespace openmss::expr
