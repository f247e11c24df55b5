#pragma once
// The narrow interface between integrators and the equations they integrate: a residual
// G(t, y, y') = 0, its Newton matrix dG/dy + cj dG/dy', and names for diagnostics. GSTIFF-,
// DASSL- and HHT-style methods all work through it.

#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

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

  // What unknown i (and equation row i, its partner) is in a second-order mechanical DAE, for
  // the Newmark family (HHT, NEWMARK; solvers/hht_integrator.hpp): a Position obeys a
  // kinematic row (r' = v, e' = E w / 2), a Velocity a force balance (M v' = forces, the row
  // HHT evaluates partly at the previous step), an Algebraic unknown (multiplier) no
  // derivative, a FirstOrder one a first-order state equation (DIFF, LSE). The default keeps
  // every differential unknown first-order.
  enum class Role { Algebraic, FirstOrder, Position, Velocity };
  virtual Role role(int i) const { return differential(i) ? Role::FirstOrder : Role::Algebraic; }

  // True when y' enters the force-balance (Velocity) rows only through a constant inertia
  // term: G_v(t, y, y') = B y' + f(t, y) with B fixed. HHT then evaluates the rows it weights
  // at the previous step once per step instead of once per corrector iteration
  // (docs/integrators.md, "HHT and NEWMARK"). addRateTerm adds B d to those rows of out.
  virtual bool forceRowsAffineInRates() const { return false; }
  virtual void addRateTerm(const Eigen::VectorXd& /*d*/, Eigen::VectorXd& /*out*/) const {}

  // Optional sparse Newton matrix (docs/theory.md, "Sparse Newton matrix"). A problem that
  // offers one returns true from sparse(), a matrix holding its fixed pattern from pattern()
  // (values irrelevant), and fills the values of a matrix with that pattern in
  // newtonMatrixSparse. It may widen the pattern when it finds an entry outside it (jac then
  // has the new pattern, which pattern() returns from then on).
  virtual bool sparse() const { return false; }
  // Whether entries of the sparse Newton matrix that are exactly zero tend to stay zero, so
  // that the BDF and HHT integrators may factorise without them (solvers/nonzero_pattern.hpp). False where
  // elements switch on and off (contacts), whose entries would keep turning up.
  virtual bool zerosPersist() const { return true; }
  virtual const Eigen::SparseMatrix<double>* pattern() { return nullptr; }
  virtual void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                  double cj, Eigen::SparseMatrix<double>& jac) {
    // Only called when sparse() is true; the dense matrix serves as a fallback.
    Eigen::MatrixXd dense;
    newtonMatrix(t, y, yp, cj, dense);
    jac = dense.sparseView();
  }
};

}  // namespace openmss::solvers
