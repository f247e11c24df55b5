#include "analysis/linearization.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/statics.hpp"
#include "common/dual.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/pose.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;
using D = Dual<double>;

// Rank threshold of C, as for redundant constraints (docs/theory.md §5).
constexpr double kRankTolerance = 1e-9;

// C in ground coordinates: columns 6 b + 3..5 are rotations about the ground axes, i.e. the
// body-axes rotation A^T dtheta. Rows: the active equations.
Eigen::MatrixXd groundConstraintJacobian(const mechanics::MultibodySystem& system,
                                         const Eigen::VectorXd& y) {
  const StateLayout& l = system.layout();
  Eigen::MatrixXd c = mechanics::activeConstraintJacobian(system, y.data(), nullptr);
  for (int b = 0; b < l.bodies; ++b) {
    const Eigen::Matrix3d a = toEigen(mechanics::bodyPose(l, b, y.data()).a);
    c.middleCols<3>(6 * b + 3) = c.middleCols<3>(6 * b + 3) * a.transpose();
  }
  return c;
}

// Orthonormal basis of the null space of c (6 nb columns).
Eigen::MatrixXd nullSpace(const Eigen::MatrixXd& c, int columns) {
  if (c.rows() == 0) return Eigen::MatrixXd::Identity(columns, columns);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i)
    if (sv(i) > kRankTolerance * sv(0)) ++rank;
  return svd.matrixV().rightCols(columns - rank);
}

// The same span with one part coordinate per column: the rows S of the basis picked by
// column-pivoted QR (the best-conditioned n coordinates) become the identity.
Eigen::MatrixXd partCoordinateBasis(const Eigen::MatrixXd& n, std::vector<int>& selected) {
  const int dof = static_cast<int>(n.cols());
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(n.transpose());
  selected.clear();
  for (int j = 0; j < dof; ++j)
    selected.push_back(static_cast<int>(qr.colsPermutation().indices()(j)));
  std::sort(selected.begin(), selected.end());  // states in part order
  Eigen::MatrixXd ns(dof, dof);
  for (int j = 0; j < dof; ++j) ns.row(j) = n.row(selected[j]);
  Eigen::MatrixXd p = n * ns.inverse();
  // Exact zeros and ones where they belong (round-off of the inverse otherwise shows there).
  for (int j = 0; j < dof; ++j) {
    p.row(selected[j]).setZero();
    p(selected[j], j) = 1.0;
  }
  return p;
}

// One forward-mode pass of the residual along (dy, dyp).
class ResidualDerivative {
 public:
  ResidualDerivative(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                     const Eigen::VectorXd& yp)
      : system_(system), t_(t), n_(static_cast<int>(y.size())), y_(n_), yp_(n_), g_(n_) {
    for (int i = 0; i < n_; ++i) {
      y_[i] = D(y(i), 0.0);
      yp_[i] = D(yp(i), 0.0);
    }
  }
  Eigen::VectorXd along(const Eigen::VectorXd& dy, const Eigen::VectorXd& dyp) {
    for (int i = 0; i < n_; ++i) {
      y_[i].d = dy(i);
      yp_[i].d = dyp(i);
      g_[i] = D(0.0);
    }
    system_.residual(t_, y_.data(), yp_.data(), g_.data());
    Eigen::VectorXd out(n_);
    for (int i = 0; i < n_; ++i) out(i) = g_[i].d;
    return out;
  }

 private:
  const mechanics::MultibodySystem& system_;
  double t_;
  int n_;
  std::vector<D> y_, yp_, g_;
};

}  // namespace

const char* partCoordinateName(int k, bool rate) {
  static const char* pos[6] = {"X", "Y", "Z", "RX", "RY", "RZ"};
  static const char* vel[6] = {"VX", "VY", "VZ", "WX", "WY", "WZ"};
  return rate ? vel[k] : pos[k];
}

int tangentDimension(const mechanics::MultibodySystem& system, const Eigen::VectorXd& y) {
  const int cols = 6 * system.layout().bodies;
  return static_cast<int>(nullSpace(groundConstraintJacobian(system, y), cols).cols());
}

