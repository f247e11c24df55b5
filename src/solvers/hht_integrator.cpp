#include "solvers/hht_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/bdf_integrator.hpp"
#include "solvers/hermite_weights.hpp"

namespace openmss::solvers {
namespace {

using Role = DaeProblem::Role;

// Corrector convergence, in units of the error tolerance (as the BDF family's): a change this
// small has converged at once.
constexpr double kTightChange = 1e-9;
// ... and an iteration whose estimated remainder, rate / (1 - rate) times its last change, is
// below this share of the tolerance (issue 21). 1e-9 here took about 9 iterations per step on
// the 100-link chains; 1e-3 takes about 6 with the same tip error at ERROR = 1e-6
// (docs/performance.md, "Where GSTIFF's time goes", HHT).
constexpr double kConvergedRemainder = 1e-3;
// A step that converged on an older matrix at a contraction rate above this re-forms the matrix
// for the next step, as BdfIntegrator's kRefreshRate does (docs/integrators.md, "HHT and
// NEWMARK"). The matrix is otherwise kept while h stays within 20 % of the h it was formed at;
// on the 100-link planar chain at ERROR = 1e-6 that was 13 matrices in 3033 steps and about 5
// corrector iterations per step. Measured there (residual evaluations, Jacobians): never
// 18369, 13; 0.3 17603, 15; 0.1 14260, 44; 0.05 12448, 59; 0.02 10589, 254 (each Jacobian and
// refactorisation costs about ten iterations at N = 100); the steps and the tip error unchanged.
constexpr double kRefreshRate = 0.05;
// A stalled iteration whose scaled residual is below this share of its first value has
// converged as far as the linear solves allow (singular configurations, BdfIntegrator).
constexpr double kResidualNoise = 1e-6;
// ... or whose unscaled residual has, BdfIntegrator's kRawResidualNoise: the scaled residual is
// dominated by the constraint rows times 1/h^2, which through a flat passage keep the positions'
// round-off along the extra degrees of freedom above kResidualNoise while every equation is
// solved to round-off (A02 with the I3 velocity test, without this rule: N = 4 at ERROR = 1e-9
// stopped at the flat passage at t = 9.05 s, the steps shrunk to 2.5e-8 s by corrector
// failures; N = 40 at 1e-8 at t = 7.1 s).
constexpr double kRawResidualNoise = 1e-6;
// The I3 velocity test's horizon in steps, BdfIntegrator's kVelocityTestSteps (docs/integrators.md,
// "HHT's velocity test").
constexpr double kVelocityTestSteps = 2.0;

int roleCode(Role r) { return static_cast<int>(r); }

}  // namespace

HhtIntegrator::HhtIntegrator(DaeProblem& problem, const HhtSettings& settings)
    : problem_(problem), settings_(settings) {}

void HhtIntegrator::start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  const int n = problem_.size();
  role_.resize(n);
  for (int i = 0; i < n; ++i) role_(i) = roleCode(problem_.role(i));
  t_ = tPrevious_ = t0;
  y_ = yPrev_ = y0;
  yp_ = ypPrev_ = yp0;
  // Newmark's acceleration of a position is q'' = d/dt f(y) for its kinematic row
  // G_q = q' - f(y): q'' = -dG_q/dy . y', the directional derivative along the consistent
  // y' (multipliers held: their rates do not enter the kinematic rows).
  acc_ = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd dir = yp0, gPlus(n), gMinus(n);
  for (int i = 0; i < n; ++i)
    if (role_(i) == roleCode(Role::Algebraic)) dir(i) = 0.0;
  const double size = dir.lpNorm<Eigen::Infinity>();
  if (size > 0.0) {
    const double eps = 1e-6 * std::max(1.0, y0.lpNorm<Eigen::Infinity>()) / size;
    problem_.residual(t0, y0 + eps * dir, yp0, gPlus);
    problem_.residual(t0, y0 - eps * dir, yp0, gMinus);
    stats_.residualEvaluations += 2;
    for (int i = 0; i < n; ++i)
      if (role_(i) == roleCode(Role::Position)) acc_(i) = -(gPlus(i) - gMinus(i)) / (2.0 * eps);
  }
  h_ = settings_.hinit > 0 ? settings_.hinit
                           : (std::isfinite(settings_.hmax) ? settings_.hmax / 100.0 : 1e-3);
  h_ = std::min(h_, settings_.hmax);
  for (auto* v : {&yNew_, &ypNew_, &yPred_, &ypPred_, &g_, &gOld_, &gOldPred_, &dy_, &slope_})
    v->resize(n);
  rowScale_ = Eigen::VectorXd::Ones(n);
  colScale_ = Eigen::VectorXd::Ones(n);
  // Large problems with a sparse Newton matrix: KLU, as the BDF family (dense LU on the 1,900
  // unknowns of a 100-link chain: 16.9 s CPU for 1 s of motion, KLU 0.19 s; docs/theory.md §9a).
  sparse_ = problem_.sparse() && n >= BdfIntegrator::kSparseThreshold;
  if (sparse_) {
    sparseJac_ = *problem_.pattern();
    sparseA_ = sparseJac_;
    klu_.analyze(sparseJac_);
  }
  haveJacobian_ = jacobianCurrent_ = refreshNext_ = false;
}

