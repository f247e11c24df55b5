#include "mechanics/coordinate_partitioning.hpp"

#include <algorithm>
#include <cmath>

#include "mechanics/initial_conditions.hpp"

namespace openmss::mechanics {
namespace {

// Dependent positions are converged far below any integration tolerance (lengths of the
// model's units): the recovered state must satisfy the constraints as tightly as the
// initial-condition assembly does.
constexpr double kPositionTolerance = 1e-11;
constexpr int kPositionIterations = 12;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v(2), v(1), v(2), 0.0, -v(0), -v(1), v(0), 0.0;
  return s;
}

// Right Jacobian of SO(3): for A = A_ref exp([phi]x) the body-axes angular velocity is
// w = J_r(phi) phi'. Series near phi = 0 avoid 0/0.
Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& phi) {
  const double th = phi.norm();
  const double a = th < 1e-4 ? 0.5 - th * th / 24.0 : (1.0 - std::cos(th)) / (th * th);
  const double b = th < 1e-4 ? 1.0 / 6.0 - th * th / 120.0 : (th - std::sin(th)) / (th * th * th);
  const Eigen::Matrix3d s = skew(phi);
  return Eigen::Matrix3d::Identity() - a * s + b * s * s;
}

Eigen::Matrix3d rightJacobianInverse(const Eigen::Vector3d& phi) {
  const double th = phi.norm();
  const double c = th < 1e-4 ? 1.0 / 12.0 + th * th / 720.0
                             : 1.0 / (th * th) - (1.0 + std::cos(th)) / (2.0 * th * std::sin(th));
  const Eigen::Matrix3d s = skew(phi);
  return Eigen::Matrix3d::Identity() + 0.5 * s + c * s * s;
}

// Quaternion product p (x) q, scalar first (the layout's Euler parameters).
Eigen::Vector4d multiply(const Eigen::Vector4d& p, const Eigen::Vector4d& q) {
  Eigen::Vector4d r;
  r(0) = p(0) * q(0) - p(1) * q(1) - p(2) * q(2) - p(3) * q(3);
  r(1) = p(0) * q(1) + p(1) * q(0) + p(2) * q(3) - p(3) * q(2);
  r(2) = p(0) * q(2) + p(2) * q(0) + p(3) * q(1) - p(1) * q(3);
  r(3) = p(0) * q(3) + p(3) * q(0) + p(1) * q(2) - p(2) * q(1);
  return r;
}

Eigen::Vector4d exponential(const Eigen::Vector3d& phi) {
  const double th = phi.norm();
  const double s = th < 1e-8 ? 0.5 - th * th / 48.0 : std::sin(0.5 * th) / th;
  return {std::cos(0.5 * th), s * phi(0), s * phi(1), s * phi(2)};
}

Eigen::Vector3d logarithm(Eigen::Vector4d q) {
  if (q(0) < 0) q = -q;  // the shorter of the two rotations
  const Eigen::Vector3d v = q.tail<3>();
  const double sn = v.norm();
  const double th = 2.0 * std::atan2(sn, q(0));
  return sn < 1e-12 ? Eigen::Vector3d(2.0 * v / q(0)) : Eigen::Vector3d(th / sn * v);
}

Eigen::Vector4d conjugate(const Eigen::Vector4d& q) { return {q(0), -q(1), -q(2), -q(3)}; }

}  // namespace

CoordinatePartitioning::CoordinatePartitioning(const MultibodySystem& system)
    : system_(system), nb_(system.layout().bodies) {}

bool CoordinatePartitioning::partition(const Eigen::VectorXd& y) {
  reference_ = y;
  zLast_ = Eigen::VectorXd::Zero(6 * nb_);
  std::vector<int> active;
  const Eigen::MatrixXd c = activeConstraintJacobian(system_, y.data(), &active);
  rows_.clear();
  dependent_.clear();
  independent_.clear();
  if (c.rows() == 0) {
    for (int j = 0; j < 6 * nb_; ++j) independent_.push_back(j);
    referencePivotRatio_ = 1.0;
    return true;
  }
  // Full pivoting picks, at every elimination step, the largest remaining entry: its column
  // is the coordinate the constraints determine best, so the pivot columns are the dependent
  // coordinates and the Jacobian block C_D is as well conditioned as the choice allows.
  Eigen::FullPivLU<Eigen::MatrixXd> lu(c);
  lu.setThreshold(1e-9);
  const int rank = static_cast<int>(lu.rank());
  if (rank == 0) return false;
  std::vector<bool> isDependent(6 * nb_, false);
  // Row k of P C is row p^-1(k) of C; column k of C Q is column q(k) of C.
  const Eigen::PermutationMatrix<Eigen::Dynamic> rowOrder = lu.permutationP().inverse();
  for (int k = 0; k < rank; ++k) {
    rows_.push_back(active[static_cast<size_t>(rowOrder.indices()(k))]);
    const int column = lu.permutationQ().indices()(k);
    dependent_.push_back(column);
    isDependent[column] = true;
  }
  // Keep the equations in their own order (diagnostics read better).
  std::sort(rows_.begin(), rows_.end());
  for (int j = 0; j < 6 * nb_; ++j)
    if (!isDependent[j]) independent_.push_back(j);
  referencePivotRatio_ = 1.0;
  Eigen::MatrixXd cd(rank, rank);
  std::vector<double> row(6 * nb_);
  for (int r = 0; r < rank; ++r) {
    system_.constraintRow(rows_[r], y.data(), row.data());
    for (int k = 0; k < rank; ++k) cd(r, k) = row[dependent_[k]];
  }
  referencePivotRatio_ = pivotRatio(cd);
  return referencePivotRatio_ > 0;
}

