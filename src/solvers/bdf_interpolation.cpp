// BdfIntegrator's interpolant over the last accepted step: the corrector polynomial through the
// last k + 1 solutions, for output times, SENSOR events and the contact event locator
// (docs/theory.md §6c, "Events").
#include <algorithm>

#include "solvers/bdf_integrator.hpp"
#include "solvers/bdf_polynomials.hpp"

namespace openmss::solvers {

using bdf::lagrangeAt;

void BdfIntegrator::interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  const int n = std::min(lastStepOrder_ + 1, static_cast<int>(ts_.size()));
  if (n < 2) {
    y = y_ + (s - t_) * yp_;
    yp = yp_;
    return;
  }
  double nodes[8] = {}, w[8], dw[8];
  for (int j = 0; j < n; ++j) nodes[j] = ts_[j];
  // At a node the Lagrange weights are a unit vector; the derivative still needs the
  // polynomial, so evaluate a hair away from the node in that case.
  for (int j = 0; j < n; ++j)
    if (s == nodes[j]) {
      if (j == 0) {
        y = y_;
        yp = yp_;
        return;
      }
    }
  double x = s;
  for (int j = 1; j < n; ++j)
    if (x == nodes[j]) x = nodes[j] + 1e-9 * (nodes[0] - nodes[j]);
  lagrangeAt(nodes, n, x, w, dw);
  y.setZero(y_.size());
  yp.setZero(y_.size());
  for (int j = 0; j < n; ++j) {
    y += w[j] * ys_[j];
    yp += dw[j] * ys_[j];
  }
  if (x != s) y = ys_[static_cast<size_t>(std::find(nodes, nodes + n, s) - nodes)];
}

// interpolate()'s y component by component: the same operations in the same order on each
// entry (the build does not contract a*b+c, CMakeLists.txt), so the same bits.
void BdfIntegrator::interpolateComponents(double s, const std::vector<int>& components,
                                          Eigen::VectorXd& y) const {
  if (y.size() != y_.size()) y = y_;
  const int n = std::min(lastStepOrder_ + 1, static_cast<int>(ts_.size()));
  if (n < 2) {
    for (const int i : components) y(i) = y_(i) + (s - t_) * yp_(i);
    return;
  }
  double nodes[8] = {}, w[8], dw[8];
  for (int j = 0; j < n; ++j) nodes[j] = ts_[j];
  if (s == nodes[0]) {
    for (const int i : components) y(i) = y_(i);
    return;
  }
  double x = s;
  for (int j = 1; j < n; ++j)
    if (x == nodes[j]) x = nodes[j] + 1e-9 * (nodes[0] - nodes[j]);
  if (x != s) {
    const Eigen::VectorXd& at = ys_[static_cast<size_t>(std::find(nodes, nodes + n, s) - nodes)];
    for (const int i : components) y(i) = at(i);
    return;
  }
  lagrangeAt(nodes, n, x, w, dw);
  for (const int i : components) {
    double v = 0.0;
    for (int j = 0; j < n; ++j) v += w[j] * ys_[static_cast<size_t>(j)](i);
    y(i) = v;
  }
}

}  // namespace openmss::solvers