double HhtIntegrator::weightedNorm(const Eigen::VectorXd& v, const Eigen::VectorXd& ref,
                                   bool errorOnly) const {
  double worst = 0.0;
  for (int i = 0; i < v.size(); ++i) {
    if (errorOnly ? !problem_.errorControlled(i) : role_(i) == roleCode(Role::Algebraic)) continue;
    const double r = std::abs(v(i)) / (settings_.error * (1.0 + std::abs(ref(i))));
    if (std::isnan(r)) return r;
    worst = std::max(worst, r);
  }
  return worst;
}

void HhtIntegrator::noteWorst(const Eigen::VectorXd& g, const Eigen::VectorXd& dy) {
  auto worse = [](double candidate, double current) {
    return !std::isfinite(candidate) ? std::isfinite(current) : candidate > current;
  };
  lastWorstEq_ = lastWorstVar_ = -1;
  lastWorstRes_ = lastWorstChange_ = 0.0;
  for (int i = 0; i < g.size(); ++i) {
    if (worse(std::abs(g(i)), lastWorstRes_)) {
      lastWorstRes_ = std::abs(g(i));
      lastWorstEq_ = i;
    }
    if (role_(i) != roleCode(Role::Algebraic) && worse(std::abs(dy(i)), lastWorstChange_)) {
      lastWorstChange_ = std::abs(dy(i));
      lastWorstVar_ = i;
    }
  }
}

// The corrector's unknown is y; y' follows linearly, y'_i = y'pred_i + slope_i (y_i - ypred_i):
// slope 1/(h gamma) for velocities and first-order states (gamma rule), gamma/(h beta) for
// positions (beta rule with q' as Newmark's velocity), 0 for multipliers. With A = dG/dy and
// B = dG/dy', column i of the Newton matrix is A_i + slope_i B_i, except that the alpha-shifted
// force-balance rows take (1 + alpha) A: their old-step part depends on y' only.
void HhtIntegrator::formNewtonMatrix(double tNew, double h) {
  const int n = problem_.size();
  // Balance as the BDF family does, with 1/h in the place of cj.
  const double s = 1.0 / h;
  for (int i = 0; i < n; ++i) {
    rowScale_(i) = std::pow(s, problem_.rowScaleExponent(i));
    colScale_(i) = std::pow(s, problem_.unknownScaleExponent(i));
  }
  hJacobian_ = h;
  haveJacobian_ = jacobianCurrent_ = true;
  if (sparse_) {
    formSparseNewtonMatrix(tNew);
    return;
  }
  problem_.newtonMatrix(tNew, yPred_, ypPred_, 0.0, jac_);   // A
  problem_.newtonMatrix(tNew, yPred_, ypPred_, 1.0, jacB_);  // A + B
  ++stats_.jacobianEvaluations;
  jacB_ -= jac_;
  const double alpha = settings_.alpha;
  for (int r = 0; r < n; ++r)
    if (role_(r) == roleCode(Role::Velocity)) jac_.row(r) *= 1.0 + alpha;
  for (int c = 0; c < n; ++c) jac_.col(c) += slope_(c) * jacB_.col(c);
  jac_ = rowScale_.asDiagonal() * jac_ * colScale_.asDiagonal();
  lu_.compute(jac_);
}

