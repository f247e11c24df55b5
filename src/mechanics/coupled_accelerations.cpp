#include "mechanics/coupled_accelerations.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/dual.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::mechanics {
namespace {

bool functionReads(const model::Model& m, const model::BoundExpression& f, bool reactionsOnly,
                   int depth);

// Whether marker i's FX..TM(i, j) takes a constraint reaction: a joint, joint primitive or
// motion acting between them, or a GCON whose FUNCTION reads them (as
// ForceElements::netForceTakes selects the equations).
bool netForceReadsReactions(const model::Model& m, const model::Measure& ms) {
  auto acts = [&](int a, int b) {
    return (a == ms.i && (ms.j < 0 || b == ms.j)) || (b == ms.i && (ms.j < 0 || a == ms.j));
  };
  for (const model::Joint& j : m.joints)
    if (acts(j.iMarker, j.jMarker)) return true;
  for (const model::JPrim& j : m.jprims)
    if (acts(j.iMarker, j.jMarker)) return true;
  for (const model::Motion& j : m.motions)
    if (acts(j.iMarker, j.jMarker)) return true;
  for (const model::PointCurve& p : m.ptcvs)
    if (acts(p.iMarker, p.rmMarker)) return true;
  for (const model::CurveCurve& c : m.cvcvs)
    if (acts(c.iRm, c.jRm)) return true;
  return !m.gcons.empty();  // conservative: a GCON's markers are those its FUNCTION reads
}

// Whether a force element read back by `ms` (SFORCE, VFORCE, ..., FX..TM) has a function that
// reads accelerations or reactions: the read-back then reads them too (force_read_back.hpp).
bool readBackReads(const model::Model& m, const model::Measure& ms, bool reactionsOnly,
                   int depth) {
  using K = model::MeasureKind;
  auto vector = [&](int k) {
    for (const auto& c : m.vectorForces[k].components)
      if (c && functionReads(m, *c, reactionsOnly, depth + 1)) return true;
    return false;
  };
  switch (ms.kind) {
    case K::SForceForce:
      return functionReads(m, m.sforces[ms.element].function, reactionsOnly, depth + 1);
    case K::VForceForce: case K::VTorqueForce: case K::GForceForce:
      return vector(ms.element);
    case K::FrictionOutput:  // the normal force is the joint's reaction (its multipliers)
      return true;
    case K::NetForce: {
      if (netForceReadsReactions(m, ms)) return true;
      auto acts = [&](int a, int b) {
        return (a == ms.i && (ms.j < 0 || b == ms.j)) || (b == ms.i && (ms.j < 0 || a == ms.j));
      };
      for (size_t k = 0; k < m.sforces.size(); ++k)
        if (acts(m.sforces[k].iMarker, m.sforces[k].jMarker) &&
            functionReads(m, m.sforces[k].function, reactionsOnly, depth + 1))
          return true;
      for (size_t k = 0; k < m.vectorForces.size(); ++k)
        if (acts(m.vectorForces[k].iMarker, m.vectorForces[k].jFloat) &&
            vector(static_cast<int>(k)))
          return true;
      return false;
    }
    default:
      return false;
  }
}

// True when f reads an acceleration (unless reactionsOnly) or a reaction, directly or through
// the force elements it reads back. The model builder refuses read-back cycles; `depth` bounds
// the chain all the same (a longer one is taken as reading them).
bool functionReads(const model::Model& m, const model::BoundExpression& f, bool reactionsOnly,
                   int depth) {
  if (depth > static_cast<int>(m.sforces.size() + m.vectorForces.size()) + 1) return true;
  using K = model::MeasureKind;
  return std::any_of(f.measures.begin(), f.measures.end(), [&](const model::Measure& ms) {
    const bool reaction =
        ms.kind == K::JointForce || ms.kind == K::MotionForce || ms.kind == K::JPrimForce;
    if (reaction || (!reactionsOnly && model::readsAccelerationOrReaction(ms.kind))) return true;
    return readBackReads(m, ms, reactionsOnly, depth);
  });
}

bool functionReads(const model::Model& m, const model::BoundExpression& f) {
  return functionReads(m, f, false, 0);
}

}  // namespace

