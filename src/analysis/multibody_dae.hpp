#pragma once
// Adapts the mechanics' equations of motion to the integrators' DaeProblem interface.

#include "mechanics/multibody_system.hpp"
#include "solvers/dae_problem.hpp"

namespace openmss::analysis {

class MultibodyDae : public solvers::DaeProblem {
 public:
  explicit MultibodyDae(const mechanics::MultibodySystem& system) : system_(system) {}

  int size() const override { return system_.layout().size(); }
  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(size());
    system_.residual(t, y.data(), yp.data(), g.data());
  }
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) override {
    system_.newtonMatrix(t, y, yp, cj, jac);
  }
  bool differential(int i) const override { return system_.layout().differential(i); }
  bool errorControlled(int i) const override { return system_.layout().displacement(i); }
  // Constraint rows and multipliers: exponent 2 (index 3); the Euler-parameter normalisation
  // and its multiplier mu: exponent 1 (index 2).
  int rowScaleExponent(int i) const override { return scaleExponent(i); }
  int unknownScaleExponent(int i) const override { return scaleExponent(i); }
  // Newmark-family roles: r, e positions; v, w velocities; mu, user algebraic states and
  // multipliers algebraic; DIFF/LSE/TFSISO states first order.
  Role role(int i) const override {
    const auto& l = system_.layout();
    if (i < l.userStates()) {
      const int o = i % mechanics::StateLayout::kPerBody;
      return o == mechanics::StateLayout::kMu ? Role::Algebraic
             : o < mechanics::StateLayout::kV ? Role::Position
                                              : Role::Velocity;
    }
    return l.isUserDifferential(i) ? Role::FirstOrder : Role::Algebraic;
  }
  std::string equationName(int row) const override;
  std::string variableName(int i) const override;

  // The sparse Newton matrix: structural pattern and compressed forward AD
  // (mechanics/jacobian_pattern.hpp). Every evaluation is checked against one exact
  // directional derivative; rows where an entry falls outside the pattern are made dense (and
  // counted in patternRepairs()), so a pattern rule that misses a dependency costs speed, not
  // convergence.
  bool sparse() const override { return true; }
  const Eigen::SparseMatrix<double>* pattern() override;
  void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                          double cj, Eigen::SparseMatrix<double>& jac) override;
  const mechanics::JacobianPattern& jacobianPattern() {
    pattern();
    return pattern_;
  }
  int patternRepairs() const { return repairs_; }

 private:
  int scaleExponent(int i) const {
    const auto& l = system_.layout();
    if (i >= l.lambda(0)) return 2;
    if (i >= l.userStates()) return 0;  // user equations (docs/theory.md §4a)
    return i % mechanics::StateLayout::kPerBody == mechanics::StateLayout::kMu ? 1 : 0;
  }
  const mechanics::MultibodySystem& system_;
  mechanics::JacobianPattern pattern_;
  Eigen::SparseMatrix<double> patternMatrix_;
  mechanics::SparseJacobianWork work_;
  bool havePattern_ = false;
  int repairs_ = 0;
};

}  // namespace openmss::analysis