void HhtIntegrator::formSparseNewtonMatrix(double tNew) {
  // A and A + B on one pattern. The problem may widen its pattern while filling either
  // (DaeProblem::newtonMatrixSparse); widening only adds entries, so when the two counts
  // differ the first is filled again on the widened pattern, after which both hold it.
  problem_.newtonMatrixSparse(tNew, yPred_, ypPred_, 0.0, sparseA_);
  problem_.newtonMatrixSparse(tNew, yPred_, ypPred_, 1.0, sparseJac_);
  if (sparseA_.nonZeros() != sparseJac_.nonZeros()) {
    problem_.newtonMatrixSparse(tNew, yPred_, ypPred_, 0.0, sparseA_);
    if (sparseA_.nonZeros() != sparseJac_.nonZeros())
      problem_.newtonMatrixSparse(tNew, yPred_, ypPred_, 1.0, sparseJac_);
  }
  ++stats_.jacobianEvaluations;
  // Entry by entry the dense formula: (1 + alpha) A on the force-balance (velocity) rows, A
  // elsewhere, plus slope_c B_c, then the row and column balance.
  const double alpha = settings_.alpha;
  const double* a = sparseA_.valuePtr();
  double* j = sparseJac_.valuePtr();
  for (int c = 0; c < sparseJac_.outerSize(); ++c) {
    for (int e = sparseJac_.outerIndexPtr()[c]; e < sparseJac_.outerIndexPtr()[c + 1]; ++e) {
      const int r = sparseJac_.innerIndexPtr()[e];
      const double aShifted = role_(r) == roleCode(Role::Velocity) ? (1.0 + alpha) * a[e] : a[e];
      j[e] = rowScale_(r) * (aShifted + slope_(c) * (j[e] - a[e])) * colScale_(c);
    }
  }
  // Exact zeros left out of the factorisation where they persist (nonzero_pattern.hpp).
  klu_.factor(problem_.zerosPersist() ? nonzero_.select(sparseJac_) : sparseJac_);
}

void HhtIntegrator::solveNewton(Eigen::VectorXd& x) {
  if (sparse_) {
    klu_.solve(x);  // NaNs when the factorisation failed: the attempt fails
    return;
  }
  const Eigen::VectorXd solved = lu_.solve(x);  // (a temporary, as before: no aliasing)
  x = solved;
}

