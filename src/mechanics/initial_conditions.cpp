#include "mechanics/initial_conditions.hpp"

#include <cmath>

#include "common/rotation.hpp"
#include "mechanics/user_state_solve.hpp"

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

namespace {

// Appends the rows of the joints' initial conditions to C (after the active equations).
void appendInitialConditionRows(const MultibodySystem& system, const double* y,
                                const std::vector<const ConstraintEquation*>& extra,
                                Eigen::MatrixXd& c) {
  if (extra.empty()) return;
  const Eigen::Index base = c.rows();
  const int cols = 6 * system.layout().bodies;
  c.conservativeResize(base + static_cast<Eigen::Index>(extra.size()), cols);
  std::vector<double> row(cols);
  for (size_t r = 0; r < extra.size(); ++r) {
    system.constraintRow(*extra[r], y, row.data());
    for (int j = 0; j < cols; ++j) c(base + static_cast<Eigen::Index>(r), j) = row[j];
  }
}

}  // namespace

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

void applyBodyCorrection(const StateLayout& l, const Eigen::VectorXd& delta, Eigen::VectorXd& y) {
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

namespace {

Eigen::Matrix3d bodyRotation(const StateLayout& l, int body, const Eigen::VectorXd& y) {
  return toEigen(bodyPose(l, body, y.data()).a);
}

// Body-axes rotation per unit change of the 3-1-3 angles (psi, theta, phi) of A:
// delta pi = B delta(psi, theta, phi).
Eigen::Matrix3d eulerRateMatrix(const Eigen::Matrix3d& a) {
  const Eigen::Vector3d ang = euler313FromMatrix(a);
  const double st = std::sin(ang(1)), ct = std::cos(ang(1));
  const double sp = std::sin(ang(2)), cp = std::cos(ang(2));
  Eigen::Matrix3d b;
  b << st * sp, cp, 0.0,  //
      st * cp, -sp, 0.0,  //
      ct, 0.0, 1.0;
  return b;
}

// Change of each body coordinate (X, Y, Z, PSI, THETA, PHI) between two states; angles are
// compared through the rotation between them where psi and phi are not separable.
std::array<double, 6> coordinateChange(const StateLayout& l, int body, const Eigen::VectorXd& y0,
                                       const Eigen::VectorXd& y) {
  const int offset = l.body(body);
  std::array<double, 6> d{};
  for (int k = 0; k < 3; ++k) d[k] = y(offset + k) - y0(offset + k);
  const Eigen::Vector3d a0 = euler313FromMatrix(bodyRotation(l, body, y0));
  const Eigen::Vector3d a1 = euler313FromMatrix(bodyRotation(l, body, y));
  for (int k = 0; k < 3; ++k)
    d[3 + k] = std::remainder(a1(k) - a0(k), 2.0 * 3.14159265358979323846);
  return d;
}

// Change from y0 to y in the assembly's coordinates: translations, then per body either the
// body-axes rotation vector of A0^T A or (EXACT angles) the change of the 3-1-3 angles.
Eigen::VectorXd totalChange(const StateLayout& l, const Eigen::VectorXd& y0,
                            const Eigen::VectorXd& y, const std::vector<bool>& eulerBody) {
  Eigen::VectorXd d(6 * l.bodies);
  for (int b = 0; b < l.bodies; ++b) {
    const std::array<double, 6> c = coordinateChange(l, b, y0, y);
    for (int k = 0; k < 3; ++k) d(6 * b + k) = c[k];
    if (eulerBody[b]) {
      for (int k = 0; k < 3; ++k) d(6 * b + 3 + k) = c[3 + k];
    } else {
      const Eigen::AngleAxisd turn(bodyRotation(l, b, y0).transpose() * bodyRotation(l, b, y));
      d.segment<3>(6 * b + 3) = turn.angle() * turn.axis();
    }
  }
  return d;
}

}  // namespace

AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 double tolerance, int maxIterations) {
  AssemblyOptions options;
  options.tolerance = tolerance;
  options.maxIterations = maxIterations;
  return assemblePositions(system, t, y, options);
}

AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 const AssemblyOptions& options) {
  AssemblyResult result;
  const StateLayout& l = system.layout();
  const model::Model& m = system.model();
  const int nb = l.bodies;
  const Eigen::VectorXd y0 = y;
  std::vector<int> rows;
  // Which bodies take their rotation in 3-1-3 angle increments (an EXACT angle is held).
  std::vector<bool> eulerBody(nb, false);
  Eigen::VectorXd columnScale = Eigen::VectorXd::Ones(6 * nb);
  if (options.honourExact) {
    const double s = 1.0 / std::sqrt(AssemblyOptions::kExactWeight);
    for (int b = 0; b < nb; ++b) {
      const auto& exact = m.parts[m.movingParts[b]].exact;
      for (int k = 0; k < 6; ++k)
        if (exact[k]) columnScale(6 * b + k) = s;
      eulerBody[b] = exact[3] || exact[4] || exact[5];
    }
  }
  // Joint initial displacements: extra equations of this solve (joint coordinate = value).
  std::vector<ConstraintSet::JointInitialCondition> jointIcs;
  if (options.holdJointInitialConditions)
    for (const auto& ic : ConstraintSet::jointInitialConditions(m))
      if (ic.hasDisplacement) jointIcs.push_back(ic);
  std::vector<const ConstraintEquation*> icEquations;
  for (const auto& ic : jointIcs) icEquations.push_back(&ic.equation);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  Eigen::MatrixXd scaledJacobian;
  Eigen::MatrixXd transform = Eigen::MatrixXd::Identity(6 * nb, 6 * nb);
  for (int it = 0; it <= options.maxIterations; ++it) {
    Eigen::VectorXd phi;
    const bool form = it == 0 || options.pattern[static_cast<size_t>(it % 10)];
    Eigen::MatrixXd c;
    if (form) {
      c = activeConstraintJacobian(system, y.data(), &rows);
      appendInitialConditionRows(system, y.data(), icEquations, c);
    }
    phi.resize(static_cast<Eigen::Index>(rows.size() + jointIcs.size()));
    result.residual = 0.0;
    for (size_t r = 0; r < rows.size(); ++r) {
      phi(static_cast<Eigen::Index>(r)) = system.constraintValue(rows[r], t, y.data());
      if (std::abs(phi(static_cast<Eigen::Index>(r))) > result.residual) {
        result.residual = std::abs(phi(static_cast<Eigen::Index>(r)));
        result.worstEquation = rows[r];
      }
    }
    double icResidual = 0.0;
    for (size_t r = 0; r < jointIcs.size(); ++r) {
      const ConstraintSet::JointInitialCondition& ic = jointIcs[r];
      double v = system.geometryValue(ic.equation, y.data()) - ic.displacement;
      if (ic.equation.kind == ConstraintEquation::Kind::MotionRotation)
        v = std::remainder(v, 2.0 * 3.14159265358979323846);
      phi(static_cast<Eigen::Index>(rows.size() + r)) = v;
      icResidual = std::max(icResidual, std::abs(v));
    }
    result.iterations = it;
    if (result.residual <= options.tolerance && icResidual <= options.tolerance) {
      result.converged = true;
      break;
    }
    result.residual = std::max(result.residual, icResidual);
    if (it == options.maxIterations || phi.size() == 0) break;
    if (form) {
      // Coordinates: body translations, and body-axes rotations or 3-1-3 angle increments;
      // each column scaled by 1/sqrt(weight) so that the minimum-norm solution in the scaled
      // coordinates is the least weighted change.
      for (int b = 0; b < nb; ++b) {
        if (!eulerBody[b]) continue;
        transform.block<3, 3>(6 * b + 3, 6 * b + 3) = eulerRateMatrix(bodyRotation(l, b, y));
      }
      scaledJacobian = c * transform * columnScale.asDiagonal();
      cod.compute(scaledJacobian);
    }
    // Minimum-norm correction: the least change that satisfies the linearised constraints.
    // With EXACT coordinates the change is measured from the data set's configuration, not from
    // the last iterate: each step is the least-squares return to the data projected on the
    // linearised constraints (else a first step forced through an EXACT coordinate by the
    // linearisation would never be undone).
    Eigen::VectorXd delta;
    if (options.honourExact) {
      const Eigen::VectorXd z0 =
          columnScale.cwiseInverse().asDiagonal() * totalChange(l, y0, y, eulerBody);
      const Eigen::VectorXd w = cod.solve(-phi + scaledJacobian * z0);
      delta = transform * (columnScale.asDiagonal() * (w - z0));
    } else {
      delta = transform * (columnScale.asDiagonal() * cod.solve(-phi));
    }
    // TLIMIT / ALIMIT: scale the whole correction so that no body moves or turns more.
    double scale = 1.0;
    for (int b = 0; b < nb; ++b) {
      const double dr = delta.segment<3>(6 * b).cwiseAbs().maxCoeff();
      const double da = delta.segment<3>(6 * b + 3).norm();
      if (dr > options.translationLimit) scale = std::min(scale, options.translationLimit / dr);
      if (da > options.angleLimit) scale = std::min(scale, options.angleLimit / da);
    }
    applyBodyCorrection(l, scale * delta, y);
  }
  for (int b = 0; b < nb; ++b) {
    const int o = l.body(b);
    result.partMoves.push_back((y.segment<3>(o) - y0.segment<3>(o)).norm());
    const double c = std::abs(y.segment<4>(o + StateLayout::kE).dot(y0.segment<4>(o + StateLayout::kE)));
    result.partTurns.push_back(2.0 * std::acos(std::min(1.0, c)));
    if (!options.honourExact) continue;
    const auto& exact = m.parts[m.movingParts[b]].exact;
    const std::array<double, 6> d = coordinateChange(l, b, y0, y);
    for (int k = 0; k < 6; ++k)
      if (exact[k] && std::abs(d[k]) > 1e-9) result.exactChanged.push_back({b, k, d[k]});
  }
  return result;
}

