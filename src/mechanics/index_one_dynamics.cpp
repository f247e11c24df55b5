// The index-1 form of the equations of motion (mechanics/index_one_dynamics.hpp): accelerations
// and multipliers from the factored Schur complement (index_one_engine.hpp), and the position
// and velocity projections of the explicit integrators (docs/theory.md §9f).
#include "mechanics/index_one_dynamics.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>
#include <utility>

#include "mechanics/constraint_rows.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/index_one_engine.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::mechanics {
namespace {

// Position and velocity projections: a Newton iteration on an older factorisation is kept while
// it shrinks the violation at least this much per iteration, else S is formed afresh.
constexpr double kContraction = 0.2;
constexpr int kMaxProjectionIterations = 10;

}  // namespace

IndexOneDynamics::IndexOneDynamics(const MultibodySystem& system)
    : system_(system), engine_(std::make_unique<Engine>(system)) {}

IndexOneDynamics::~IndexOneDynamics() = default;

void IndexOneDynamics::useRuntimeSizeKernels() { engine_->runtimeSizeKernels = true; }

std::string IndexOneDynamics::unsupportedReason() const {
  if (system_.layout().userDifferential > 0)
    return "the model has DIFF, LSE, TFSISO or GSE states, which the index-1 form does not "
           "integrate; use INTEGRATOR/GSTIFF";
  return {};
}

namespace {

void normaliseEulerParameters(const StateLayout& l, Eigen::VectorXd& y) {
  for (int b = 0; b < l.bodies; ++b) {
    auto e = y.segment<4>(l.body(b) + StateLayout::kE);
    e /= e.norm();
  }
}

}  // namespace

bool IndexOneDynamics::evaluate(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  normaliseEulerParameters(l, y);
  // Functions of accelerations or reactions couple Q to u' and lambda (a Newton solve,
  // docs/theory.md §4b), and a massless body has no M^-1: both take the full KKT solve of the
  // initial-condition analysis, correct though several times slower.
  if (g.baselineAccelerations || !g.massInvertible) {
    ++factorizations_;
    return solveAccelerations(system_, t, y, yp);
  }
  if (g.m > 0) {
    g.rows.evaluate(t, y.data(), g.values.data(), g.gamma.data());
    ++factorizations_;
    if (!g.factor(g.values.data(), y)) return false;
  }
  return accelerationsFromFactor(t, y, yp);
}

