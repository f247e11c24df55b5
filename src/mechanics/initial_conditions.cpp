#include "mechanics/initial_conditions.hpp"

#include <cmath>

namespace openmss::mechanics {

Eigen::MatrixXd activeConstraintJacobian(const MultibodySystem& system, const double* y,
                                         std::vector<int>* rows) {
  const auto& eqs = system.constraints().equations();
  const int nb = system.layout().bodies;
  std::vector<int> active;
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k)
    if (eqs[k].active) active.push_back(k);
  Eigen::MatrixXd c(active.size(), 6 * nb);
  std::vector<double> row(6 * nb);
  for (size_t r = 0; r < active.size(); ++r) {
    system.constraintRow(active[r], y, row.data());
    for (int j = 0; j < 6 * nb; ++j) c(static_cast<Eigen::Index>(r), j) = row[j];
  }
  if (rows) *rows = active;
  return c;
}

RedundancyReport removeRedundantConstraints(MultibodySystem& system, const Eigen::VectorXd& y) {
  RedundancyReport report;
  auto& eqs = system.constraints().equations();
  const int nb = system.layout().bodies;
  std::vector<Eigen::VectorXd> basis;
  std::vector<double> row(6 * nb);
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    if (!eqs[k].active) continue;
    system.constraintRow(k, y.data(), row.data());
    Eigen::VectorXd v = Eigen::Map<Eigen::VectorXd>(row.data(), 6 * nb);
    const double scale = std::max(v.norm(), 1e-300);
    // Two passes of Gram-Schmidt keep the projection accurate.
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& q : basis) v -= q * q.dot(v);
    if (v.norm() <= 1e-9 * scale || 6 * nb == 0) {
      eqs[k].active = false;
      report.removed.push_back(k);
    } else {
      basis.push_back(v / v.norm());
    }
  }
  report.rank = static_cast<int>(basis.size());
  return report;
}

namespace {

void applyCorrection(const StateLayout& l, const Eigen::VectorXd& delta, Eigen::VectorXd& y) {
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    y.segment<3>(o + StateLayout::kR) += delta.segment<3>(6 * b);
    // e <- e (x) (1, dpi/2), normalised: a body-axes rotation by dpi.
    const Eigen::Vector3d h = 0.5 * delta.segment<3>(6 * b + 3);
    const Eigen::Vector4d e = y.segment<4>(o + StateLayout::kE);
    Eigen::Vector4d n;
    n(0) = e(0) - e(1) * h(0) - e(2) * h(1) - e(3) * h(2);
    n(1) = e(1) + e(0) * h(0) + e(2) * h(2) - e(3) * h(1);
    n(2) = e(2) + e(0) * h(1) + e(3) * h(0) - e(1) * h(2);
    n(3) = e(3) + e(0) * h(2) + e(1) * h(1) - e(2) * h(0);
    y.segment<4>(o + StateLayout::kE) = n.normalized();
  }
}

}  // namespace

AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 double tolerance, int maxIterations) {
  AssemblyResult result;
  const StateLayout& l = system.layout();
  const Eigen::VectorXd y0 = y;
  std::vector<int> rows;
  for (int it = 0; it <= maxIterations; ++it) {
    Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
    Eigen::VectorXd phi(rows.size());
    result.residual = 0.0;
    for (size_t r = 0; r < rows.size(); ++r) {
      phi(static_cast<Eigen::Index>(r)) = system.constraintValue(rows[r], t, y.data());
      if (std::abs(phi(static_cast<Eigen::Index>(r))) > result.residual) {
        result.residual = std::abs(phi(static_cast<Eigen::Index>(r)));
        result.worstEquation = rows[r];
      }
    }
    result.iterations = it;
    if (result.residual <= tolerance) {
      result.converged = true;
      break;
    }
    if (it == maxIterations || rows.empty()) break;
    // Minimum-norm correction: the least change that satisfies the linearised constraints.
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(c);
    const Eigen::VectorXd delta = cod.solve(-phi);
    applyCorrection(l, delta, y);
  }
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    result.partMoves.push_back((y.segment<3>(o) - y0.segment<3>(o)).norm());
    const double c = std::abs(y.segment<4>(o + StateLayout::kE).dot(y0.segment<4>(o + StateLayout::kE)));
    result.partTurns.push_back(2.0 * std::acos(std::min(1.0, c)));
  }
  return result;
}