void solveVelocities(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                     bool holdJointInitialConditions) {
  const StateLayout& l = system.layout();
  const model::Model& m = system.model();
  const int nb = l.bodies;
  std::vector<int> rows;
  Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
  // Joint initial velocities: C_ic u = the given rate of the joint coordinate.
  std::vector<ConstraintSet::JointInitialCondition> jointIcs;
  if (holdJointInitialConditions)
    for (const auto& ic : ConstraintSet::jointInitialConditions(m))
      if (ic.hasVelocity) jointIcs.push_back(ic);
  std::vector<const ConstraintEquation*> icEquations;
  for (const auto& ic : jointIcs) icEquations.push_back(&ic.equation);
  appendInitialConditionRows(system, y.data(), icEquations, c);
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
  Eigen::VectorXd rhs(c.rows());
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& eq = system.constraints().equations()[rows[r]];
    rhs(static_cast<Eigen::Index>(r)) = eq.motion >= 0 ? system.motionJet(rows[r], t).d1 : 0.0;
  }
  for (size_t r = 0; r < jointIcs.size(); ++r)
    rhs(static_cast<Eigen::Index>(rows.size() + r)) = jointIcs[r].velocity;
  Eigen::VectorXd u = u0;
  if (c.rows() > 0) {
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
  // VARIABLE values and DIFF derivatives first: applied forces may read them (§4a).
  if (!solveUserAlgebraic(system, t, y).converged) return false;
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
  // A model of user equations only has no mechanical unknowns: nothing to factor.
  Eigen::VectorXd sol(0);
  if (kkt.rows() > 0) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
    if (!lu.isInvertible()) return false;
    sol = lu.solve(rhs);
  }
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
  userStateRates(system, t, y, yp);
  return true;
}

}  // namespace openmss::mechanics
