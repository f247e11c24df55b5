#pragma once
// The stabilised index-2 (SI2) formulation of the equations of motion (docs/integrators.md,
// "SI2"), after Gear, Gupta and Leimkuhler: the index-3 equations of MultibodyDae plus the
// velocity form of every constraint, C u + Phi_t = 0, with one more multiplier eta per
// constraint entering the kinematic rows as r' = v - C_r^T eta, e' = E (w - C_pi^T eta) / 2 +
// mu e. On the exact solution eta = 0; the velocities now satisfy their constraints at every
// step and can be put under error control with the positions. State: the I3 state, then eta.

#include "analysis/multibody_dae.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/dae_problem.hpp"

namespace openmss::analysis {

class MultibodyDaeSi2 : public solvers::DaeProblem {
 public:
  explicit MultibodyDaeSi2(const mechanics::MultibodySystem& system)
      : system_(system), i3_(system) {}

  int baseSize() const { return system_.layout().size(); }
  int size() const override { return baseSize() + system_.layout().constraintEquations; }
  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override;
  // The I3 block exactly (forward AD); the new rows' and columns' velocity and multiplier
  // derivatives exactly (constraint rows); their position derivatives by central differences.
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) override;
  bool differential(int i) const override { return i < baseSize() && i3_.differential(i); }
  // Positions and velocities (the I3 formulation controls positions only).
  bool errorControlled(int i) const override { return differential(i); }
  // Index 2: constraint rows, velocity rows and both multipliers scale with cj^1.
  int rowScaleExponent(int i) const override { return scaleExponent(i); }
  int unknownScaleExponent(int i) const override { return scaleExponent(i); }
  Role role(int i) const override { return i < baseSize() ? i3_.role(i) : Role::Algebraic; }
  std::string equationName(int row) const override;
  std::string variableName(int i) const override;

 private:
  int scaleExponent(int i) const {
    if (i >= baseSize()) return 1;
    const int e = i3_.rowScaleExponent(i);
    return e == 2 ? 1 : e;
  }
  // Adds the eta terms of the kinematic rows and writes the velocity-constraint rows.
  void addStabilisation(double t, const double* y, double* g) const;

  const mechanics::MultibodySystem& system_;
  MultibodyDae i3_;
};

}  // namespace openmss::analysis
