#include "mechanics/initial_conditions.hpp"

#include <algorithm>
#include <cmath>

#include "common/rotation.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/saddle_point_solver.hpp"
#include "mechanics/sparse_constraint_jacobian.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::mechanics {

double limitedCorrectionScale(const Eigen::VectorXd& delta, int bodies, double translationLimit,
                              double angleLimit) {
  double scale = 1.0;
  for (int b = 0; b < bodies; ++b) {
    const double dr = delta.segment<3>(6 * b).cwiseAbs().maxCoeff();
    const double da = delta.segment<3>(6 * b + 3).norm();
    if (dr > translationLimit) scale = std::min(scale, translationLimit / dr);
    if (da > angleLimit) scale = std::min(scale, angleLimit / da);
  }
  return scale;
}

bool usesSparseAlgebra(const MultibodySystem& system, LinearAlgebra method) {
  if (method == LinearAlgebra::Automatic) return system.layout().bodies >= kSparseFromBodies;
  return method == LinearAlgebra::Sparse;
}

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

std::vector<int> activeRows(const MultibodySystem& system) {
  std::vector<int> rows;
  const auto& eqs = system.constraints().equations();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k)
    if (eqs[k].active) rows.push_back(k);
  return rows;
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

// Diagonal matrix of `d`, sparse.
SparseMatrix sparseDiagonal(const Eigen::VectorXd& d) {
  SparseMatrix m(d.size(), d.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < d.size(); ++i) entries.emplace_back(i, i, d(i));
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// The mass matrix: per body m I (translations) and the inertia tensor (body-axes rotations).
SparseMatrix sparseMassMatrix(const MultibodySystem& system) {
  const int nb = system.layout().bodies;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(nb) * 12);
  for (int b = 0; b < nb; ++b) {
    for (int c = 0; c < 3; ++c) entries.emplace_back(6 * b + c, 6 * b + c, system.bodyMass(b));
    const Eigen::Matrix3d& j = system.bodyInertia(b);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(6 * b + 3 + r, 6 * b + 3 + c, j(r, c));
  }
  SparseMatrix m(6 * nb, 6 * nb);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

// Above this many unknowns a failed sparse solve is not retried densely (the dense matrix
// alone would need (n + m)^2 doubles): the solve reports failure instead.
constexpr int kDenseRetryLimit = 4000;

RedundancyReport removeRedundantSparse(MultibodySystem& system, const Eigen::VectorXd& y,
                                       bool* ok) {
  RedundancyReport report;
  const std::vector<int> rows = activeRows(system);
  const SparseMatrix c = sparseConstraintJacobian(system, y.data(), rows);
  std::vector<bool> dependent;
  *ok = findDependentRows(c, kRedundancyTolerance, dependent);
  if (!*ok) return report;
  auto& eqs = system.constraints().equations();
  for (size_t r = 0; r < rows.size(); ++r) {
    if (dependent[r]) {
      eqs[rows[r]].active = false;
      report.removed.push_back(rows[r]);
    } else {
      ++report.rank;
    }
  }
  return report;
}

}  // namespace

