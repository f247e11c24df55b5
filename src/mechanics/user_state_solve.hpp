#pragma once
// Consistent values of the user states (docs/theory.md §4a) for given body states: the
// algebraic unknowns (VARIABLE values, DIFF derivatives) by Newton on their own rows, and the
// rates of the differential ones (DIFF, LSE, TFSISO states) from their explicit rows.

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

struct UserSolveResult {
  bool converged = true;
  int iterations = 0;
  double residual = 0.0;  // largest |row| of the user algebraic equations at the end
  int worstRow = -1;      // index among the user algebraic unknowns
  bool singular = false;  // the Jacobian of the rows with respect to the unknowns is singular
};

// Newton on the rows of the user algebraic unknowns, every other entry of y held; the matrix
// is exact (forward-mode AD, one column per unknown), so an algebraic loop among VARIABLEs is
// solved simultaneously. Converged when the last correction is below 1e-12 (1 + |y|).
UserSolveResult solveUserAlgebraic(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                   int maxIterations = 50);

// y' of the user differential states: every such row reads y_i' - h_i(y) = 0, so
// y_i' = h_i(y) = -(row at y_i' = 0). Other entries of yp are left as they are.
void userStateRates(const MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::VectorXd& yp);

}  // namespace openmss::mechanics
