#pragma once
// A DAE problem that answers every core question (residual, dense Newton matrix, roles, scaling,
// names) from another one. Tests derive from it to hide or withhold one capability of a real
// problem and compare the integrator's two paths on the same equations; what it does not
// forward (the sparse matrix, HHT's one-residual shortcut, ...) keeps DaeProblem's default.

#include <string>

#include "solvers/dae_problem.hpp"

namespace openmss::testing {

class ForwardingProblem : public solvers::DaeProblem {
 public:
  explicit ForwardingProblem(solvers::DaeProblem& inner) : inner_(inner) {}
  int size() const override { return inner_.size(); }
  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    inner_.residual(t, y, yp, g);
  }
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) override {
    inner_.newtonMatrix(t, y, yp, cj, jac);
  }
  bool differential(int i) const override { return inner_.differential(i); }
  bool errorControlled(int i) const override { return inner_.errorControlled(i); }
  int rowScaleExponent(int i) const override { return inner_.rowScaleExponent(i); }
  int unknownScaleExponent(int i) const override { return inner_.unknownScaleExponent(i); }
  Role role(int i) const override { return inner_.role(i); }
  std::string equationName(int row) const override { return inner_.equationName(row); }
  std::string variableName(int i) const override { return inner_.variableName(i); }

 protected:
  solvers::DaeProblem& inner_;
};

}  // namespace openmss::testing
