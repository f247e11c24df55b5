#pragma once
// The narrow interface between integrators and the equations they integrate: a residual
// G(t, y, y') = 0, its Newton matrix dG/dy + cj dG/dy', and names for diagnostics. GSTIFF-,
// DASSL- and HHT-style methods all work through it.

#include <string>

#include <Eigen/Dense>

namespace openmss::solvers {

class DaeProblem {
 public:
  virtual ~DaeProblem() = default;
  virtual int size() const = 0;
  virtual void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                        Eigen::VectorXd& g) = 0;
  virtual void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                            double cj, Eigen::MatrixXd& jac) = 0;
  // y'_i appears in G (false for algebraic unknowns such as Lagrange multipliers).
  virtual bool differential(int i) const = 0;
  // y_i is under local-error control.
  virtual bool errorControlled(int i) const = 0;
  // Scaling of the Newton matrix for pivoting: row i is multiplied by cj^rowScaleExponent(i)
  // and unknown i is solved for in units of cj^unknownScaleExponent(i). For an index-3
  // mechanical DAE both are 2 for constraint equations and multipliers, so that the matrix
  // [M cj^2, C^T; C, 0] is solved in the balanced form [M, C^T; C, 0] (its condition would
  // otherwise grow like cj^2 = 1/h^2 as steps shrink).
  virtual int rowScaleExponent(int i) const = 0;
  virtual int unknownScaleExponent(int i) const = 0;
  virtual std::string equationName(int row) const = 0;
  virtual std::string variableName(int i) const = 0;
};

}  // namespace openmss::solvers
