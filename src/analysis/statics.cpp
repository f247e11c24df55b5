#include "analysis/statics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/dual.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/pose.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

std::vector<int> activeEquations(const mechanics::MultibodySystem& system) {
  std::vector<int> rows;
  const auto& eqs = system.constraints().equations();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k)
    if (eqs[k].active) rows.push_back(k);
  return rows;
}

// The length that turns a rotation into a displacement for the singularity test: the largest
// distance of a marker from its part's CM (1 when every marker sits at its CM).
double characteristicLength(const model::Model& m) {
  double l = 0.0;
  for (const auto& mk : m.markers)
    if (m.parts[mk.part].body >= 0) l = std::max(l, mk.position.norm());
  return l > 1e-12 ? l : 1.0;
}

struct StiffnessAnalysis {
  Eigen::MatrixXd basis;      // orthonormal basis of the free directions (scaled coordinates)
  Eigen::MatrixXd projected;  // basis^T K basis
  double scale = 0.0;         // magnitude against which a stiffness counts as zero
};

// Projects the balance stiffness K (6 nb square block of the Jacobian, without the
// stability term) on the directions the constraints leave free. Rotations are scaled by the
// characteristic length so that every coordinate is a length and every row a force.
StiffnessAnalysis analyseStiffness(const Eigen::MatrixXd& jac, int nb, int na, double length,
                                   const Eigen::VectorXd& balance) {
  const int n = 6 * nb;
  Eigen::VectorXd d(n);
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < 6; ++k) d(6 * b + k) = k < 3 ? 1.0 : 1.0 / length;
  const Eigen::MatrixXd k = d.asDiagonal() * jac.topLeftCorner(n, n) * d.asDiagonal();
  StiffnessAnalysis s;
  if (na > 0) {
    const Eigen::MatrixXd c = jac.block(n, 0, na, n) * d.asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeFullV);
    const Eigen::VectorXd& sv = svd.singularValues();
    int rank = 0;
    for (int i = 0; i < sv.size(); ++i)
      if (sv(i) > 1e-9 * sv(0)) ++rank;
    s.basis = svd.matrixV().rightCols(n - rank);
  } else {
    s.basis = Eigen::MatrixXd::Identity(n, n);
  }
  s.projected = s.basis.transpose() * k * s.basis;
  const double loadScale = (d.asDiagonal() * balance).cwiseAbs().maxCoeff() / length;
  s.scale = std::max({k.cwiseAbs().maxCoeff(), loadScale, 1e-300});
  return s;
}

MotionDirection directionOf(const mechanics::MultibodySystem& system, const Eigen::VectorXd& y,
                            const Eigen::VectorXd& scaled, double length) {
  const int nb = system.layout().bodies;
  MotionDirection m;
  double biggest = -1.0;
  for (int b = 0; b < nb; ++b) {
    const double size = scaled.segment<6>(6 * b).norm();
    if (size > biggest) {
      biggest = size;
      m.body = b;
    }
  }
  const Eigen::Vector3d t = scaled.segment<3>(6 * m.body);
  const Eigen::Vector3d r = scaled.segment<3>(6 * m.body + 3) / length;  // body axes, rad
  // A rigid motion that turns the part at all is a rotation (about some axis, perhaps not
  // through the CM); a pure translation has no rotational part.
  m.rotation = scaled.segment<3>(6 * m.body + 3).norm() > 1e-6 * biggest;
  if (m.rotation) {
    const Eigen::Matrix3d a = toEigen(mechanics::bodyPose(system.layout(), m.body, y.data()).a);
    m.axis = (a * r).normalized();
  } else {
    m.axis = t.normalized();
  }
  // Report the axis with the sign that makes its largest component positive, round-off zeroed.
  Eigen::Index at = 0;
  m.axis.cwiseAbs().maxCoeff(&at);
  if (m.axis(at) < 0) m.axis = -m.axis;
  for (int c = 0; c < 3; ++c)
    if (std::abs(m.axis(c)) < 1e-9) m.axis(c) = 0.0;
  return m;
}

struct FreeDirections {
  std::vector<MotionDirection> loaded, unloaded, negative;
};