bool IndexOneDynamics::accelerationsFromFactor(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  // VARIABLE values first: applied forces may read them (§4a).
  if (l.userAlgebraic > 0 && !solveUserAlgebraic(system_, t, y).converged) return false;
  system_.appliedForces(t, y.data(), g.forces);
  const int m = g.m;
  if (m > 0) {
    // S lambda = C M^-1 Q - gamma (from C u' = gamma and M u' = Q - C^T lambda).
    for (int pos = 0; pos < m; ++pos) g.x[pos] = -g.gamma[g.permutedRow[pos]];
    for (const Engine::Incidence& inc : g.incidences) {
      const int n = inc.rows;
      const double* wp = g.w.data() + inc.offset;
      const double* qb = g.forces.data() + 6 * inc.body;
      double* xj = g.x.data() + g.blockStart[inc.block];
      for (int r = 0; r < n; ++r) {
        const double* wr = wp + 6 * r;
        xj[r] += wr[0] * qb[0] + wr[1] * qb[1] + wr[2] * qb[2] + wr[3] * qb[3] + wr[4] * qb[4] +
                 wr[5] * qb[5];
      }
    }
    g.solve(g.x.data());
    g.correction(g.x.data(), g.delta);  // -M^-1 C^T lambda
  } else {
    g.delta.setZero(6 * l.bodies);
  }
  if (yp.size() != l.size()) yp.resize(l.size());
  yp.tail(l.size() - l.userStates()).setZero();
  for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) = 0.0;
  bool finite = true;
  for (int pos = 0; pos < m; ++pos) {
    const double lambda = g.x[pos];
    finite = finite && std::isfinite(lambda);
    y(l.lambda(g.rows.rows()[g.permutedRow[pos]])) = lambda;
  }
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    const double* e = y.data() + o + StateLayout::kE;
    const double* wb = y.data() + o + StateLayout::kW;
    double* d = yp.data() + o;
    for (int c = 0; c < 3; ++c) d[StateLayout::kR + c] = y(o + StateLayout::kV + c);
    d[StateLayout::kE + 0] = 0.5 * (-e[1] * wb[0] - e[2] * wb[1] - e[3] * wb[2]);
    d[StateLayout::kE + 1] = 0.5 * (e[0] * wb[0] + e[2] * wb[2] - e[3] * wb[1]);
    d[StateLayout::kE + 2] = 0.5 * (e[0] * wb[1] + e[3] * wb[0] - e[1] * wb[2]);
    d[StateLayout::kE + 3] = 0.5 * (e[0] * wb[2] + e[1] * wb[1] - e[2] * wb[0]);
    // u' = M^-1 Q - M^-1 C^T lambda.
    const double* qb = g.forces.data() + 6 * b;
    const double* cb = g.delta.data() + 6 * b;
    const Eigen::Matrix3d& ji = g.inverseInertia[b];
    for (int c = 0; c < 3; ++c) {
      d[StateLayout::kV + c] = g.inverseMass[b] * qb[c] + cb[c];
      d[StateLayout::kW + c] = ji(c, 0) * qb[3] + ji(c, 1) * qb[4] + ji(c, 2) * qb[5] + cb[3 + c];
      finite =
          finite && std::isfinite(d[StateLayout::kV + c]) && std::isfinite(d[StateLayout::kW + c]);
    }
    d[StateLayout::kMu] = 0.0;
    y(o + StateLayout::kMu) = 0.0;
  }
  userStateRates(system_, t, y, yp);
  return finite;
}

bool IndexOneDynamics::project(double t, Eigen::VectorXd& y, double positionTolerance) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  normaliseEulerParameters(l, y);
  if (g.m == 0) return true;
  if (!g.massInvertible) {
    // No mass weighting without M^-1: the plain least change of the set-up analysis.
    const AssemblyResult r = assemblePositions(system_, t, y, positionTolerance, 25);
    if (!r.converged) return false;
    solveVelocities(system_, t, y);
    return true;
  }
  if (!projectPositions(t, y, positionTolerance)) return false;
  // Velocities with C at the final positions (gamma is not needed: rows only).
  g.rows.evaluate(t, y.data(), g.values.data(), nullptr);
  return projectVelocities(y, false);
}

bool IndexOneDynamics::projectAndEvaluate(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp,
                                          double positionTolerance, bool* projected) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  if (projected) *projected = false;
  if (g.m == 0 || g.baselineAccelerations || !g.massInvertible) {
    // Nothing to share: no constraints, or evaluate() does not factor S.
    const bool done = project(t, y, positionTolerance);
    if (projected) *projected = done;
    return evaluate(t, y, yp);
  }
  normaliseEulerParameters(l, y);
  // Positions as project() does them (quasi-Newton on the factorisation at hand).
  if (!projectPositions(t, y, positionTolerance)) return evaluate(t, y, yp);
  normaliseEulerParameters(l, y);  // as evaluate() would before reading the positions
  // C at the projected positions and the one factorisation the evaluation needs anyway; the
  // velocity projection runs on it (exact: one solve), then gamma at the projected velocities
  // (C does not depend on them, gamma does, quadratically).
  g.rows.evaluate(t, y.data(), g.values.data(), nullptr);
  ++factorizations_;
  if (!g.factor(g.values.data(), y)) return false;
  const bool velocitiesProjected = projectVelocities(y, true);
  if (projected) *projected = velocitiesProjected;
  g.rows.evaluate(t, y.data(), nullptr, g.gamma.data());
  return accelerationsFromFactor(t, y, yp);
}

