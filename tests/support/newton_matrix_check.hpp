#pragma once
// The check every equation of the mechanics is held to: its Newton matrix dG/dy + cj dG/dy'
// (forward-mode AD) against central differences of the residual along the corrector's
// direction (y + h e_c, y' + cj h e_c).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::testing {

// Central differences of the residual along the corrector's direction (y + h e_c,
// y' + cj h e_c), h = 1e-6 max(1, |y_c|): good to about 1e-8 relative for these residuals.
inline Eigen::MatrixXd centralDifferenceMatrix(const mechanics::MultibodySystem& s, double t,
                                               const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                               double cj) {
  const int n = s.layout().size();
  Eigen::MatrixXd fd(n, n);
  for (int c = 0; c < n; ++c) {
    const double h = 1e-6 * std::max(1.0, std::abs(y(c)));
    Eigen::VectorXd yA = y, yB = y, pA = yp, pB = yp;
    yA(c) += h;
    yB(c) -= h;
    if (s.layout().differential(c)) {
      pA(c) += cj * h;
      pB(c) -= cj * h;
    }
    Eigen::VectorXd gA(n), gB(n);
    s.residual(t, yA.data(), pA.data(), gA.data());
    s.residual(t, yB.data(), pB.data(), gB.data());
    fd.col(c) = (gA - gB) / (2 * h);
  }
  return fd;
}

// Adds a failure for every entry off by more than 1e-6 (1 + |difference quotient|): central
// differences with h = 1e-6 max(1, |y_c|) are good to about 1e-8 relative for these
// residuals, so 1e-6 leaves margin. Returns the largest relative difference; the matrix itself
// in *jacobian when given.
inline double checkNewtonMatrix(const mechanics::MultibodySystem& s, double t,
                                const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                                const std::string& context, Eigen::MatrixXd* jacobian = nullptr) {
  const int n = s.layout().size();
  Eigen::MatrixXd jac;
  s.newtonMatrix(t, y, yp, cj, jac);
  const Eigen::MatrixXd fd = centralDifferenceMatrix(s, t, y, yp, cj);
  double worst = 0.0;
  for (int c = 0; c < n; ++c) {
    for (int r = 0; r < n; ++r) {
      EXPECT_NEAR(jac(r, c), fd(r, c), 1e-6 * (1.0 + std::abs(fd(r, c))))
          << context << ": row " << r << " column " << c;
      worst = std::max(worst, std::abs(jac(r, c) - fd(r, c)) / (1.0 + std::abs(fd(r, c))));
    }
  }
  if (jacobian) *jacobian = jac;
  return worst;
}

// Every nonzero of the dense Newton matrix `jac` lies in the structural pattern, and no row of
// the pattern is dense (every dependency was resolved). Returns the number of nonzeros checked.
inline int expectPatternCovers(const mechanics::MultibodySystem& s, const Eigen::MatrixXd& jac) {
  const mechanics::JacobianPattern p = mechanics::newtonMatrixPattern(s);
  EXPECT_EQ(p.denseRows, 0);
  Eigen::MatrixXi in = Eigen::MatrixXi::Zero(p.size, p.size);
  for (int c = 0; c < p.size; ++c)
    for (int k = p.columnStart[c]; k < p.columnStart[c + 1]; ++k) in(p.rowIndex[k], c) = 1;
  int nonzeros = 0;
  for (int r = 0; r < p.size; ++r)
    for (int c = 0; c < p.size; ++c)
      if (jac(r, c) != 0.0) {
        ++nonzeros;
        EXPECT_EQ(in(r, c), 1) << "entry " << r << ", " << c;
      }
  return nonzeros;
}

}  // namespace openmss::testing