FreeDirections freeDirections(const mechanics::MultibodySystem& system, const Eigen::VectorXd& y,
                              const Eigen::MatrixXd& jac, const Eigen::VectorXd& g, int na,
                              double length, double imbalance) {
  const int nb = system.layout().bodies;
  const int n = 6 * nb;
  FreeDirections out;
  const Eigen::VectorXd balance = g.head(n);
  const StiffnessAnalysis s = analyseStiffness(jac, nb, na, length, balance);
  if (s.basis.cols() == 0) return out;
  Eigen::VectorXd d(n);
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < 6; ++k) d(6 * b + k) = k < 3 ? 1.0 : 1.0 / length;
  const Eigen::VectorXd scaledLoad = d.asDiagonal() * balance;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(s.projected, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const double zero = 1e-8 * s.scale;
  for (int i = 0; i < svd.singularValues().size(); ++i) {
    if (svd.singularValues()(i) > zero) continue;
    const Eigen::VectorXd v = s.basis * svd.matrixV().col(i);
    MotionDirection m = directionOf(system, y, v, length);
    m.stiffness = svd.singularValues()(i);
    m.load = v.dot(scaledLoad);
    (std::abs(m.load) > imbalance ? out.loaded : out.unloaded).push_back(m);
  }
  // Negative stiffness (the symmetric part): an unstable equilibrium.
  const Eigen::MatrixXd sym = 0.5 * (s.projected + s.projected.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sym);
  for (int i = 0; i < eig.eigenvalues().size(); ++i) {
    if (eig.eigenvalues()(i) >= -zero) continue;
    MotionDirection m = directionOf(system, y, s.basis * eig.eigenvectors().col(i), length);
    m.stiffness = eig.eigenvalues()(i);
    out.negative.push_back(m);
  }
  std::sort(out.loaded.begin(), out.loaded.end(),
            [](const auto& a, const auto& b) { return std::abs(a.load) > std::abs(b.load); });
  return out;
}

double largestCorrection(const Eigen::VectorXd& delta, int nb) {
  return nb > 0 ? delta.head(6 * nb).cwiseAbs().maxCoeff() : 0.0;
}

// The user states solved for in statics (docs/theory.md §4a): every user entry but the
// differential states that STATIC_HOLD keeps fixed. Their rows are the same entries of the
// residual with y' = 0 (a held state's row, y' = f, is dropped with it).
std::vector<int> staticUserUnknowns(const mechanics::MultibodySystem& system) {
  const StateLayout& l = system.layout();
  const std::vector<bool> held = system.userEquations().staticHold();
  std::vector<int> out;
  for (int k = 0; k < l.userDifferential; ++k)
    if (!held[static_cast<size_t>(k)]) out.push_back(l.userDiff(k));
  for (int k = 0; k < l.userAlgebraic; ++k) out.push_back(l.userAlg(k));
  return out;
}

// The Jacobian of the mechanical unknowns with the user unknowns condensed out (Schur
// complement), so that the free-direction analysis sees the stiffness a controller adds.
// False when the user block is singular (e.g. an integrator state only the balance rows
// determine): the analysis is then skipped.
bool condensedJacobian(const Eigen::MatrixXd& jac, int mechanical, Eigen::MatrixXd& out) {
  const Eigen::Index nu = jac.rows() - mechanical;
  if (nu == 0) {
    out = jac;
    return true;
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(jac.bottomRightCorner(nu, nu));
  if (!lu.isInvertible()) return false;
  out = jac.topLeftCorner(mechanical, mechanical) -
        jac.topRightCorner(mechanical, nu) * lu.solve(jac.bottomLeftCorner(nu, mechanical));
  return true;
}

}  // namespace

// de/d(delta pi_k) for a body-axes rotation: e (x) (0, e_k / 2).
Eigen::Matrix<double, 4, 3> eulerParameterRates(const Eigen::Vector4d& e) {
  Eigen::Matrix<double, 4, 3> g;
  g << -e(1), -e(2), -e(3),  //
      e(0), -e(3), e(2),     //
      e(3), e(0), -e(1),     //
      -e(2), e(1), e(0);
  return 0.5 * g;
}

std::string MotionDirection::describe(const model::Model& model) const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s of PART/%ld %s (%.6g, %.6g, %.6g)",
                rotation ? "rotation" : "translation", model.parts[model.movingParts[body]].id,
                rotation ? "about the ground-axes direction" : "along the ground-axes direction",
                axis(0), axis(1), axis(2));
  return buf;
}

