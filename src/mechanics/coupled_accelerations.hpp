#pragma once
// Accelerations, multipliers and user algebraic unknowns solved together when some force,
// VARIABLE or DIFF function reads accelerations or reactions (docs/theory.md §4b). The plain
// acceleration solve [M C^T; C 0][u'; lambda] = [Q; gamma] takes the applied forces Q from the
// positions and velocities alone; here Q (and the VARIABLEs) depend on u' and lambda too, so
// the force-balance rows of the DAE residual, the acceleration-level constraints C u' = gamma
// and the user algebraic rows are one nonlinear system, solved by Newton with the exact
// (forward-mode AD) Jacobian.

#include <string>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

// True when a function of an SFORCE, VFORCE/VTORQUE/GFORCE, VARIABLE or DIFF reads an
// acceleration or a JOINT/JPRIM/MOTION reaction.
bool readsAccelerationsOrReactions(const model::Model& model);
// True when an applied force's function (SFORCE, VFORCE, VTORQUE, GFORCE) reads a JOINT, JPRIM
// or MOTION reaction: its balance rows then depend on multipliers beyond C^T lambda.
bool forceFunctionsReadReactions(const model::Model& model);

// y' of the kinematic rows (r' = v, e' = 1/2 e (x) (0, w)) for the current velocities: the
// rows the acceleration solves (coupled and dense KKT, initial_conditions.cpp) fill alike.
void kinematicRates(const StateLayout& l, const Eigen::VectorXd& y, Eigen::VectorXd& yp);

struct CoupledAccelerationResult {
  bool converged = false;
  bool singular = false;  // the Jacobian of the coupled system is singular
  int iterations = 0;
  double residual = 0.0;  // largest |row| at the end
};

// Fills y' (r' = v, e' from w, v', w', user differential rates) and the multipliers and user
// algebraic unknowns of y, positions and velocities held. Converged when the last Newton
// correction is below 1e-12 (1 + |unknown|) in every unknown.
CoupledAccelerationResult solveCoupledAccelerations(const MultibodySystem& system, double t,
                                                    Eigen::VectorXd& y, Eigen::VectorXd& yp,
                                                    int maxIterations = 25);

}  // namespace openmss::mechanics
