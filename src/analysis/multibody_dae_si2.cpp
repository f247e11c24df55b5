#include "analysis/multibody_dae_si2.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/si2_newton_pattern.hpp"

namespace openmss::analysis {

using mechanics::StateLayout;

void MultibodyDaeSi2::addStabilisation(double t, const double* y, double* g) const {
  const StateLayout& l = system_.layout();
  const int n = baseSize();
  const auto& eqs = system_.constraints().equations();
  for (int k = 0; k < l.constraintEquations; ++k) {
    const double eta = y[n + k];
    if (!eqs[k].active) {
      g[n + k] = eta;  // a removed (redundant) equation: its multiplier is zero
      continue;
    }
    // The velocity form is C u with the same row C (virtual displacements: translations in
    // ground, rotations about the body's axes) as the reactions C^T lambda and C^T eta. On the
    // unit sphere of the Euler parameters it is dPhi/dt along u; off it (inside a Newton
    // iteration) the two differ, and this one is what the sparse Newton matrix differentiates.
    system_.constraintRowEntries(k, y, rowColumns_, rowValues_);
    double first = 0.0;
    for (size_t e = 0; e < rowColumns_.size(); ++e) {
      const int o = l.body(rowColumns_[e] / 6), d = rowColumns_[e] % 6;
      first += rowValues_[e] * y[o + (d < 3 ? StateLayout::kV + d : StateLayout::kW + d - 3)];
    }
    if (eqs[k].motion >= 0) first -= system_.motionJet(k, t).d1;
    g[n + k] = first;
    if (eta == 0.0) continue;
    for (size_t e = 0; e < rowColumns_.size(); ++e) {
      const int o = l.body(rowColumns_[e] / 6), d = rowColumns_[e] % 6;
      const double x = rowValues_[e] * eta;
      if (d < 3) {
        g[o + StateLayout::kR + d] += x;
        continue;
      }
      // e' = E(e) (w - C_pi^T eta) / 2: the eta part moves to the residual with + sign;
      // column d - 3 of E(e).
      const double* q = y + o + StateLayout::kE;
      const double column[3][4] = {
          {-q[1], q[0], q[3], -q[2]}, {-q[2], -q[3], q[0], q[1]}, {-q[3], q[2], -q[1], q[0]}};
      for (int r = 0; r < 4; ++r) g[o + StateLayout::kE + r] += 0.5 * column[d - 3][r] * x;
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
  Eigen::SparseMatrix<double> sparseJac = *pattern();
  newtonMatrixSparse(t, y, yp, cj, sparseJac);
  jac = Eigen::MatrixXd(sparseJac);
}

const Eigen::SparseMatrix<double>* MultibodyDaeSi2::pattern() {
  if (!havePattern_) {
    pattern_ = mechanics::stabilisedNewtonPattern(system_, i3_.jacobianPattern());
    patternMatrix_ = pattern_.matrix();
    havePattern_ = true;
  }
  return &patternMatrix_;
}

void MultibodyDaeSi2::newtonMatrixSparse(double t, const Eigen::VectorXd& y,
                                         const Eigen::VectorXd& yp, double cj,
                                         Eigen::SparseMatrix<double>& jac) {
  pattern();
  if (jac.nonZeros() != pattern_.nonZeros() || jac.rows() != pattern_.size) jac = patternMatrix_;
  if (!work_.local || work_.local->patternStamp() != pattern_.stamp)
    work_.local = std::make_shared<mechanics::LocalNewtonMatrix>(system_, pattern_);
  lastElementLocal_ = work_.local->usable() && work_.local->stabilised();
  if (!lastElementLocal_) {
    denseIntoPattern(t, y, yp, cj, jac);
    return;
  }
  work_.local->assemble(t, y, yp, cj, jac.valuePtr(), work_);
  if (!guard_.due()) return;
  const std::vector<int> outside = rowsOutsidePattern(t, y, yp, cj, jac);
  if (outside.empty()) return;
  // A dependency the pattern rules missed: those rows dense, and from now on the fallback.
  ++repairs_;
  guard_.patternChanged();
  lastElementLocal_ = false;
  mechanics::makeRowsDense(pattern_, outside);
  patternMatrix_ = pattern_.matrix();
  jac = patternMatrix_;
  denseIntoPattern(t, y, yp, cj, jac);
}

void MultibodyDaeSi2::denseIntoPattern(double t, const Eigen::VectorXd& y,
                                       const Eigen::VectorXd& yp, double cj,
                                       Eigen::SparseMatrix<double>& jac) {
  Eigen::MatrixXd dense;
  newtonMatrixByDifferences(t, y, yp, cj, dense);
  const int m = size();
  std::vector<std::vector<int>> rows(static_cast<size_t>(m));
  bool widened = false;
  for (int c = 0; c < m; ++c) {
    const int* first = pattern_.rowIndex.data() + pattern_.columnStart[c];
    const int* last = pattern_.rowIndex.data() + pattern_.columnStart[c + 1];
    for (const int* r = first; r != last; ++r) rows[*r].push_back(c);
    for (int r = 0; r < m; ++r)
      if (dense(r, c) != 0.0 && !std::binary_search(first, last, r)) {
        rows[r].push_back(c);
        widened = true;
      }
  }
  if (widened) {
    const int denseRows = pattern_.denseRows;
    for (auto& row : rows) std::sort(row.begin(), row.end());
    pattern_ = mechanics::patternFromRows(m, std::move(rows));
    pattern_.denseRows = std::max(pattern_.denseRows, denseRows);
    patternMatrix_ = pattern_.matrix();
    jac = patternMatrix_;
  }
  for (int c = 0; c < m; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator e(jac, c); e; ++e)
      e.valueRef() = dense(e.row(), c);
}

std::vector<int> MultibodyDaeSi2::rowsOutsidePattern(double t, const Eigen::VectorXd& y,
                                                     const Eigen::VectorXd& yp, double cj,
                                                     const Eigen::SparseMatrix<double>& jac) {
  using D = Dual<double>;
  const StateLayout& l = system_.layout();
  const int n = baseSize();
  work_.y.resize(static_cast<size_t>(n));
  work_.yp.resize(static_cast<size_t>(n));
  work_.g.assign(static_cast<size_t>(n), D(0.0, 0.0));
  work_.direction.resize(static_cast<size_t>(n));
  work_.product.assign(static_cast<size_t>(n), 0.0);
  work_.magnitude.assign(static_cast<size_t>(n), 0.0);
  // A fixed direction with entries of both signs in [0.5, 1.5], as the I3 check uses.
  unsigned state = 12345u;
  for (int c = 0; c < n; ++c) {
    state = state * 1664525u + 1013904223u;
    const double u = static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
    work_.direction[c] = (u < 0.5 ? -1.0 : 1.0) * (0.5 + 2.0 * std::abs(u - 0.5));
    work_.y[c] = D(y(c), work_.direction[c]);
    work_.yp[c] = D(yp(c), l.differential(c) ? cj * work_.direction[c] : 0.0);
  }
  system_.residual(t, work_.y.data(), work_.yp.data(), work_.g.data());
  for (int c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator e(jac, c); e; ++e) {
      if (e.row() >= n) continue;
      work_.product[e.row()] += e.value() * work_.direction[c];
      work_.magnitude[e.row()] += std::abs(e.value() * work_.direction[c]);
    }
  std::vector<int> rows;
  for (int r = 0; r < n; ++r) {
    if (r < l.userStates() && r % StateLayout::kPerBody < StateLayout::kV) continue;
    const double exact = work_.g[r].d;
    if (!std::isfinite(exact) || !std::isfinite(work_.product[r])) continue;
    if (!(std::abs(exact - work_.product[r]) <= 1e-8 * (work_.magnitude[r] + std::abs(exact))))
      rows.push_back(r);
  }
  return rows;
}

void MultibodyDaeSi2::newtonMatrixByDifferences(double t, const Eigen::VectorXd& y,
                                                const Eigen::VectorXd& yp, double cj,
                                                Eigen::MatrixXd& jac) {
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
