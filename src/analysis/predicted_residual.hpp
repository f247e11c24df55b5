#pragma once
// The equation a failed step could not satisfy, for the integrators that advance an ODE form
// of the equations (ABAM, MERSON) and so have no corrector residual of their own: the DAE
// residual at a forward-Euler prediction from the last accepted state (at that state itself
// every residual is zero). Fills failure.worstEquation and failure.worstResidual.

#include <cmath>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

inline void notePredictedResidual(const mechanics::MultibodySystem& system, double t, double h,
                                  const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                  solvers::IntegratorFailure& failure) {
  const int n = system.layout().size();
  if (y.size() != n || yp.size() != n) return;
  const Eigen::VectorXd yPredicted = y + h * yp;
  Eigen::VectorXd g(n);
  system.residual(t + h, yPredicted.data(), yp.data(), g.data());
  for (int i = 0; i < n; ++i) {
    const double r = std::abs(g(i));
    if (failure.worstEquation < 0 || !std::isfinite(r) || r > failure.worstResidual) {
      failure.worstEquation = i;
      failure.worstResidual = r;
      if (!std::isfinite(r)) break;
    }
  }
}

}  // namespace openmss::analysis
