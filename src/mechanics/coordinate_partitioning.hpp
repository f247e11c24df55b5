#pragma once
// Coordinate partitioning (Wehage and Haug) for ABAM (docs/integrators.md, "ABAM"): the
// constraint Jacobian C (active equations x 6 virtual displacements per moving body, docs/theory.md
// §4) is factored by LU with full pivoting; the pivot columns are the dependent coordinates, the
// others the independent ones. The independent positions and velocities form an ODE
//   x = [z_I; u_I],   x' = [(T(z)^-1 u)_I; u'_I],
// where z are position coordinates measured from a reference configuration (the state at the
// last partitioning): per body the CM displacement and the rotation vector of A_ref^T A (body
// axes), u the velocities (CM velocity in ground, angular velocity in body axes) and T(z) the
// map from z' to u (identity for translations, the right Jacobian of SO(3) for rotations).
// From x at time t the full state is recovered: dependent positions by Newton on Phi(q, t) = 0,
// dependent velocities from C u = Phi_t-terms, accelerations and multipliers by the KKT solve
// (solveAccelerations).

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

class CoordinatePartitioning {
 public:
  explicit CoordinatePartitioning(const MultibodySystem& system);

  // Chooses the independent coordinates at the consistent state y (full DAE layout) and makes
  // y the reference configuration (z = 0). Returns false if C has no usable pivots.
  bool partition(const Eigen::VectorXd& y);
  // Number of independent coordinates (degrees of freedom); the ODE has twice as many.
  int degreesOfFreedom() const { return static_cast<int>(independent_.size()); }
  // The independent coordinates (indices into the 6-per-body virtual displacements).
  const std::vector<int>& independent() const { return independent_; }
  // "X of PART/2", "rotation about body axis z of PART/3", ...
  std::string coordinateName(int column) const;

  // Smallest over largest |pivot| of the dependent block C_D at y, relative to the same
  // ratio at partitioning: 1 right after partition(), falling as the choice degrades.
  double pivotQuality(const Eigen::VectorXd& y) const;
  // Largest rotation (rad) of any body away from its reference orientation at y.
  double largestRotation(const Eigen::VectorXd& y) const;

  // x = [z_I; u_I] of a full state y.
  void reduce(const Eigen::VectorXd& y, Eigen::VectorXd& x) const;
  // The full state (y, y') at time t from x, and x' when xdot is given. `guess` supplies the
  // dependent positions to start Newton from (the last state; its independent part is
  // ignored) and receives the recovered state. Returns false if the position Newton fails
  // or the KKT matrix is singular.
  bool expand(double t, const Eigen::VectorXd& x, Eigen::VectorXd& y, Eigen::VectorXd& yp,
              Eigen::VectorXd* xdot) const;

  // Newton iterations spent on dependent positions so far.
  long positionIterations() const { return positionIterations_; }

 private:
  void configuration(const Eigen::VectorXd& z, Eigen::VectorXd& y) const;
  void coordinates(const Eigen::VectorXd& y, Eigen::VectorXd& z) const;
  // dq/dz: per body identity for translations and the right Jacobian for rotations.
  void tangentMap(const Eigen::VectorXd& z, Eigen::MatrixXd& t) const;
  double pivotRatio(const Eigen::MatrixXd& cDependent) const;

  const MultibodySystem& system_;
  int nb_ = 0;
  std::vector<int> rows_;         // constraint equations used (independent rows of C)
  std::vector<int> dependent_;    // pivot columns
  std::vector<int> independent_;  // the rest
  Eigen::VectorXd reference_;     // full state at partitioning
  double referencePivotRatio_ = 1.0;
  // The method's working state (one partitioning per ABAM integrator, so per SIMULATE), not
  // run data of the model: the last recovered z, Newton's starting guess.
  mutable Eigen::VectorXd zLast_;
  mutable long positionIterations_ = 0;
};

}  // namespace openmss::mechanics