bool HhtIntegrator::attemptStep(double h, bool* newtonFailed, double* errorNorm) {
  *newtonFailed = false;
  const int n = problem_.size();
  const double tNew = t_ + h;
  const double beta = settings_.beta, gamma = settings_.gamma, alpha = settings_.alpha;
  // Predictor: Newmark's update with the acceleration held at its last value.
  for (int i = 0; i < n; ++i) {
    switch (static_cast<Role>(role_(i))) {
      case Role::Position:
        ypPred_(i) = yp_(i) + h * acc_(i);
        yPred_(i) = y_(i) + h * yp_(i) + 0.5 * h * h * acc_(i);
        slope_(i) = gamma / (h * beta);
        break;
      case Role::Velocity:
      case Role::FirstOrder:
        ypPred_(i) = yp_(i);
        yPred_(i) = y_(i) + h * yp_(i);
        slope_(i) = 1.0 / (h * gamma);
        break;
      case Role::Algebraic:
        ypPred_(i) = yp_(i);
        yPred_(i) = y_(i);
        slope_(i) = 0.0;
        break;
    }
  }
  if (!haveJacobian_ || refreshNext_ || std::abs(h / hJacobian_ - 1.0) > 0.2)
    formNewtonMatrix(tNew, h);
  refreshNext_ = false;

  const bool affineInRates = problem_.forceRowsAffineInRates();
  stalledMove_ = false;
  for (int attempt = 0; attempt < 2; ++attempt) {
    yNew_ = yPred_;
    double previous = 0.0, rate = 0.0;
    double firstResidual = 0.0, lastResidual = 0.0;
    double firstRaw = 0.0, lastRaw = 0.0;  // the same, unscaled (kRawResidualNoise)
    bool converged = false;
    for (int it = 0; it < settings_.maxit; ++it) {
      ypNew_ = ypPred_ + slope_.cwiseProduct(yNew_ - yPred_);
      if (settings_.patternGiven && (it == 0 ? !jacobianCurrent_ : settings_.pattern[it % 10])) {
        std::swap(yPred_, yNew_);  // formNewtonMatrix linearises at yPred_
        std::swap(ypPred_, ypNew_);
        formNewtonMatrix(tNew, h);
        std::swap(yPred_, yNew_);
        std::swap(ypPred_, ypNew_);
      }
      problem_.residual(tNew, yNew_, ypNew_, g_);
      ++stats_.residualEvaluations;
      if (alpha != 0.0) {
        // HHT: force balance = (1 + alpha) G(t_n+1) - alpha G(t_n, y_n, y'_n+1): inertia at the
        // new step, applied and constraint forces weighted between the steps. Where y' enters
        // those rows only as B y' (DaeProblem::forceRowsAffineInRates), G(t_n, y_n, y') is
        // G(t_n, y_n, y'_pred) + B (y' - y'_pred): one residual per step, not per iteration.
        if (!affineInRates) {
          problem_.residual(t_, y_, ypNew_, gOld_);
          ++stats_.residualEvaluations;
        } else if (it == 0) {
          problem_.residual(t_, y_, ypPred_, gOldPred_);
          ++stats_.residualEvaluations;
          gOld_ = gOldPred_;  // y'_new = y'_pred at the predictor
        } else {
          gOld_ = gOldPred_;
          dy_ = ypNew_ - ypPred_;  // dy_ is free until the solve below
          problem_.addRateTerm(dy_, gOld_);
        }
        for (int i = 0; i < n; ++i)
          if (role_(i) == roleCode(Role::Velocity))
            g_(i) = (1.0 + alpha) * g_(i) - alpha * gOld_(i);
      }
      dy_ = rowScale_.cwiseProduct(g_);
      lastResidual = dy_.cwiseAbs().maxCoeff();
      lastRaw = g_.cwiseAbs().maxCoeff();
      if (it == 0) {
        firstResidual = lastResidual;
        firstRaw = lastRaw;
      }
      solveNewton(dy_);
      dy_ = colScale_.cwiseProduct(dy_);
      yNew_ -= dy_;
      const double size = weightedNorm(dy_, yNew_, false);
      noteWorst(g_, dy_);
      if (!std::isfinite(size)) break;
      notifyIteration(
          {tNew, h, 2, it + 1, lastWorstEq_, lastWorstRes_, lastWorstVar_, lastWorstChange_});
      if (it > 0) rate = size / std::max(previous, 1e-300);
      previous = size;
      if (size <= kTightChange ||
          (it > 0 && rate < 0.9 && rate / (1.0 - rate) * size <= kConvergedRemainder)) {
        converged = true;
        break;
      }
      // Stalled at round-off: changes far below the tolerance, or (at a singular
      // configuration, where the matrix is nearly singular along the mechanism's extra degrees
      // of freedom) a residual already below kResidualNoise of its first value, as in
      // BdfIntegrator (docs/integrators.md, "Singular configurations").
      if (it > 0 && rate >= 0.9 &&
          (size <= 1e-3 || lastResidual <= kResidualNoise * firstResidual ||
           lastRaw <= kRawResidualNoise * firstRaw)) {
        converged = true;
        stalledMove_ = size > 1e-3;
        break;
      }
      if (it > 1 && rate > 0.9) break;
    }
    if (converged && !jacobianCurrent_ && rate > kRefreshRate) refreshNext_ = true;
    if (converged) break;
    if (jacobianCurrent_ || attempt == 1) {
      *newtonFailed = true;
      return false;
    }
    formNewtonMatrix(tNew, h);
  }
  ypNew_ = ypPred_ + slope_.cwiseProduct(yNew_ - yPred_);
  // Local error: positions (beta - 1/6) h^3 q''' with q''' from the change of q'' over the
  // step; first-order states max(|gamma - 1/2|, 1/12) h^2 y'' likewise.
  dy_.setZero();
  for (int i = 0; i < n; ++i) {
    if (!problem_.errorControlled(i)) continue;
    if (role_(i) == roleCode(Role::Position)) {
      const double accNew = (ypNew_(i) - yp_(i) - h * (1.0 - gamma) * acc_(i)) / (h * gamma);
      dy_(i) = std::abs(beta - 1.0 / 6.0) * h * h * (accNew - acc_(i));
    } else if (role_(i) != roleCode(Role::Algebraic)) {
      dy_(i) = std::max(std::abs(gamma - 0.5), 1.0 / 12.0) * h * (ypNew_(i) - yp_(i));
    }
  }
  *errorNorm = weightedNorm(dy_, yNew_, true);
  // The I3 velocity test (docs/integrators.md, "HHT's velocity test"): an index-3 velocity is
  // outside the position test, yet its local error turns into a phase error of undamped motion
  // (A02). Its estimate is the gamma rule's truncation term, as for the first-order states
  // above, weighed as the displacement it makes over kVelocityTestSteps steps, the index-2
  // scaling by h of Hairer and Wanner's RADAU5 that BdfIntegrator's I3 velocity test uses too:
  // kVelocityTestSteps h / (ERROR (1 + |v_n|)). Its order, h^3, is the position test's, so
  // the step ratio keeps the exponent 1/3.
  const double velocityCoefficient =
      kVelocityTestSteps * h * std::max(std::abs(gamma - 0.5), 1.0 / 12.0) * h;
  for (int i = 0; i < n; ++i) {
    if (role_(i) != roleCode(Role::Velocity) || problem_.errorControlled(i)) continue;
    const double e = velocityCoefficient * std::abs(ypNew_(i) - yp_(i)) /
                     (settings_.error * (1.0 + std::abs(y_(i))));
    if (!(e <= *errorNorm)) *errorNorm = e;  // NaN propagates
  }
  if (!std::isfinite(*errorNorm)) {
    *newtonFailed = true;
    return false;
  }
  return *errorNorm <= 1.0;
}

