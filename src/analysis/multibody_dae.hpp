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
  std::string equationName(int row) const override;
  std::string variableName(int i) const override;

 private:
  int scaleExponent(int i) const {
    const auto& l = system_.layout();
    if (i >= l.lambda(0)) return 2;
    if (i >= l.userStates()) return 0;  // user equations (docs/theory.md §4a)
    return i % mechanics::StateLayout::kPerBody == mechanics::StateLayout::kMu ? 1 : 0;
  }
  const mechanics::MultibodySystem& system_;
};

}  // namespace openmss::analysis
