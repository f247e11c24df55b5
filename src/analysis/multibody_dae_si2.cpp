#include "analysis/multibody_dae_si2.hpp"

#include <vector>

namespace openmss::analysis {

using mechanics::StateLayout;

void MultibodyDaeSi2::addStabilisation(double t, const double* y, double* g) const {
  const StateLayout& l = system_.layout();
  const int n = baseSize(), nb = l.bodies;
  const auto& eqs = system_.constraints().equations();
  std::vector<double> row(static_cast<size_t>(6 * nb));
  for (int k = 0; k < l.constraintEquations; ++k) {
    const double eta = y[n + k];
    if (!eqs[k].active) {
      g[n + k] = eta;  // a removed (redundant) equation: its multiplier is zero
      continue;
    }
    double first = 0.0, second = 0.0;
    system_.constraintRates(k, y, &first, &second);
    if (eqs[k].motion >= 0) first -= system_.motionJet(k, t).d1;
    g[n + k] = first;
    if (eta == 0.0) continue;
    system_.constraintRow(k, y, row.data());
    for (int b = 0; b < nb; ++b) {
      const int o = l.body(b);
      const double* c = &row[static_cast<size_t>(6 * b)];
      for (int d = 0; d < 3; ++d) g[o + StateLayout::kR + d] += c[d] * eta;
      // e' = e (x) (0, w - C_pi^T eta) / 2: the eta part moves to the residual with + sign.
      const double x1 = c[3] * eta, x2 = c[4] * eta, x3 = c[5] * eta;
      const double e0 = y[o + StateLayout::kE], e1 = y[o + StateLayout::kE + 1];
      const double e2 = y[o + StateLayout::kE + 2], e3 = y[o + StateLayout::kE + 3];
      g[o + StateLayout::kE + 0] += 0.5 * (-e1 * x1 - e2 * x2 - e3 * x3);
      g[o + StateLayout::kE + 1] += 0.5 * (e0 * x1 + e2 * x3 - e3 * x2);
      g[o + StateLayout::kE + 2] += 0.5 * (e0 * x2 + e3 * x1 - e1 * x3);
      g[o + StateLayout::kE + 3] += 0.5 * (e0 * x3 + e1 * x2 - e2 * x1);
    }
  }
}

void MultibodyDaeSi2::residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                               Eigen::VectorXd& g) {
  g.resize(size());
  system_.residual(t, y.data(), yp.data(), g.data());
  addStabilisation(t, y.data(), g.data());
}

void MultibodyDaeSi2::newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                   double cj, Eigen::MatrixXd& jac) {
  const int n = baseSize(), m = size();
  const StateLayout& l = system_.layout();
  Eigen::MatrixXd base;
  Eigen::VectorXd yBase = y.head(n), ypBase = yp.head(n);
  i3_.newtonMatrix(t, yBase, ypBase, cj, base);
  jac.setZero(m, m);
  jac.topLeftCorner(n, n) = base;
  // The stabilisation terms depend on y only. Their derivatives along the velocities (the
  // velocity rows are C u, linear) and along eta (linear) and positions (nonlinear, scaled by
  // eta or by u) all come from central differences of addStabilisation, column by column; a
  // column the terms do not involve (multipliers, mu, user states) is skipped.
  Eigen::VectorXd yy = y, gPlus(m), gMinus(m);
  for (int c = 0; c < m; ++c) {
    const bool bodyColumn = c < l.userStates() && c % StateLayout::kPerBody != StateLayout::kMu;
    if (!bodyColumn && c < n) continue;
    const double step = 1e-6 * std::max(1.0, std::abs(y(c)));
    gPlus.setZero();
    gMinus.setZero();
    yy(c) = y(c) + step;
    addStabilisation(t, yy.data(), gPlus.data());
    yy(c) = y(c) - step;
    addStabilisation(t, yy.data(), gMinus.data());
    yy(c) = y(c);
    jac.col(c) += (gPlus - gMinus) / (2.0 * step);
  }
}

std::string MultibodyDaeSi2::equationName(int row) const {
  const int n = baseSize();
  if (row < n) return i3_.equationName(row);
  return "velocity form of " + i3_.equationName(system_.layout().lambda(row - n));
}

std::string MultibodyDaeSi2::variableName(int i) const {
  const int n = baseSize();
  if (i < n) return i3_.variableName(i);
  return "stabilising multiplier of " + i3_.equationName(system_.layout().lambda(i - n));
}

}  // namespace openmss::analysis