double CoordinatePartitioning::pivotRatio(const Eigen::MatrixXd& cd) const {
  if (cd.rows() == 0) return 1.0;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(cd);
  const Eigen::VectorXd d = lu.matrixLU().diagonal().cwiseAbs();
  return d.maxCoeff() > 0 ? d.minCoeff() / d.maxCoeff() : 0.0;
}

double CoordinatePartitioning::pivotQuality(const Eigen::VectorXd& y) const {
  const int m = static_cast<int>(rows_.size());
  if (m == 0) return 1.0;
  Eigen::MatrixXd cd(m, m);
  std::vector<double> row(6 * nb_);
  for (int r = 0; r < m; ++r) {
    system_.constraintRow(rows_[r], y.data(), row.data());
    for (int k = 0; k < m; ++k) cd(r, k) = row[dependent_[k]];
  }
  return pivotRatio(cd) / referencePivotRatio_;
}

double CoordinatePartitioning::largestRotation(const Eigen::VectorXd& y) const {
  Eigen::VectorXd z;
  coordinates(y, z);
  double worst = 0.0;
  for (int b = 0; b < nb_; ++b) worst = std::max(worst, z.segment<3>(6 * b + 3).norm());
  return worst;
}

std::string CoordinatePartitioning::coordinateName(int column) const {
  static const char* kNames[6] = {"X",
                                  "Y",
                                  "Z",
                                  "rotation about body x",
                                  "rotation about body y",
                                  "rotation about body z"};
  const auto& m = system_.model();
  return std::string(kNames[column % 6]) + " of PART/" +
         std::to_string(m.parts[m.movingParts[column / 6]].id);
}

void CoordinatePartitioning::configuration(const Eigen::VectorXd& z, Eigen::VectorXd& y) const {
  const StateLayout& l = system_.layout();
  for (int b = 0; b < nb_; ++b) {
    const int o = l.body(b);
    y.segment<3>(o + StateLayout::kR) =
        reference_.segment<3>(o + StateLayout::kR) + z.segment<3>(6 * b);
    const Eigen::Vector4d e0 = reference_.segment<4>(o + StateLayout::kE);
    y.segment<4>(o + StateLayout::kE) = multiply(e0, exponential(z.segment<3>(6 * b + 3)));
  }
}

void CoordinatePartitioning::coordinates(const Eigen::VectorXd& y, Eigen::VectorXd& z) const {
  const StateLayout& l = system_.layout();
  z.resize(6 * nb_);
  for (int b = 0; b < nb_; ++b) {
    const int o = l.body(b);
    z.segment<3>(6 * b) = y.segment<3>(o + StateLayout::kR) - reference_.segment<3>(o + StateLayout::kR);
    const Eigen::Vector4d e0 = reference_.segment<4>(o + StateLayout::kE);
    z.segment<3>(6 * b + 3) = logarithm(multiply(conjugate(e0), y.segment<4>(o + StateLayout::kE)));
  }
}

void CoordinatePartitioning::tangentMap(const Eigen::VectorXd& z, Eigen::MatrixXd& t) const {
  t.setIdentity(6 * nb_, 6 * nb_);
  for (int b = 0; b < nb_; ++b)
    t.block<3, 3>(6 * b + 3, 6 * b + 3) = rightJacobian(z.segment<3>(6 * b + 3));
}

void CoordinatePartitioning::reduce(const Eigen::VectorXd& y, Eigen::VectorXd& x) const {
  const StateLayout& l = system_.layout();
  Eigen::VectorXd z;
  coordinates(y, z);
  const int n = degreesOfFreedom();
  x.resize(2 * n);
  for (int k = 0; k < n; ++k) {
    const int j = independent_[k];
    const int o = l.body(j / 6);
    x(k) = z(j);
    x(n + k) = j % 6 < 3 ? y(o + StateLayout::kV + j % 6) : y(o + StateLayout::kW + j % 6 - 3);
  }
}