void staticResidual(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::VectorXd& g) {
  const StateLayout& l = system.layout();
  const std::vector<int> rows = activeEquations(system);
  Eigen::VectorXd ys = y;
  for (int b = 0; b < l.bodies; ++b) {
    ys.segment<3>(l.body(b) + StateLayout::kV).setZero();
    ys.segment<3>(l.body(b) + StateLayout::kW).setZero();
  }
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(l.size());
  Eigen::VectorXd full = Eigen::VectorXd::Zero(l.size());
  system.residual(t, ys.data(), yp.data(), full.data());
  const std::vector<int> users = staticUserUnknowns(system);
  g.resize(6 * l.bodies + static_cast<Eigen::Index>(rows.size() + users.size()));
  for (int b = 0; b < l.bodies; ++b) {
    g.segment<3>(6 * b) = full.segment<3>(l.body(b) + StateLayout::kV);
    g.segment<3>(6 * b + 3) = full.segment<3>(l.body(b) + StateLayout::kW);
  }
  for (size_t r = 0; r < rows.size(); ++r)
    g(6 * l.bodies + static_cast<Eigen::Index>(r)) = full(l.lambda(rows[r]));
  for (size_t u = 0; u < users.size(); ++u)
    g(6 * l.bodies + static_cast<Eigen::Index>(rows.size() + u)) = full(users[u]);
}

void staticJacobian(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                    Eigen::MatrixXd& jac, std::vector<int>* activeRows) {
  using D = Dual<double>;
  const StateLayout& l = system.layout();
  const std::vector<int> rows = activeEquations(system);
  const std::vector<int> users = staticUserUnknowns(system);
  const int nb = l.bodies, na = static_cast<int>(rows.size()), n = l.size();
  const int nu = static_cast<int>(users.size());
  const int m = 6 * nb + na + nu;
  jac.resize(m, m);
  std::vector<D> yd(n), ypd(n, D(0.0)), g(n);
  for (int i = 0; i < n; ++i) yd[i] = D(y(i), 0.0);
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < 3; ++k) {
      yd[l.body(b) + StateLayout::kV + k] = D(0.0);
      yd[l.body(b) + StateLayout::kW + k] = D(0.0);
    }
  auto column = [&](int col) {
    for (int i = 0; i < n; ++i) g[i] = D(0.0);
    system.residual(t, yd.data(), ypd.data(), g.data());
    for (int b = 0; b < nb; ++b)
      for (int k = 0; k < 3; ++k) {
        jac(6 * b + k, col) = g[l.body(b) + StateLayout::kV + k].d;
        jac(6 * b + 3 + k, col) = g[l.body(b) + StateLayout::kW + k].d;
      }
    for (int r = 0; r < na; ++r) jac(6 * nb + r, col) = g[l.lambda(rows[r])].d;
    for (int u = 0; u < nu; ++u) jac(6 * nb + na + u, col) = g[users[u]].d;
  };
  for (int b = 0; b < nb; ++b) {
    const int o = l.body(b);
    for (int k = 0; k < 3; ++k) {
      yd[o + StateLayout::kR + k].d = 1.0;
      column(6 * b + k);
      yd[o + StateLayout::kR + k].d = 0.0;
    }
    const Eigen::Matrix<double, 4, 3> rates =
        eulerParameterRates(y.segment<4>(o + StateLayout::kE));
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 4; ++c) yd[o + StateLayout::kE + c].d = rates(c, k);
      column(6 * b + 3 + k);
      for (int c = 0; c < 4; ++c) yd[o + StateLayout::kE + c].d = 0.0;
    }
  }
  for (int r = 0; r < na; ++r) {
    yd[l.lambda(rows[r])].d = 1.0;
    column(6 * nb + r);
    yd[l.lambda(rows[r])].d = 0.0;
  }
  for (int u = 0; u < nu; ++u) {
    yd[users[u]].d = 1.0;
    column(6 * nb + na + u);
    yd[users[u]].d = 0.0;
  }
  if (activeRows) *activeRows = rows;
}

void applyStaticCorrection(const mechanics::MultibodySystem& system,
                           const std::vector<int>& activeRows, const Eigen::VectorXd& delta,
                           Eigen::VectorXd& y) {
  const StateLayout& l = system.layout();
  mechanics::applyBodyCorrection(l, delta.head(6 * l.bodies), y);
  for (size_t r = 0; r < activeRows.size(); ++r)
    y(l.lambda(activeRows[r])) += delta(6 * l.bodies + static_cast<Eigen::Index>(r));
  const std::vector<int> users = staticUserUnknowns(system);
  for (size_t u = 0; u < users.size(); ++u)
    y(users[u]) += delta(6 * l.bodies + static_cast<Eigen::Index>(activeRows.size() + u));
}