void solveVelocities(const MultibodySystem& system, double t, Eigen::VectorXd& y) {
  const StateLayout& l = system.layout();
  const model::Model& m = system.model();
  const int nb = l.bodies;
  std::vector<int> rows;
  const Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
  Eigen::VectorXd u0(6 * nb), winv(6 * nb);
  for (int b = 0; b < nb; ++b) {
    const model::Part& p = m.parts[m.movingParts[b]];
    for (int k = 0; k < 3; ++k) {
      u0(6 * b + k) = y(l.body(b) + StateLayout::kV + k);
      u0(6 * b + 3 + k) = y(l.body(b) + StateLayout::kW + k);
      winv(6 * b + k) = p.velocity[k] ? 1e-6 : 1.0;
      winv(6 * b + 3 + k) = p.angularVelocity[k] ? 1e-6 : 1.0;
    }
  }
  Eigen::VectorXd rhs(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& eq = system.constraints().equations()[rows[r]];
    rhs(static_cast<Eigen::Index>(r)) = eq.motion >= 0 ? system.motionJet(rows[r], t).d1 : 0.0;
  }
  Eigen::VectorXd u = u0;
  if (rows.size() > 0) {
    const Eigen::MatrixXd cw = c * winv.asDiagonal();
    const Eigen::MatrixXd s = cw * c.transpose();
    const Eigen::VectorXd mult = s.completeOrthogonalDecomposition().solve(rhs - c * u0);
    u = u0 + winv.asDiagonal() * (c.transpose() * mult);
  }
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < 3; ++k) {
      y(l.body(b) + StateLayout::kV + k) = u(6 * b + k);
      y(l.body(b) + StateLayout::kW + k) = u(6 * b + 3 + k);
    }
}

bool solveAccelerations(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                        Eigen::VectorXd& yp) {
  const StateLayout& l = system.layout();
  const int nb = l.bodies;
  std::vector<int> rows;
  const Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
  const int nc = static_cast<int>(rows.size());
  Eigen::MatrixXd mm;
  system.massMatrix(mm);
  Eigen::VectorXd q;
  system.appliedForces(t, y.data(), q);
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(6 * nb + nc, 6 * nb + nc);
  kkt.topLeftCorner(6 * nb, 6 * nb) = mm;
  kkt.topRightCorner(6 * nb, nc) = c.transpose();
  kkt.bottomLeftCorner(nc, 6 * nb) = c;
  Eigen::VectorXd rhs(6 * nb + nc);
  rhs.head(6 * nb) = q;
  for (int r = 0; r < nc; ++r) {
    double first = 0.0, second = 0.0;
    system.constraintRates(rows[r], y.data(), &first, &second);
    const auto& eq = system.constraints().equations()[rows[r]];
    const double f2 = eq.motion >= 0 ? system.motionJet(rows[r], t).d2 : 0.0;
    rhs(6 * nb + r) = f2 - second;
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
  if (!lu.isInvertible()) return false;
  const Eigen::VectorXd sol = lu.solve(rhs);
  yp = Eigen::VectorXd::Zero(l.size());
  for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) = 0.0;
  for (int r = 0; r < nc; ++r) y(l.lambda(rows[r])) = sol(6 * nb + r);
  for (int b = 0; b < nb; ++b) {
    const int o = l.body(b);
    const Eigen::Vector4d e = y.segment<4>(o + StateLayout::kE);
    const Eigen::Vector3d w = y.segment<3>(o + StateLayout::kW);
    yp.segment<3>(o + StateLayout::kR) = y.segment<3>(o + StateLayout::kV);
    yp(o + StateLayout::kE + 0) = 0.5 * (-e(1) * w(0) - e(2) * w(1) - e(3) * w(2));
    yp(o + StateLayout::kE + 1) = 0.5 * (e(0) * w(0) + e(2) * w(2) - e(3) * w(1));
    yp(o + StateLayout::kE + 2) = 0.5 * (e(0) * w(1) + e(3) * w(0) - e(1) * w(2));
    yp(o + StateLayout::kE + 3) = 0.5 * (e(0) * w(2) + e(1) * w(1) - e(2) * w(0));
    yp.segment<3>(o + StateLayout::kV) = sol.segment<3>(6 * b);
    yp.segment<3>(o + StateLayout::kW) = sol.segment<3>(6 * b + 3);
    y(o + StateLayout::kMu) = 0.0;
  }
  return true;
}

}  // namespace openmss::mechanics