bool HhtIntegrator::step(double tout) {
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  const double hmin =
      settings_.hmin > 0 ? settings_.hmin : std::max(1e-14, 1e-10 * std::min(settings_.hmax, 1e3));
  // Stepping across a singular instant (docs/integrators.md): a step accepted on a corrector
  // that stalled with changes above round-off (a move along the Newton matrix's near-null
  // direction at a kinematic singularity, accepted by the residual rules) is not handed to the
  // caller; the next step is taken at once. When no step can leave such a state (the step size
  // falls below HMIN), the method returns once to the state it started from, which the caller
  // has seen, and tries a step twice as long as the way to the stuck point, across it. Every
  // state handed over is then one the caller can keep: no output, run-state record or sensor
  // check saw the abandoned steps.
  const double tEntry = t_;  // its state is kept (yEntry_ …) when a first stalled step leaves it
  bool returned = false;  // back at the entry state once already
  long internalSteps = 0;
  while (t_ < tout - eps) {
    double h = std::min(h_, settings_.hmax);
    if (t_ + h >= tout - eps)
      h = tout - t_;
    else if (t_ + 2.0 * h > tout)
      h = 0.5 * (tout - t_);
    bool newtonFailed = false;
    double err = 0.0;
    using Event = StepInfo::Event;
    notifyStep({Event::Attempt, stats_.steps + 1, 2, t_, h, 0.0});
    if (!attemptStep(h, &newtonFailed, &err)) {
      notifyStep({newtonFailed ? Event::CorrectorFailed : Event::ErrorTestFailed, stats_.steps + 1,
                  2, t_, h, err});
      if (newtonFailed) {
        ++stats_.newtonFailures;
        h_ = 0.25 * h;
        jacobianCurrent_ = false;
      } else {
        ++stats_.rejectedSteps;
        h_ = h * std::clamp(0.9 * std::pow(1.0 / err, 1.0 / 3.0), 0.2, 0.9);
      }
      if (h_ < hmin && !returned && t_ > tEntry) {
        h_ = std::min(2.0 * (t_ - tEntry), settings_.hmax);
        t_ = tPrevious_ = tEntry;
        y_ = yPrev_ = yEntry_;
        yp_ = ypPrev_ = ypEntry_;
        acc_ = accEntry_;
        internalSteps = 0;
        returned = true;
        refreshNext_ = true;
        ++stats_.rejectedSteps;
        continue;
      }
      if (h_ < hmin) {
        failure_ = {t_,
                    h_,
                    newtonFailed ? "the corrector did not converge"
                                 : "the local error stays above the tolerance",
                    lastWorstEq_,
                    lastWorstRes_,
                    lastWorstVar_,
                    lastWorstChange_};
        return false;
      }
      continue;
    }
    notifyStep({Event::Accepted, stats_.steps + 1, 2, t_, h, err});
    if (stalledMove_ && !returned && internalSteps == 0) {  // the entry state may be needed
      yEntry_ = y_;
      ypEntry_ = yp_;
      accEntry_ = acc_;
    }
    const double gamma = settings_.gamma;
    for (int i = 0; i < y_.size(); ++i)
      if (role_(i) == roleCode(Role::Position))
        acc_(i) = (ypNew_(i) - yp_(i) - h * (1.0 - gamma) * acc_(i)) / (h * gamma);
    tPrevious_ = t_;
    yPrev_ = y_;
    ypPrev_ = yp_;
    t_ += h;
    if (std::abs(t_ - tout) <= eps) t_ = tout;
    y_ = yNew_;
    yp_ = ypNew_;
    ++stats_.steps;
    jacobianCurrent_ = false;
    const double ratio = 0.9 * std::pow(1.0 / std::max(err, 1e-10), 1.0 / 3.0);
    if (ratio >= 1.5)
      h_ = h * std::min(ratio, 2.0);
    else if (ratio < 1.0)
      h_ = h * std::max(ratio, 0.5);
    else
      h_ = std::max(h, h_);
    h_ = std::min(h_, settings_.hmax);
    stats_.order = 2;
    stats_.stepSize = h;
    ++internalSteps;
    if (stalledMove_ && !returned && t_ < tout - eps) continue;  // not handed over yet
    if (internalSteps > 1) {
      // The caller sees one step from the entry state: interpolate over all of it.
      tPrevious_ = tEntry;
      yPrev_ = yEntry_;
      ypPrev_ = ypEntry_;
    }
    return true;
  }
  return true;
}

void HhtIntegrator::interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  const double h = t_ - tPrevious_;
  if (h <= 0.0) {
    y = y_;
    yp = yp_;
    return;
  }
  const double x = (s - tPrevious_) / h;
  const auto [h00, h10, h01, h11, d00, d10, d01, d11] = hermiteWeights(x);
  y.resize(y_.size());
  yp.resize(y_.size());
  for (int i = 0; i < y_.size(); ++i) {
    if (role_(i) == roleCode(Role::Algebraic)) {
      y(i) = (1 - x) * yPrev_(i) + x * y_(i);
      yp(i) = (1 - x) * ypPrev_(i) + x * yp_(i);
      continue;
    }
    y(i) = h00 * yPrev_(i) + h * h10 * ypPrev_(i) + h01 * y_(i) + h * h11 * yp_(i);
    yp(i) = (d00 * yPrev_(i) + d01 * y_(i)) / h + d10 * ypPrev_(i) + d11 * yp_(i);
  }
}

}  // namespace openmss::solvers