void kinematicRates(const StateLayout& l, const Eigen::VectorXd& y, Eigen::VectorXd& yp) {
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    const Eigen::Vector4d e = y.segment<4>(o + StateLayout::kE);
    const Eigen::Vector3d w = y.segment<3>(o + StateLayout::kW);
    yp.segment<3>(o + StateLayout::kR) = y.segment<3>(o + StateLayout::kV);
    yp(o + StateLayout::kE + 0) = 0.5 * (-e(1) * w(0) - e(2) * w(1) - e(3) * w(2));
    yp(o + StateLayout::kE + 1) = 0.5 * (e(0) * w(0) + e(2) * w(2) - e(3) * w(1));
    yp(o + StateLayout::kE + 2) = 0.5 * (e(0) * w(1) + e(3) * w(0) - e(1) * w(2));
    yp(o + StateLayout::kE + 3) = 0.5 * (e(0) * w(2) + e(1) * w(1) - e(2) * w(0));
  }
}

bool readsAccelerationsOrReactions(const model::Model& m) {
  if (!m.frictions.empty()) return true;  // joint friction reads its joint's reaction
  for (const model::SForce& f : m.sforces)
    if (functionReads(m, f.function)) return true;
  for (const model::VectorForce& f : m.vectorForces)
    for (const auto& c : f.components)
      if (c && functionReads(m, *c)) return true;
  for (const model::Variable& v : m.variables)
    if (functionReads(m, v.function)) return true;
  for (const model::Diff& d : m.diffs)
    if (functionReads(m, d.function)) return true;
  return false;
}

bool forceFunctionsReadReactions(const model::Model& m) {
  if (!m.frictions.empty()) return true;  // joint friction reads its joint's reaction
  // Directly or through a read-back of a force that reads them, or FX..TM (theory.md §4d).
  auto reads = [&m](const model::BoundExpression& f) { return functionReads(m, f, true, 0); };
  for (const model::SForce& f : m.sforces)
    if (reads(f.function)) return true;
  for (const model::VectorForce& f : m.vectorForces)
    for (const auto& c : f.components)
      if (c && reads(*c)) return true;
  return false;
}