bool IndexOneDynamics::projectPositions(double t, Eigen::VectorXd& y, double positionTolerance) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  // The factorisation of the last evaluation (a nearby state) serves while the Newton
  // iteration contracts fast; S is formed afresh at the current state when it does not.
  auto refactor = [&]() {
    g.rows.evaluate(t, y.data(), g.values.data(), nullptr);
    ++factorizations_;
    return g.factor(g.values.data(), y);
  };
  g.rows.values(t, y.data(), g.phi.data(), g.nu.data());
  auto largest = [&](const std::vector<double>& v) {
    double worst = 0.0;
    for (double e : v) worst = std::max(worst, std::abs(e));
    return std::isfinite(worst) ? worst : HUGE_VAL;
  };
  double error = largest(g.phi);
  for (int it = 0; error > positionTolerance; ++it) {
    if (it == kMaxProjectionIterations) return false;
    if (!g.factored && !refactor()) return false;
    for (int pos = 0; pos < g.m; ++pos) g.x[pos] = g.phi[g.permutedRow[pos]];
    g.solve(g.x.data());
    g.correction(g.x.data(), g.delta);  // dq = -M^-1 C^T S^-1 Phi
    applyBodyCorrection(l, g.delta, y);
    g.rows.values(t, y.data(), g.phi.data(), g.nu.data());
    const double next = largest(g.phi);
    if (!(next <= kContraction * error)) g.factored = false;  // poor contraction: refactor
    error = next;
  }
  return true;
}

bool IndexOneDynamics::projectVelocities(Eigen::VectorXd& y, bool current) {
  const StateLayout& l = system_.layout();
  Engine& g = *engine_;
  // du = -M^-1 C^T S^-1 (C u - nu), C (in g.values) and nu at the final positions.
  double scale = 0.0;
  double residual = g.velocityResidual(g.values.data(), g.nu.data(), y, g.x.data(), &scale);
  // Relative to the size of the terms of C u; the round-off floor is ~1e-16 of it.
  const double tolerance = 1e-12 * std::max(scale, 1e-300);
  for (int it = 0; residual > tolerance; ++it) {
    if (it == kMaxProjectionIterations) break;  // round-off floor: as good as it gets
    if (!current && !g.factoredAt(y)) {
      // A factorisation at other positions would correct along M^-1 C_old^T: C u = nu would
      // still be reached, but not by the least change. S is formed here (values hold C).
      ++factorizations_;
      if (!g.factor(g.values.data(), y)) return false;
    }
    current = true;
    g.solve(g.x.data());
    g.correction(g.x.data(), g.delta);
    for (int b = 0; b < l.bodies; ++b) {
      y.segment<3>(l.body(b) + StateLayout::kV) += g.delta.segment<3>(6 * b);
      y.segment<3>(l.body(b) + StateLayout::kW) += g.delta.segment<3>(6 * b + 3);
    }
    const double next = g.velocityResidual(g.values.data(), g.nu.data(), y, g.x.data(), nullptr);
    if (!(next <= kContraction * residual)) break;  // an exact solve stalls only at round-off
    residual = next;
  }
  return std::isfinite(residual);
}

double IndexOneDynamics::positionViolation(double t, const Eigen::VectorXd& y) const {
  Engine& g = *engine_;
  g.rows.values(t, y.data(), g.phi.data(), g.nu.data());
  double worst = 0.0;
  for (double v : g.phi) worst = std::max(worst, std::abs(v));
  return worst;
}

double IndexOneDynamics::velocityViolation(double t, const Eigen::VectorXd& y) const {
  Engine& g = *engine_;
  g.rows.values(t, y.data(), g.phi.data(), g.nu.data());
  g.rows.evaluate(t, y.data(), g.values.data(), nullptr);
  return g.velocityResidual(g.values.data(), g.nu.data(), y, nullptr, nullptr);
}

}  // namespace openmss::mechanics
