#pragma once
// Static equilibrium (SIMULATE/STATICS, docs/theory.md "Statics"): the positions and constraint
// forces at which every applied force, gravity and reaction balance with zero velocity and
// acceleration, found by Newton-Raphson on the balance and constraint equations (not by a damped
// dynamic run). A degree of freedom the constraints leave free and no force restrains, while a
// load acts along it, has no equilibrium: it is detected and named instead of iterated on.

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "mechanics/multibody_system.hpp"
#include "model/analysis_settings.hpp"

namespace openmss::analysis {

// The equations of statics at (t, y): per moving body the force and moment balance (rows
// kV..kW+2 of MultibodySystem::residual with v = w = 0 and y' = 0; force in ground, moment in
// body axes), then Phi = 0 for each active constraint equation. Velocities in y are ignored.
void staticResidual(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::VectorXd& g);

// Exact Jacobian of staticResidual with respect to the unknowns (per body a ground translation
// delta r and a body-axes rotation delta pi, then the active multipliers), by forward-mode AD of
// the residual along each unknown's direction. Also returns the active equation indices.
void staticJacobian(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::MatrixXd& jac, std::vector<int>* activeRows = nullptr);

// de/d(delta pi) of the Euler parameters e for a body-axes virtual rotation delta pi (4 x 3):
// the chain from body virtual displacements to the residual's coordinates, shared by the
// static Jacobian and the linearization (linearization.cpp).
Eigen::Matrix<double, 4, 3> eulerParameterRates(const Eigen::Vector4d& e);

// Applies a Newton correction (6 per body, then one per active multiplier) to y.
void applyStaticCorrection(const mechanics::MultibodySystem& system,
                           const std::vector<int>& activeRows, const Eigen::VectorXd& delta,
                           Eigen::VectorXd& y);

// A direction of motion the constraints allow, reduced to the part that moves most in it.
struct MotionDirection {
  int body = -1;           // moving body index
  bool rotation = false;   // mostly a rotation (else a translation)
  Eigen::Vector3d axis;    // unit vector, ground axes
  double stiffness = 0.0;  // generalised stiffness along it (scaled units, see theory.md)
  double load = 0.0;       // unbalanced generalised force along it (force units)
  // "rotation of PART/2 about (0, 0, 1)"
  std::string describe(const model::Model& model) const;
};

struct EquilibriumResult {
  enum class Status { Converged, Unbalanced, NotConverged };
  Status status = Status::NotConverged;
  int iterations = 0;
  double imbalance = 0.0;                     // largest |force or moment residual| at the end
  double correction = 0.0;                    // largest position correction of the last iteration
  double constraintError = 0.0;               // largest |Phi| at the end
  int worstBody = -1;                         // body with the largest imbalance at the end
  std::optional<MotionDirection> unbalanced;  // status Unbalanced: the free, loaded direction
  std::vector<MotionDirection> neutral;   // free directions without load (equilibrium not unique)
  std::vector<MotionDirection> unstable;  // directions of negative stiffness at the solution
};

// Newton-Raphson from y (positions assembled, or nearly so) with the EQUILIBRIUM parameters.
// On success y holds the equilibrium: positions, zero velocities, the multipliers of the active
// equations (reaction forces) and mu = 0.
EquilibriumResult solveStaticEquilibrium(const mechanics::MultibodySystem& system, double t,
                                         Eigen::VectorXd& y,
                                         const model::EquilibriumSettings& settings);

}  // namespace openmss::analysis