RedundancyReport removeRedundantConstraints(MultibodySystem& system, const Eigen::VectorXd& y,
                                            LinearAlgebra method) {
  if (usesSparseAlgebra(system, method)) {
    bool ok = false;
    RedundancyReport sparse = removeRedundantSparse(system, y, &ok);
    if (ok) return sparse;
  }
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
  Eigen::MatrixXd transform;
  // Sparse path: the same least-change step from the saddle-point system
  // [I A^T; A 0] [x; -nu] = [x_target; -phi], A = C T S (the scaled Jacobian), delta = T S x.
  bool sparse = usesSparseAlgebra(system, options.linearAlgebra);
  if (sparse) rows = activeRows(system);
  SaddlePointSolver saddle;
  SparseMatrix sparseScaled, sparseTransform;
  bool saddleFactored = false;
  const SparseMatrix identity = sparseDiagonal(Eigen::VectorXd::Ones(6 * nb));
  // T S as a sparse matrix: per body the translations' scales, and the rotations' scales or
  // (EXACT angles) the 3-1-3 rate matrix times the scales.
  auto formSparseTransform = [&]() {
    std::vector<Eigen::Triplet<double>> entries;
    for (int b = 0; b < nb; ++b) {
      for (int k = 0; k < 3; ++k) entries.emplace_back(6 * b + k, 6 * b + k, columnScale(6 * b + k));
      if (!eulerBody[b]) {
        for (int k = 3; k < 6; ++k)
          entries.emplace_back(6 * b + k, 6 * b + k, columnScale(6 * b + k));
        continue;
      }
      const Eigen::Matrix3d rate = eulerRateMatrix(bodyRotation(l, b, y));
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
          entries.emplace_back(6 * b + 3 + r, 6 * b + 3 + k, rate(r, k) * columnScale(6 * b + 3 + k));
    }
    sparseTransform.resize(6 * nb, 6 * nb);
    sparseTransform.setFromTriplets(entries.begin(), entries.end());
  };
  for (int it = 0; it <= options.maxIterations; ++it) {
    Eigen::VectorXd phi;
    const bool form = it == 0 || options.pattern[static_cast<size_t>(it % 10)] ||
                      (!sparse && transform.size() == 0);  // a dense retry forms afresh
    Eigen::MatrixXd c;
    if (form && !sparse) {
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
    Eigen::VectorXd delta;
    if (sparse) {
      if (form) {
        formSparseTransform();
        sparseScaled = sparseConstraintJacobian(system, y.data(), rows, icEquations) *
                       sparseTransform;
        saddleFactored = saddle.factor(identity, sparseScaled);
      }
      // The same least change as the dense step below; with EXACT coordinates x is nearest
      // to -z0 (the return to the data set's configuration).
      Eigen::VectorXd target = Eigen::VectorXd::Zero(6 * nb), x, nu;
      if (options.honourExact)
        target = -(columnScale.cwiseInverse().asDiagonal() * totalChange(l, y0, y, eulerBody));
      if (saddleFactored && saddle.solve(target, -phi, x, nu)) {
        delta = sparseTransform * x;
      } else {
        // Dependent rows at this iterate (a singular position, or joint initial conditions
        // that repeat a constraint): the dense least-squares step handles them.
        if (6 * nb + phi.size() > kDenseRetryLimit) break;
        sparse = false;
        --it;  // redo this iteration densely (it forms the dense factorisation)
        continue;
      }
    }
    if (!sparse && form) {
      // Coordinates: body translations, and body-axes rotations or 3-1-3 angle increments;
      // each column scaled by 1/sqrt(weight) so that the minimum-norm solution in the scaled
      // coordinates is the least weighted change.
      if (transform.size() == 0) transform = Eigen::MatrixXd::Identity(6 * nb, 6 * nb);
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
    if (sparse) {
      // delta is set above
    } else if (options.honourExact) {
      const Eigen::VectorXd z0 =
          columnScale.cwiseInverse().asDiagonal() * totalChange(l, y0, y, eulerBody);
      const Eigen::VectorXd w = cod.solve(-phi + scaledJacobian * z0);
      delta = transform * (columnScale.asDiagonal() * (w - z0));
    } else {
      delta = transform * (columnScale.asDiagonal() * cod.solve(-phi));
    }
    const double scale =
        limitedCorrectionScale(delta, nb, options.translationLimit, options.angleLimit);
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
                     bool holdJointInitialConditions, LinearAlgebra method) {
  const StateLayout& l = system.layout();
  const model::Model& m = system.model();
  const int nb = l.bodies;
  // Joint initial velocities: C_ic u = the given rate of the joint coordinate.
  std::vector<ConstraintSet::JointInitialCondition> jointIcs;
  if (holdJointInitialConditions)
    for (const auto& ic : ConstraintSet::jointInitialConditions(m))
      if (ic.hasVelocity) jointIcs.push_back(ic);
  std::vector<const ConstraintEquation*> icEquations;
  for (const auto& ic : jointIcs) icEquations.push_back(&ic.equation);
  std::vector<int> rows;
  const bool sparse = usesSparseAlgebra(system, method);
  Eigen::MatrixXd c;
  SparseMatrix cs;
  if (sparse) {
    rows = activeRows(system);
    cs = sparseConstraintJacobian(system, y.data(), rows, icEquations);
  } else {
    c = activeConstraintJacobian(system, y.data(), &rows);
    appendInitialConditionRows(system, y.data(), icEquations, c);
  }
  const Eigen::Index equations = static_cast<Eigen::Index>(rows.size() + jointIcs.size());
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
  Eigen::VectorXd rhs(equations);
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& eq = system.constraints().equations()[rows[r]];
    rhs(static_cast<Eigen::Index>(r)) = eq.motion >= 0 ? system.motionJet(rows[r], t).d1 : 0.0;
  }
  for (size_t r = 0; r < jointIcs.size(); ++r)
    rhs(static_cast<Eigen::Index>(rows.size() + r)) = jointIcs[r].velocity;
  Eigen::VectorXd u = u0;
  bool solved = false;
  if (sparse && equations > 0) {
    // The least weighted change: [W C^T; C 0] [du; -mult] = [0; rhs - C u0], W = winv^-1.
    SaddlePointSolver saddle;
    Eigen::VectorXd du, mult;
    solved = saddle.factor(sparseDiagonal(winv.cwiseInverse()), cs) &&
             saddle.solve(Eigen::VectorXd::Zero(6 * nb), rhs - cs * u0, du, mult);
    if (solved) u = u0 + du;
  } else if (sparse) {
    solved = true;
  }
  if (!solved && sparse) {
    // Dependent rows (joint initial velocities that repeat a constraint, a singular position):
    // the dense least-squares solve below handles them.
    if (6 * nb + equations > kDenseRetryLimit) return;
    c = activeConstraintJacobian(system, y.data(), &rows);
    appendInitialConditionRows(system, y.data(), icEquations, c);
  }
  if (!solved && c.rows() > 0) {
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
                        Eigen::VectorXd& yp, LinearAlgebra method) {
  // Functions that read accelerations or reactions couple Q to u' and lambda: one Newton
  // solve of the force rows, C u' = gamma and the user rows together (docs/theory.md §4b).
  if (readsAccelerationsOrReactions(system.model()))
    return solveCoupledAccelerations(system, t, y, yp).converged;
  const StateLayout& l = system.layout();
  const int nb = l.bodies;
  // VARIABLE values and DIFF derivatives first: applied forces may read them (§4a).
  if (!solveUserAlgebraic(system, t, y).converged) return false;
  std::vector<int> rows = activeRows(system);
  const int nc = static_cast<int>(rows.size());
  Eigen::VectorXd q;
  system.appliedForces(t, y.data(), q);
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
  bool solved = rhs.size() == 0;
  if (!solved && usesSparseAlgebra(system, method)) {
    // One solver per thread: its symbolic analysis serves every output step of a run (the
    // pattern of [M C^T; C 0] depends on the model only).
    thread_local SaddlePointSolver saddle;
    Eigen::VectorXd accelerations, multipliers;
    solved = saddle.factor(sparseMassMatrix(system),
                           sparseConstraintJacobian(system, y.data(), rows)) &&
             saddle.solve(q, rhs.tail(nc), accelerations, multipliers);
    if (solved) {
      sol.resize(6 * nb + nc);
      sol << accelerations, multipliers;
    } else if (6 * nb + nc > kDenseRetryLimit) {
      return false;
    }
  }
  if (!solved) {
    // Dense: full-pivot LU, whose rank test is the verdict on a singular matrix.
    const Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
    Eigen::MatrixXd mm;
    system.massMatrix(mm);
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(6 * nb + nc, 6 * nb + nc);
    kkt.topLeftCorner(6 * nb, 6 * nb) = mm;
    kkt.topRightCorner(6 * nb, nc) = c.transpose();
    kkt.bottomLeftCorner(nc, 6 * nb) = c;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
    if (!lu.isInvertible()) return false;
    sol = lu.solve(rhs);
  }
  yp = Eigen::VectorXd::Zero(l.size());
  for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) = 0.0;
  for (int r = 0; r < nc; ++r) y(l.lambda(rows[r])) = sol(6 * nb + r);
  kinematicRates(l, y, yp);
  for (int b = 0; b < nb; ++b) {
    const int o = l.body(b);
    yp.segment<3>(o + StateLayout::kV) = sol.segment<3>(6 * b);
    yp.segment<3>(o + StateLayout::kW) = sol.segment<3>(6 * b + 3);
    y(o + StateLayout::kMu) = 0.0;
  }
  userStateRates(system, t, y, yp);
  return true;
}

}  // namespace openmss::mechanics