EquilibriumResult solveStaticEquilibrium(const mechanics::MultibodySystem& system, double t,
                                         Eigen::VectorXd& y,
                                         const model::EquilibriumSettings& settings) {
  const StateLayout& l = system.layout();
  const int nb = l.bodies;
  EquilibriumResult result;
  for (int b = 0; b < nb; ++b) {
    y.segment<3>(l.body(b) + StateLayout::kV).setZero();
    y.segment<3>(l.body(b) + StateLayout::kW).setZero();
    y(l.body(b) + StateLayout::kMu) = 0.0;
  }
  for (int k = 0; k < l.constraintEquations; ++k)
    if (!system.constraints().equations()[k].active) y(l.lambda(k)) = 0.0;
  const double length = characteristicLength(system.model());
  Eigen::MatrixXd mass;
  system.massMatrix(mass);
  std::vector<int> rows;
  Eigen::MatrixXd jac;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
  Eigen::VectorXd g;
  double lastCorrection = std::numeric_limits<double>::infinity();
  int loadedSingular = 0;  // consecutive Jacobians with a free, loaded direction
  for (int it = 0;; ++it) {
    staticResidual(system, t, y, g);
    const int na = static_cast<int>(g.size()) - 6 * nb;  // constraint and user rows
    const int nu = static_cast<int>(staticUserUnknowns(system).size());
    result.imbalance = nb > 0 ? g.head(6 * nb).cwiseAbs().maxCoeff(&result.worstBody) : 0.0;
    if (nb > 0) result.worstBody /= 6;
    result.constraintError = na > 0 ? g.tail(na).cwiseAbs().maxCoeff() : 0.0;
    result.iterations = it;
    result.correction = lastCorrection;
    if ((nb == 0 && nu == 0) || (result.imbalance <= settings.imbalance &&
                    result.constraintError <= settings.error && lastCorrection <= settings.error)) {
      result.status = EquilibriumResult::Status::Converged;
      break;
    }
    if (it >= settings.maxit) break;
    if (settings.pattern.at(it)) {
      staticJacobian(system, t, y, jac, &rows);
      Eigen::MatrixXd mechanical;
      const FreeDirections free =
          condensedJacobian(jac, 6 * nb + na - nu, mechanical)
              ? freeDirections(system, y, mechanical, g, na - nu, length, settings.imbalance)
              : FreeDirections{};
      loadedSingular = free.loaded.empty() ? 0 : loadedSingular + 1;
      if (!free.loaded.empty()) result.unbalanced = free.loaded.front();
      // A free direction that stays loaded and unrestrained while Newton moves the mechanism
      // by whole TLIMIT/ALIMIT steps has no equilibrium: stop and say so. (One singular
      // Jacobian alone proves nothing: a pendulum released horizontally starts at one.)
      if (loadedSingular >= 3) {
        result.status = EquilibriumResult::Status::Unbalanced;
        return result;
      }
      // STABILITY: a fraction of the mass matrix added to the stiffness keeps the matrix
      // regular along directions nothing restrains.
      jac.topLeftCorner(6 * nb, 6 * nb) += settings.stability * mass;
      solver.compute(jac);
    }
    Eigen::VectorXd delta = solver.solve(-g);
    delta *= mechanics::limitedCorrectionScale(delta, nb, settings.translationLimit,
                                               settings.angleLimit);
    lastCorrection = largestCorrection(delta, nb);
    if (nu > 0) lastCorrection = std::max(lastCorrection, delta.tail(nu).cwiseAbs().maxCoeff());
    applyStaticCorrection(system, rows, delta, y);
  }
  if (result.status == EquilibriumResult::Status::Converged && nb > 0) {
    result.unbalanced.reset();
    std::vector<int> active;
    staticJacobian(system, t, y, jac, &active);
    const int na = static_cast<int>(active.size());
    Eigen::MatrixXd mechanical;
    const FreeDirections free =
        condensedJacobian(jac, 6 * nb + na, mechanical)
            ? freeDirections(system, y, mechanical, g, na, length, settings.imbalance)
            : FreeDirections{};
    result.neutral = free.unloaded;
    result.unstable = free.negative;
  }
  return result;
}

}  // namespace openmss::analysis
