#pragma once
// The stabilised index-2 (SI2) formulation of the equations of motion (docs/integrators.md,
// "SI2"), after Gear, Gupta and Leimkuhler: the index-3 equations of MultibodyDae plus the
// velocity form of every constraint, C u + Phi_t = 0, with one more multiplier eta per
// constraint entering the kinematic rows as r' = v - C_r^T eta, e' = E (w - C_pi^T eta) / 2 +
// mu e. On the exact solution eta = 0; the velocities now satisfy their constraints at every
// step and can be put under error control with the positions. State: the I3 state, then eta.

#include <vector>

#include "analysis/multibody_dae.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/dae_problem.hpp"

namespace openmss::analysis {

class MultibodyDaeSi2 : public solvers::DaeProblem {
 public:
  explicit MultibodyDaeSi2(const mechanics::MultibodySystem& system)
      : system_(system), i3_(system, false), guard_(!system.model().contacts.empty()) {}  // the SI2 pattern is built once: every CONTACT

  int baseSize() const { return system_.layout().size(); }
  int size() const override { return baseSize() + system_.layout().constraintEquations; }
  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override;
  // The sparse matrix below, made dense; for a model the element-local assembly cannot plan
  // (GCON, repaired patterns) the I3 block by forward AD and the stabilisation terms' position
  // derivatives by central differences (newtonMatrixByDifferences).
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) override;
  // The sparse Newton matrix (docs/theory.md §9a): the element-local assembly of the I3 matrix
  // planned on the SI2 pattern (mechanics/si2_newton_pattern.hpp), which fills the velocity-form
  // rows and the eta columns from the same seeded constraint gradients, exactly. As for I3,
  // every evaluation is checked against one exact directional derivative of the index-3 rows;
  // rows found outside the pattern are made dense and the matrix falls back to the differences.
  bool sparse() const override { return true; }
  bool zerosPersist() const override { return i3_.zerosPersist(); }
  const Eigen::SparseMatrix<double>* pattern() override;
  void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                          Eigen::SparseMatrix<double>& jac) override;
  int patternRepairs() const { return repairs_; }
  // Matrices checked by the guard (PatternGuard: every one with CONTACT).
  long patternChecks() const { return guard_.checks(); }
  void checkEveryMatrix(bool always) { guard_.checkEveryMatrix(always); }
  // Whether the last sparse matrix came from the element-local assembly (not the fallback).
  bool lastElementLocal() const { return lastElementLocal_; }
  void newtonMatrixByDifferences(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                 double cj, Eigen::MatrixXd& jac);
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

  // The dense fallback written into jac's pattern, widened when it finds entries outside it.
  void denseIntoPattern(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                        Eigen::SparseMatrix<double>& jac);
  // Index-3 rows other than the kinematic ones (which only the analytic body blocks and the
  // stabilisation fill) where jac disagrees with an exact directional derivative.
  std::vector<int> rowsOutsidePattern(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                      double cj, const Eigen::SparseMatrix<double>& jac);

  const mechanics::MultibodySystem& system_;
  MultibodyDae i3_;
  mechanics::JacobianPattern pattern_;
  Eigen::SparseMatrix<double> patternMatrix_;
  mechanics::SparseJacobianWork work_;
  mutable std::vector<int> rowColumns_;  // scratch of addStabilisation
  mutable std::vector<double> rowValues_;
  bool havePattern_ = false, lastElementLocal_ = false;
  int repairs_ = 0;
  PatternGuard guard_;
};

}  // namespace openmss::analysis