bool CoordinatePartitioning::expand(double t, const Eigen::VectorXd& x, Eigen::VectorXd& y,
                                    Eigen::VectorXd& yp, Eigen::VectorXd* xdot) const {
  const StateLayout& l = system_.layout();
  const int n = degreesOfFreedom();
  const int m = static_cast<int>(rows_.size());
  if (y.size() != l.size()) y = reference_;
  // Positions: the independent coordinates are given; Newton on Phi(q(z), t) = 0 for the
  // dependent ones with the exact derivative dPhi/dz_D = C dq/dz restricted to z_D.
  Eigen::VectorXd z = zLast_;
  for (int k = 0; k < n; ++k) z(independent_[k]) = x(k);
  Eigen::MatrixXd c(m, 6 * nb_), tangent;
  Eigen::VectorXd phi(m);
  std::vector<double> row(6 * nb_);
  bool converged = m == 0;
  for (int it = 0; it <= kPositionIterations && !converged; ++it) {
    configuration(z, y);
    double worst = 0.0;
    for (int r = 0; r < m; ++r) {
      phi(r) = system_.constraintValue(rows_[r], t, y.data());
      worst = std::max(worst, std::abs(phi(r)));
    }
    if (!std::isfinite(worst)) return false;
    if (worst <= kPositionTolerance) {
      converged = true;
      break;
    }
    if (it == kPositionIterations) break;
    for (int r = 0; r < m; ++r) {
      system_.constraintRow(rows_[r], y.data(), row.data());
      for (int j = 0; j < 6 * nb_; ++j) c(r, j) = row[j];
    }
    tangentMap(z, tangent);
    Eigen::MatrixXd cd(m, m);
    const Eigen::MatrixXd cz = c * tangent;
    for (int k = 0; k < m; ++k) cd.col(k) = cz.col(dependent_[k]);
    const Eigen::VectorXd dz = cd.partialPivLu().solve(-phi);
    for (int k = 0; k < m; ++k) z(dependent_[k]) += dz(k);
    ++positionIterations_;
  }
  if (!converged) return false;
  configuration(z, y);
  zLast_ = z;
  for (int b = 0; b < nb_; ++b) y(l.body(b) + StateLayout::kMu) = 0.0;

  // Velocities: u_I given; C_D u_D = nu - C_I u_I with nu the motions' rates.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * nb_);
  for (int k = 0; k < n; ++k) u(independent_[k]) = x(n + k);
  if (m > 0) {
    Eigen::VectorXd rhs(m);
    Eigen::MatrixXd cd(m, m);
    for (int r = 0; r < m; ++r) {
      system_.constraintRow(rows_[r], y.data(), row.data());
      const auto& eq = system_.constraints().equations()[rows_[r]];
      rhs(r) = eq.motion >= 0 ? system_.motionJet(rows_[r], t).d1 : 0.0;
      for (int k = 0; k < n; ++k) rhs(r) -= row[independent_[k]] * u(independent_[k]);
      for (int k = 0; k < m; ++k) cd(r, k) = row[dependent_[k]];
    }
    const Eigen::VectorXd ud = cd.partialPivLu().solve(rhs);
    for (int k = 0; k < m; ++k) u(dependent_[k]) = ud(k);
  }
  for (int b = 0; b < nb_; ++b) {
    y.segment<3>(l.body(b) + StateLayout::kV) = u.segment<3>(6 * b);
    y.segment<3>(l.body(b) + StateLayout::kW) = u.segment<3>(6 * b + 3);
  }
  // Accelerations and multipliers: the KKT solve of the initial-condition analysis.
  if (!solveAccelerations(system_, t, y, yp)) return false;
  if (!y.allFinite() || !yp.allFinite()) return false;
  if (xdot) {
    xdot->resize(2 * n);
    for (int b = 0; b < nb_; ++b) {
      const Eigen::Vector3d zr = rightJacobianInverse(z.segment<3>(6 * b + 3)) * u.segment<3>(6 * b + 3);
      u.segment<3>(6 * b + 3) = zr;  // u now holds z'
    }
    for (int k = 0; k < n; ++k) {
      const int j = independent_[k];
      const int o = l.body(j / 6);
      (*xdot)(k) = u(j);
      (*xdot)(n + k) = j % 6 < 3 ? yp(o + StateLayout::kV + j % 6) : yp(o + StateLayout::kW + j % 6 - 3);
    }
  }
  return true;
}

}  // namespace openmss::mechanics
