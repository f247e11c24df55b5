#pragma once
// Initial-condition analysis (seed chapter 2): find redundant constraint equations, assemble
// positions with the least change to the data set, then velocities, then accelerations and
// constraint forces. The same solves give kinematic analysis and consistent outputs.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

struct RedundancyReport {
  int rank = 0;
  std::vector<int> removed;  // equation indices found redundant (now inactive)
};

// Deactivates every equation whose row of C is a linear combination of earlier rows (earlier
// statements keep their equations, as ADAMS keeps the first of two coaxial hinges).
RedundancyReport removeRedundantConstraints(MultibodySystem& system, const Eigen::VectorXd& y);

struct AssemblyResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;   // largest |Phi| at the end
  int worstEquation = -1;  // equation with the largest |Phi| at the end
  std::vector<double> partMoves;  // per moving body: how far its CM moved
  std::vector<double> partTurns;  // per moving body: how far it turned (rad)
};

// Positions: Gauss-Newton with minimum-norm corrections of body positions and orientations.
AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 double tolerance, int maxIterations);

// Velocities satisfying C u = Phi_t-terms, changing given velocities as little as possible
// (a velocity given in the data set weighs 1e6 times an unset one).
void solveVelocities(const MultibodySystem& system, double t, Eigen::VectorXd& y);

// Accelerations and multipliers from [M C^T; C 0][u'; lambda] = [Q; gamma]. Fills y' for the
// integrator (r' = v, e' from w, v', w') and the multipliers in y. Returns false if singular.
bool solveAccelerations(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                        Eigen::VectorXd& yp);

// C over the active equations (rows) and moving bodies (6 columns each).
Eigen::MatrixXd activeConstraintJacobian(const MultibodySystem& system, const double* y,
                                         std::vector<int>* rows);

}  // namespace openmss::mechanics