CoupledAccelerationResult solveCoupledAccelerations(const MultibodySystem& system, double t,
                                                    Eigen::VectorXd& y, Eigen::VectorXd& yp,
                                                    int maxIterations) {
  using D = Dual<double>;
  const StateLayout& l = system.layout();
  const int nb = l.bodies, n = l.size();
  std::vector<int> rows;
  const Eigen::MatrixXd c = activeConstraintJacobian(system, y.data(), &rows);
  const int nc = static_cast<int>(rows.size()), na = l.userAlgebraic;
  // Right-hand side of the acceleration-level constraints: f'' - (C' u) (as solveAccelerations).
  Eigen::VectorXd gamma(nc);
  for (int r = 0; r < nc; ++r) {
    double first = 0.0, second = 0.0;
    system.constraintRates(rows[r], y.data(), &first, &second);
    const auto& eq = system.constraints().equations()[rows[r]];
    gamma(r) = (eq.motion >= 0 ? system.motionJet(rows[r], t).d2 : 0.0) - second;
  }
  // Unknowns: v' and w' of every body (yp), the active multipliers and the user algebraic
  // unknowns (y). `where` maps unknown u to its entry, `inYp` to which vector.
  const int nu = 6 * nb + nc + na;
  std::vector<int> where(static_cast<size_t>(nu));
  std::vector<bool> inYp(static_cast<size_t>(nu), false);
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k < 3; ++k) {
      where[6 * b + k] = l.body(b) + StateLayout::kV + k;
      where[6 * b + 3 + k] = l.body(b) + StateLayout::kW + k;
      inYp[6 * b + k] = inYp[6 * b + 3 + k] = true;
    }
  for (int r = 0; r < nc; ++r) where[6 * nb + r] = l.lambda(rows[r]);
  for (int k = 0; k < na; ++k) where[6 * nb + nc + k] = l.userAlg(k);
  // Equations: the force and moment rows of every body, C u' = gamma, the user algebraic rows.
  auto residualRow = [&](int e) {
    const int body = e / 6, k = e % 6;
    return l.body(body) + (k < 3 ? StateLayout::kV + k : StateLayout::kW + k - 3);
  };

  yp = Eigen::VectorXd::Zero(n);
  kinematicRates(l, y, yp);
  for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) = 0.0;
  for (int b = 0; b < nb; ++b) y(l.body(b) + StateLayout::kMu) = 0.0;

  Eigen::VectorXd g(n), f(nu);
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(nu, nu);
  std::vector<D> yd(static_cast<size_t>(n)), ypd(static_cast<size_t>(n)), gd(static_cast<size_t>(n));
  auto unknownsOf = [&](int u) -> double& { return inYp[u] ? yp(where[u]) : y(where[u]); };
  auto evaluate = [&]() {
    g.setZero();
    system.residual(t, y.data(), yp.data(), g.data());
    for (int e = 0; e < 6 * nb; ++e) f(e) = g(residualRow(e));
    Eigen::VectorXd accelerations(6 * nb);
    for (int e = 0; e < 6 * nb; ++e) accelerations(e) = yp(where[e]);
    if (nc > 0) f.segment(6 * nb, nc) = c * accelerations - gamma;
    for (int k = 0; k < na; ++k) f(6 * nb + nc + k) = g(l.userAlg(k));
  };
  CoupledAccelerationResult result;
  for (int it = 0; it < maxIterations; ++it) {
    evaluate();
    result.residual = f.size() > 0 ? f.cwiseAbs().maxCoeff() : 0.0;
    if (!std::isfinite(result.residual)) return result;
    // The exact Jacobian: one dual residual pass per unknown (the constraint rows are C).
    for (int i = 0; i < n; ++i) {
      yd[i] = D(y(i), 0.0);
      ypd[i] = D(yp(i), 0.0);
    }
    jac.setZero();
    for (int u = 0; u < nu; ++u) {
      std::vector<D>& seeded = inYp[u] ? ypd : yd;
      seeded[where[u]].d = 1.0;
      std::fill(gd.begin(), gd.end(), D(0.0, 0.0));
      system.residual(t, yd.data(), ypd.data(), gd.data());
      for (int e = 0; e < 6 * nb; ++e) jac(e, u) = gd[residualRow(e)].d;
      for (int k = 0; k < na; ++k) jac(6 * nb + nc + k, u) = gd[l.userAlg(k)].d;
      seeded[where[u]].d = 0.0;
    }
    if (nc > 0) jac.block(6 * nb, 0, nc, 6 * nb) = c;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(jac);
    if (!lu.isInvertible()) {
      result.singular = true;
      return result;
    }
    const Eigen::VectorXd delta = lu.solve(-f);
    double size = 0.0;
    for (int u = 0; u < nu; ++u) {
      double& x = unknownsOf(u);
      x += delta(u);
      size = std::max(size, std::abs(delta(u)) / (1.0 + std::abs(x)));
    }
    result.iterations = it + 1;
    if (size <= 1e-12) {
      evaluate();
      result.residual = f.size() > 0 ? f.cwiseAbs().maxCoeff() : 0.0;
      result.converged = std::isfinite(result.residual);
      break;
    }
  }
  if (result.converged) userStateRates(system, t, y, yp);
  return result;
}

}  // namespace openmss::mechanics
