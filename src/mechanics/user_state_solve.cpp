#include "mechanics/user_state_solve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/dual.hpp"

namespace openmss::mechanics {

UserSolveResult solveUserAlgebraic(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                   int maxIterations) {
  using D = Dual<double>;
  const StateLayout& l = system.layout();
  const int na = l.userAlgebraic, n = l.size();
  UserSolveResult result;
  if (na == 0) return result;
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(n);  // algebraic rows do not read y'
  Eigen::VectorXd full(n), g(na);
  Eigen::MatrixXd jac(na, na);
  std::vector<D> yd(n), ypd(n, D(0.0)), gd(n);
  auto rows = [&]() {
    full.setZero();
    system.residual(t, y.data(), yp.data(), full.data());
    for (int k = 0; k < na; ++k) g(k) = full(l.userAlg(k));
    Eigen::Index worst = 0;
    result.residual = g.cwiseAbs().maxCoeff(&worst);
    result.worstRow = static_cast<int>(worst);
  };
  result.converged = false;
  for (int it = 0; it < maxIterations; ++it) {
    rows();
    if (!std::isfinite(result.residual)) return result;
    if (result.residual == 0.0) {
      result.converged = true;
      return result;
    }
    for (int i = 0; i < n; ++i) yd[i] = D(y(i), 0.0);
    for (int c = 0; c < na; ++c) {
      yd[l.userAlg(c)].d = 1.0;
      for (int i = 0; i < n; ++i) gd[i] = D(0.0, 0.0);
      system.residual(t, yd.data(), ypd.data(), gd.data());
      for (int r = 0; r < na; ++r) jac(r, c) = gd[l.userAlg(r)].d;
      yd[l.userAlg(c)].d = 0.0;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(jac);
    if (!lu.isInvertible()) {
      result.singular = true;
      return result;
    }
    const Eigen::VectorXd delta = lu.solve(-g);
    double size = 0.0;
    for (int k = 0; k < na; ++k) {
      y(l.userAlg(k)) += delta(k);
      size = std::max(size, std::abs(delta(k)) / (1.0 + std::abs(y(l.userAlg(k)))));
    }
    result.iterations = it + 1;
    if (size <= 1e-12) {
      rows();
      result.converged = std::isfinite(result.residual);
      return result;
    }
  }
  rows();
  return result;
}

void userStateRates(const MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::VectorXd& yp) {
  const StateLayout& l = system.layout();
  if (l.userDifferential == 0) return;
  Eigen::VectorXd ypZero = yp;
  for (int k = 0; k < l.userDifferential; ++k) ypZero(l.userDiff(k)) = 0.0;
  Eigen::VectorXd full = Eigen::VectorXd::Zero(l.size());
  system.residual(t, y.data(), ypZero.data(), full.data());
  for (int k = 0; k < l.userDifferential; ++k) yp(l.userDiff(k)) = -full(l.userDiff(k));
}

}  // namespace openmss::mechanics
