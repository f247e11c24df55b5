#pragma once
// A DAE problem with its sparse Newton matrix hidden, so that an integrator takes its dense
// path: the tests that compare the KLU path with dense LU on the same equations (I3 and SI2)
// wrap the problem in this.

#include <string>

#include "solvers/dae_problem.hpp"

namespace openmss::testing {

class DenseOnlyProblem final : public solvers::DaeProblem {
 public:
  explicit DenseOnlyProblem(solvers::DaeProblem& inner) : inner_(inner) {}
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

 private:
  solvers::DaeProblem& inner_;
};

}  // namespace openmss::testing