bool linearize(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
               const Eigen::VectorXd& yp, const LinearizationRequest& request, LinearSystem& out,
               std::string* whyNot) {
  auto refuse = [&](const std::string& why) {
    if (whyNot) *whyNot = why;
    return false;
  };
  const StateLayout& l = system.layout();
  const model::Model& m = system.model();
  const int nb = l.bodies, size = l.size();
  const Eigen::MatrixXd orthonormal = nullSpace(groundConstraintJacobian(system, y), 6 * nb);
  const int n = static_cast<int>(orthonormal.cols());
  if (n == 0)
    return refuse(
        "the model has no degree of freedom at this configuration; a linear analysis needs at "
        "least one (ADAMS does not linearise a model without degrees of freedom either)");
  std::vector<int> selected;
  out.positionBasis = request.basis == LinearBasis::Orthonormal
                          ? orthonormal
                          : partCoordinateBasis(orthonormal, selected);
  const Eigen::MatrixXd& basis = out.positionBasis;

  // Ground coordinates -> the residual's coordinates (per body: r, e via the body-axes rotation
  // A^T dtheta; v and w_body = A^T dw for velocities and their rates).
  std::vector<Eigen::Matrix3d> axes(nb);
  for (int b = 0; b < nb; ++b) axes[b] = toEigen(mechanics::bodyPose(l, b, y.data()).a);
  auto positionDirection = [&](const Eigen::VectorXd& g) {
    Eigen::VectorXd dy = Eigen::VectorXd::Zero(size);
    for (int b = 0; b < nb; ++b) {
      const int o = l.body(b);
      dy.segment<3>(o + StateLayout::kR) = g.segment<3>(6 * b);
      dy.segment<4>(o + StateLayout::kE) = eulerParameterRates(y.segment<4>(o + StateLayout::kE)) *
                                           (axes[b].transpose() * g.segment<3>(6 * b + 3));
    }
    return dy;
  };
  auto velocityDirection = [&](const Eigen::VectorXd& g) {
    Eigen::VectorXd dy = Eigen::VectorXd::Zero(size);
    for (int b = 0; b < nb; ++b) {
      const int o = l.body(b);
      dy.segment<3>(o + StateLayout::kV) = g.segment<3>(6 * b);
      dy.segment<3>(o + StateLayout::kW) = axes[b].transpose() * g.segment<3>(6 * b + 3);
    }
    return dy;
  };
  // Balance rows (force in ground, moment in body axes) as generalised forces dual to the
  // ground coordinates, projected on the basis: basis^T T^T R.
  auto project = [&](const Eigen::VectorXd& r) {
    Eigen::VectorXd g(6 * nb);
    for (int b = 0; b < nb; ++b) {
      const int o = l.body(b);
      g.segment<3>(6 * b) = r.segment<3>(o + StateLayout::kV);
      g.segment<3>(6 * b + 3) = axes[b] * r.segment<3>(o + StateLayout::kW);
    }
    return Eigen::VectorXd(basis.transpose() * g);
  };

  // Unknowns: [z (n), z' (n), user differential (nd) | user algebraic (na)]; equations:
  // [z' = velocity (n), projected balance (n), user rows (nd + na)]. E x' + F x + G u = 0.
  const int nd = l.userDifferential, na = l.userAlgebraic;
  const int rows = 2 * n + nd + na;
  const int nDiff = 2 * n + nd;
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(rows, rows), f = Eigen::MatrixXd::Zero(rows, rows);
  ResidualDerivative derivative(system, t, y, yp);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(size);
  auto fill = [&](Eigen::MatrixXd& target, int column, const Eigen::VectorXd& r) {
    target.block(n, column, n, 1) = project(r);
    for (int k = 0; k < nd + na; ++k) target(2 * n + k, column) = r(l.userDiff(0) + k);
  };
  e.topLeftCorner(n, n).setIdentity();
  f.block(0, n, n, n) = -Eigen::MatrixXd::Identity(n, n);
  for (int j = 0; j < n; ++j) {
    const Eigen::VectorXd dq = positionDirection(basis.col(j));
    const Eigen::VectorXd du = velocityDirection(basis.col(j));
    fill(f, j, derivative.along(dq, zero));      // stiffness, incl. d(C^T lambda)/dq
    fill(f, n + j, derivative.along(du, zero));  // damping, gyroscopic terms
    fill(e, n + j, derivative.along(zero, du));  // mass
    // A balance or user equation of the position rates themselves (none in the mechanics).
    const Eigen::VectorXd rates = derivative.along(zero, dq);
    Eigen::VectorXd extra = Eigen::VectorXd::Zero(rows);
    extra.segment(n, n) = project(rates);
    for (int k = 0; k < nd + na; ++k) extra(2 * n + k) = rates(l.userDiff(0) + k);
    e.col(j) += extra;
  }
  for (int k = 0; k < nd + na; ++k) {
    Eigen::VectorXd unit = zero;
    unit(l.userDiff(0) + k) = 1.0;
    fill(f, 2 * n + k, derivative.along(unit, zero));
    fill(e, 2 * n + k, derivative.along(zero, unit));
  }
  if (request.withoutDamping) f.block(n, n, n, n).setZero();
  out.mass = e.block(n, n, n, n);
  out.damping = f.block(n, n, n, n);
  out.stiffness = f.block(n, 0, n, n);
  // A force function reading a reaction depends on the multipliers, whose perturbation the
  // projection removes (docs/theory.md §4b).
  if (mechanics::forceFunctionsReadReactions(system.model()))
    return refuse(
        system.model().frictions.empty()
            ? "a force function reads a constraint reaction force; linearising it is not "
              "supported yet"
            : "FRICTION reads its joint's reaction force; linearising it is not supported yet");
  // User equations that read reaction forces would need the multipliers' perturbation, which
  // the projection removes from the balance rows only.
  if (nd + na > 0) {
    for (int k = 0; k < l.constraintEquations; ++k) {
      if (!system.constraints().equations()[k].active) continue;
      Eigen::VectorXd unit = zero;
      unit(l.lambda(k)) = 1.0;
      const Eigen::VectorXd r = derivative.along(unit, zero);
      if (r.segment(l.userDiff(0), nd + na).cwiseAbs().maxCoeff() > 0.0)
        return refuse(
            "a user equation reads a constraint reaction force; linearising it is "
            "not supported yet");
    }
    if (e.rightCols(na).cwiseAbs().maxCoeff() > 0.0)
      return refuse(
          "a user equation depends on the rate of an algebraic unknown; linearising "
          "it is not supported yet");
  }

  // Plant inputs: the VARIABLE's own equation is replaced by v = u (its row dropped, its
  // column moved to G). Outputs: the VARIABLE's value.
  const int ni = static_cast<int>(request.inputs.size());
  std::vector<bool> isInput(static_cast<size_t>(na), false);
  for (int v : request.inputs) isInput[static_cast<size_t>(v)] = true;
  std::vector<int> keptRows, keptAlgebraic;
  for (int r = 0; r < rows; ++r)
    if (r < nDiff || !isInput[static_cast<size_t>(r - nDiff)]) keptRows.push_back(r);
  for (int k = 0; k < na; ++k)
    if (!isInput[static_cast<size_t>(k)]) keptAlgebraic.push_back(k);
  const int unknowns = static_cast<int>(keptRows.size());
  const int nKeptAlg = static_cast<int>(keptAlgebraic.size());
  // H [x_D'; x_A] = -(F_D x_D + G u)
  Eigen::MatrixXd h(unknowns, unknowns), fd(unknowns, nDiff), g(unknowns, ni);
  for (int r = 0; r < unknowns; ++r) {
    const int row = keptRows[static_cast<size_t>(r)];
    h.row(r).head(nDiff) = e.row(row).head(nDiff);
    for (int k = 0; k < nKeptAlg; ++k) h(r, nDiff + k) = f(row, nDiff + keptAlgebraic[k]);
    fd.row(r) = f.row(row).head(nDiff);
    for (int i = 0; i < ni; ++i) g(r, i) = f(row, nDiff + request.inputs[i]);
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(h);
  if (!lu.isInvertible())
    return refuse(
        "the linearised equations do not determine the accelerations and the "
        "algebraic unknowns (singular mass matrix, or a VARIABLE that is not defined "
        "by its own equation)");
  const Eigen::MatrixXd sx = -lu.solve(fd);
  const Eigen::MatrixXd su = -lu.solve(g);
  out.degreesOfFreedom = n;
  out.userStates = nd;
  out.a = sx.topRows(nDiff);
  out.b = su.topRows(nDiff);
  const int no = static_cast<int>(request.outputs.size());
  out.c = Eigen::MatrixXd::Zero(no, nDiff);
  out.d = Eigen::MatrixXd::Zero(no, ni);
  for (int o = 0; o < no; ++o) {
    const int v = request.outputs[o];
    if (isInput[static_cast<size_t>(v)]) {
      for (int i = 0; i < ni; ++i) out.d(o, i) = request.inputs[i] == v ? 1.0 : 0.0;
      continue;
    }
    const auto at =
        std::find(keptAlgebraic.begin(), keptAlgebraic.end(), v) - keptAlgebraic.begin();
    out.c.row(o) = sx.row(nDiff + at);
    out.d.row(o) = su.row(nDiff + at);
  }

  // Names.
  out.stateNames.clear();
  for (int rate = 0; rate < 2; ++rate)
    for (int j = 0; j < n; ++j) {
      if (request.basis == LinearBasis::PartCoordinates) {
        const int c = selected[j];
        out.stateNames.push_back("PART/" + std::to_string(m.parts[m.movingParts[c / 6]].id) + " " +
                                 partCoordinateName(c % 6, rate == 1));
      } else {
        out.stateNames.push_back(std::string(rate ? "mode velocity " : "mode coordinate ") +
                                 std::to_string(j + 1));
      }
    }
  for (int k = 0; k < nd; ++k) out.stateNames.push_back("user state " + std::to_string(k + 1));
  int k = 0;
  for (const auto& diff : m.diffs) {
    if (k < nd) out.stateNames[static_cast<size_t>(2 * n + k)] = "DIFF/" + std::to_string(diff.id);
    ++k;
  }
  for (const auto& lse : m.linearStates) {
    const int first = lse.firstState >= 0 ? lse.firstState : k;
    for (int s = 0; s < lse.a.rows() && first + s < nd; ++s)
      out.stateNames[static_cast<size_t>(2 * n + first + s)] =
          std::string(lse.kind == model::LinearStateElement::Kind::Lse ? "LSE/" : "TFSISO/") +
          std::to_string(lse.id) + " X" + std::to_string(s + 1);
    k = first + static_cast<int>(lse.a.rows());
  }
  out.inputVariables = request.inputs;
  out.outputVariables = request.outputs;
  out.inputNames.clear();
  out.outputNames.clear();
  for (int v : request.inputs)
    out.inputNames.push_back("VARIABLE/" + std::to_string(m.variables[v].id));
  for (int v : request.outputs)
    out.outputNames.push_back("VARIABLE/" + std::to_string(m.variables[v].id));
  return true;
}

}  // namespace openmss::analysis
