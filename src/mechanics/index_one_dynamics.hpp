#pragma once
// The equations of motion in index-1 form for explicit integration (docs/theory.md §9d):
// from positions and velocities, the accelerations and multipliers of
//   [M C^T; C 0] [u'; lambda] = [Q; gamma]
// and the projection of a state back onto the position and velocity constraints. Explicit
// methods (analysis/merson_integrator.hpp) call evaluate() several times per step, so it is
// built for speed: the structure of every matrix is fixed for the model and analysed once.

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

class IndexOneDynamics {
 public:
  // The active equations of `system` at construction are the constraints (redundant ones were
  // removed by the initial-condition analysis before).
  explicit IndexOneDynamics(const MultibodySystem& system);
  ~IndexOneDynamics();
  IndexOneDynamics(const IndexOneDynamics&) = delete;
  IndexOneDynamics& operator=(const IndexOneDynamics&) = delete;

  // Why this model cannot be integrated in the index-1 form, naming the statements and the
  // remedy; empty when it can. (User differential states and functions of accelerations or
  // reactions are not supported.)
  std::string unsupportedReason() const;

  // From the positions and velocities in y (state_layout.hpp; Euler parameters are used
  // normalised and written back normalised): the multipliers (and mu = 0) into y and the full
  // y' (r' = v, e' = 1/2 e (x) (0, w), v', w', user rates). False when the KKT matrix is
  // singular at y.
  bool evaluate(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp);

  // Moves y onto Phi(q, t) = 0 (largest |Phi| <= positionTolerance, model length units) and
  // then onto C u = nu, each by the mass-weighted least change (positions to first order, on
  // the factorisation at hand while it contracts; velocities exactly, with S formed at the
  // final positions unless the factorisation at hand is of them). False when the position
  // iteration does not converge. An integrator that evaluates right after projecting should
  // call projectAndEvaluate instead: it forms S there once for both.
  bool project(double t, Eigen::VectorXd& y, double positionTolerance);

  // project(t, y, positionTolerance) then evaluate(t, y, yp), sharing their work: the
  // positions as project() moves them (on the factorisation at hand), then C and S once at the
  // projected positions, serving both the velocity projection (one exact solve) and the
  // accelerations (with gamma recomputed at the projected velocities). The same results to
  // round-off with one factorisation instead of two. `projected` (optional): whether the
  // projection converged (project()'s result); when the positions do not converge y is
  // evaluated where the iteration left it, as project() followed by evaluate() does. Returns
  // evaluate()'s result.
  bool projectAndEvaluate(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp,
                          double positionTolerance, bool* projected = nullptr);

  // Largest |Phi_k(q, t)| and largest |(C u - nu)_k| over the active equations at y.
  double positionViolation(double t, const Eigen::VectorXd& y) const;
  double velocityViolation(double t, const Eigen::VectorXd& y) const;

  // Numeric factorisations done so far (evaluations and projections).
  long factorizations() const { return factorizations_; }

 private:
  friend struct IndexOneDynamicsTestAccess;  // tests/mechanics/index_one_dynamics_test.cpp
  // Runs the block kernels with the block size at run time (tests: the path of blocks of more
  // than 6 equations).
  void useRuntimeSizeKernels();
  // The parts evaluate(), project() and projectAndEvaluate() share. Accelerations, multipliers
  // and y' at y from the factorisation of S and gamma in the engine (both at y).
  bool accelerationsFromFactor(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp);
  // Newton onto |Phi| <= positionTolerance on the factorisation at hand (refactored when the
  // iteration contracts poorly); leaves nu at the final positions in the engine.
  bool projectPositions(double t, Eigen::VectorXd& y, double positionTolerance);
  // Onto C u = nu with C in the engine (at y's positions); `current`: the engine's
  // factorisation is of that C.
  bool projectVelocities(Eigen::VectorXd& y, bool current);
  struct Engine;
  const MultibodySystem& system_;
  std::unique_ptr<Engine> engine_;
  long factorizations_ = 0;
};

}  // namespace openmss::mechanics
