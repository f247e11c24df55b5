#include "solvers/bdf_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "solvers/bdf_polynomials.hpp"
#include "solvers/bdf_vector_passes.hpp"

namespace openmss::solvers {
namespace {

// Corrector convergence: the remaining change must be this fraction of the step's own local
// error estimate. Measured on the 100-link planar chain at ERROR = 1e-5 (tip error after 10 s
// against Simbody at 1e-10): 0.33 (DASSL's constant, relative to the tolerance) 3.3e-5,
// 1e-3 1.5e-6, 1e-4 4.7e-7, 1e-6 3.6e-7. The modified Newton iteration stops short of the
// solution in the same direction step after step, so its remainder adds up over the steps
// while the truncation errors largely do not (docs/integrators.md, "Corrector").
constexpr double kCorrectorShare = 1e-4;
// ... or this fraction of the tolerance (HMAX-limited steps, whose local error is tiny).
constexpr double kTightChange = 1e-9;
// A corrector that stops contracting with changes below this (in units of the tolerance) has
// reached the noise floor of the linear solves. Stalled changes are noise, not a same-sign
// remainder, so they do not add up like kCorrectorShare's. 1e-3 failed the 1000-link planar
// chain at t = 5.85 s (ERROR = 1e-5): the KKT system's conditioning leaves velocity noise near
// 0.01 of the tolerance there; 1e-1 runs it to 10 s with every test unchanged.
constexpr double kStalledChange = 1e-1;
// ... or whose every change is below kRoundOffUlps of the unknown's own round-off
// (bdf_error_measures.cpp, withinRoundOff).
// A solve accepted by a stall rule whose last change is above this share of the tolerance moved
// along the Newton matrix's near-null direction rather than stopping at round-off (HHT's
// threshold): the step is not handed over at once (step(), "Stepping across a singular
// instant" in docs/integrators.md).
constexpr double kStalledMove = 1e-3;
// A step across that the error test shortens to end within this share of the way to the stuck
// point from it ends this share past it instead (step()).
constexpr double kAcrossClearance = 0.25;
// A cj change beyond this share re-forms the Newton matrix.
constexpr double kCjDrift = 0.2;
// ... and so does a step that converged on an older matrix at a contraction rate above this
// (docs/integrators.md, "Cost per step"; Hairer and Wanner's RADAU5 re-forms its Jacobian when
// the rate exceeds 0.001). The relative convergence target (kCorrectorShare) asks for ~1e-5 of
// the correction, so the iteration count is set by the rate: on the 100-link chains a matrix
// kept over ~70 steps converged at 0.07 (4-6 iterations per step), a fresh one at 5e-6 (2).
// Only where the step's own error set the target: on HMAX-held steps kTightChange does, the
// changes are near round-off and their ratio says nothing of the matrix (the nine ADAMS joint
// cases, HMAX = 1e-5, re-formed it at a third of their 500000 steps, 1.7 -> 3.9 s of CPU).
// A refresh costs about 11 residual evaluations with their solves there. Measured (GSTIFF, 10 s,
// residuals + 11 x Jacobians; planar / spatial at 1e-5 and 1e-6): never 7637 / 8893 / 3929 /
// 5115; 0.01 7970 / 6200 (planar); 0.03 7206 / 6308 / 3462 / 3757; 0.05 6915 / 6081 / 3227 / 3708;
// 0.1 7211 / 6548 / 4009 / 3931. Tip errors at 0.05 (m): 1.6e-7 / 2.3e-7 / 9.9e-7 / 1.1e-7, never
// 7.2e-7 / 1.6e-7 / 9.9e-7 / 1.1e-7: the spread any change of the step sequence gives.
constexpr double kRefreshRate = 0.05;
// Singular configurations (docs/integrators.md, "Singular configurations"): where the
// constraint Jacobian loses rank (the flat position of a four-bar) the Newton matrix is
// singular in the multipliers along the null space of C^T. A modified Newton iteration on a
// stale matrix there converges in the differential unknowns while the residual stays: the old
// multiplier columns absorb the force-balance residual into multiplier changes that move
// nothing (EPRINT of A02 at ERROR = 1e-8: steps accepted with 0.5 N m left in a moment
// balance, then a corrector failure). An iteration declared converged on a stale matrix whose
// scaled residual shrank by less than kResidualStall, while its first change was above
// kResidualCheckFloor of the tolerance (the predictor was not already at round-off), is
// retried on a fresh matrix.
constexpr double kResidualStall = 0.5;
constexpr double kResidualCheckFloor = 1e-3;
// ... and on the fresh matrix, nearly singular itself, the iteration drives the residual to
// round-off and then keeps making changes of one size: the residual's round-off along the
// matrix's near-null directions (the N extra degrees of freedom of the flat four-bar row). A
// stalled iteration whose scaled residual has fallen below kResidualNoise of its first value
// has converged as far as the linear solves allow.
constexpr double kResidualNoise = 1e-6;
// ... or whose unscaled residual has (kRawResidualNoise): the scaled one is dominated by the
// constraint rows times cj^2, which at the steps of ~1e-5 s taken through a flat passage keep
// the positions' round-off along the extra degrees of freedom above kResidualNoise while every
// equation is solved to round-off (A02, N = 40, GSTIFF at ERROR = 1e-8 with the I3 velocities in
// the error test, docs/integrators.md: failed at t = 4.65 s without it). Was 1e-6: solves cut
// 2e5- to 8e5-fold failed ("Crossing a flat passage at tight tolerances", there).
constexpr double kRawResidualNoise = 1e-5;
// An iteration accepted by any of these stall rules stops with the noise of its last changes
// in the solution: at A02's flat passages the positions along the extra degrees of freedom are
// left up to 32 tolerances apart from one iteration to the next (SI2 GSTIFF, N = 40, ERROR =
// 1e-8; up to 36 x kRoundOffUlps), and the error test, corrector minus predictor, sees that
// noise as local error: it rejected every step down to h = 3.2e-6 s, and below that the
// corrector failed (t = 6.6187 s; docs/integrators.md, "The noise of a stalled solve in the
// BDF's error test", under "Singular configurations"). So the error test of a solve
// accepted at noise does not ask for less than the noise: each differential unknown's weight
// becomes 1 / (ERROR (1 + |y|) + noise), the noise being the sum of the changes after the
// first iteration (the first is the correction proper) taken at the largest weighted level of
// its role (the noise lies along the matrix's near-null directions, which mix the extra
// degrees of freedom, so which unknown shows it is chance; DSTIFF's rule, docs/integrators.md,
// "DSTIFF and ABAM"). A solve that converges is unchanged.
// The I3 velocity test (docs/integrators.md, "The I3 velocity test"). An index-3 velocity is
// not under the displacement error test, yet its local error becomes an energy, hence phase,
// error of undamped motion (A02, N = 40, GSTIFF at ERROR = 1e-6: 1.6e-2 m after 20 s). Its
// predictor-corrector estimate is weighed as the displacement it makes over kVelocityTestSteps
// steps, kVelocityTestSteps h / (ERROR (1 + |v_n|)): the velocities are the index-2 variables
// of the index-3 DAE, whose error estimates are scaled by h as in Hairer and Wanner's RADAU5,
// and the h keeps the round-off of velocities recovered through cj (like 1/h) from failing the
// test at tiny steps. The test accepts or rejects a step and bounds the next step at the order
// chosen, but takes no part in choosing the order: as an order-selection estimate it made the
// coupled driveline (CouplerTurns) and the test-set pendulum 8-9x less accurate (a velocity's
// higher divided differences favour low orders whose displacement error is larger). Measured
// on A02 N = 40 at ERROR = 1e-6 (B0 error at 20 s, GSTIFF / WSTIFF): without the test
// 1.6e-2 / 5.5e-3 m; 1 step 1.8e-3 / 2.1e-3; 2 steps 2.8e-4 / 2.7e-3; 4 steps 3.1e-4 / 9.4e-4;
// 8 steps 1.3e-5 / 6.0e-3 m (not monotonic in the factor: the estimate is noisy, see there).
// Calibrated with the exact-history error coefficient, which the velocity estimate keeps
// (attemptStep, exactHistoryRatio): with DASSL's on it A02's B0 errors grew 1.46x over 31 runs.
constexpr double kVelocityTestSteps = 2.0;

using bdf::bdfWeights;
using bdf::combine;
using bdf::combineFromZero;
using bdf::lagrangeAt;

}  // namespace

BdfIntegrator::BdfIntegrator(DaeProblem& problem, const MultistepSettings& settings)
    : problem_(problem), settings_(settings) {
  settings_.kmax = std::clamp(settings_.kmax, 1, 6);
  if (settings_.pivotOrder != PivotOrder::Default)
    sparseSolver_.setKluOptions(KluLinearSolver::optionsFor(settings_.pivotOrder));
}

void BdfIntegrator::start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  const int n = problem_.size();
  t_ = t0;
  y_ = y0;
  yp_ = yp0;
  ts_.assign(1, t0);
  ys_.assign(1, y0);
  diagonal_.assign(1, y0);
  previousDiagonal_.clear();
  k_ = 1;
  stepsAtOrder_ = 0;
  lowOrderStep_ = 0.0;
  highOrderBarredUntil_ = 0;
  stabilityBar_ = 0;
  stabilityLimitDetections_ = 0;
  stepsSinceRoughSolve_ = std::numeric_limits<long>::max() / 2;
  lastSolveAtNoise_ = false;
  stalledMove_ = false;
  handedFrom_ = t0;
  heldLow_.clear();
  heldOwn_.clear();
  h_ = settings_.hinit > 0 ? settings_.hinit : 1e-3;
  h_ = std::min(h_, settings_.hmax);
  for (auto* v : {&yNew_, &ypNew_, &yPred_, &base_, &g_, &dy_, &predictorDiff_, &errorWeight_,
                  &correctorWeight_, &errorMask_, &differentialMask_, &velocityMask_,
                  &positionMask_, &roundOffFloor_, &velocityTestMask_, &velocityWeight_})
    v->resize(n);
  rowExponent_.resize(n);
  unknownExponent_.resize(n);
  for (int i = 0; i < n; ++i) {
    const bool controlled = problem_.errorControlled(i), differential = problem_.differential(i);
    errorMask_(i) = controlled ? 1.0 : 0.0;
    differentialMask_(i) = differential ? 1.0 : 0.0;
    velocityMask_(i) = problem_.role(i) == DaeProblem::Role::Velocity ? 1.0 : 0.0;
    positionMask_(i) = problem_.role(i) == DaeProblem::Role::Position ? 1.0 : 0.0;
    // Velocities left out of the displacement error test (I3), tested on their own.
    velocityTestMask_(i) = velocityMask_(i) != 0.0 && !controlled ? 1.0 : 0.0;
    rowExponent_(i) = problem_.rowScaleExponent(i);
    unknownExponent_(i) = problem_.unknownScaleExponent(i);
  }
  rowScale_ = Eigen::VectorXd::Ones(n);
  colScale_ = Eigen::VectorXd::Ones(n);
  sparse_ = problem_.sparse() && n >= kSparseThreshold;
  if (sparse_) {
    sparseJac_ = *problem_.pattern();
    // No analysis here: the first factor() analyses the pattern it is given, and a restart
    // (SENSOR/RESTART, a CONTACT onset) on an unchanged pattern keeps the analysis and the
    // factors, so its first matrix is a refactorisation on the last pivots (guarded by the
    // condition estimate) instead of a full factorisation (a pile restarts at nearly every
    // step: 7-12 % of its CPU at N = 64 and 100, docs/performance.md, "Contact pile").
    solver_ = &sparseSolver_;
  } else {
    solver_ = &dense_;
  }
  jacobianCurrent_ = false;
  haveJacobian_ = false;
  refreshNext_ = false;
  consecutiveErrorFailures_ = 0;
  velocityTested_ = velocityTestMask_.sum() > 0.0;
  controlledVelocities_ = (velocityMask_.array() * errorMask_.array()).sum() > 0.0;
  velocityError_ = 0.0;
  velocityRejected_ = false;
}

void BdfIntegrator::restart(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  // The factors were formed with the row and column scaling of their cj (refresh()), which
  // start() resets: kept with them. The first attempt from here uses them like any older
  // matrix: the cj drift test, a corrector failure on attempt 0 and the slow-convergence
  // refresh form a new one when it no longer serves.
  const bool keep = haveJacobian_ && y0.size() == y_.size();
  Eigen::VectorXd rowScale = rowScale_, colScale = colScale_;
  const double cj = cjJacobian_;
  start(t0, y0, yp0);
  if (!keep) return;
  rowScale_ = std::move(rowScale);
  colScale_ = std::move(colScale);
  cjJacobian_ = cj;
  haveJacobian_ = true;
}

// Over ~150 lines: kept whole in the pure-move pass of issue 23; its phases share many locals,
// so a split needs a state struct (left for a change that can be checked on its own).
bool BdfIntegrator::attemptStep(double h, int k, bool* newtonFailed, double* errorNorm) {
  *newtonFailed = false;
  velocityRejected_ = false;
  stalledMove_ = false;
  const double tNew = t_ + h;
  const int nh = static_cast<int>(ts_.size());
  double nodes[8] = {}, w[8], dw[8], a[8];

  // Predictor: polynomial through the last k+1 solutions, or a Taylor step at start-up.
  double errorRatio;  // local error / (corrector - predictor), exact for variable steps
  // The error of a step from an exact history (the residual over cj), 1 + 1/2 + ... + 1/k below
  // errorRatio at constant steps: the coefficient before DASSL's, kept where it was calibrated,
  // the corrector's target (kCorrectorShare) and the I3 velocity test (kVelocityTestSteps;
  // docs/integrators.md, "Local error audit on A02").
  double exactHistoryRatio;
  if (nh >= k + 1) {
    for (int j = 0; j <= k; ++j) nodes[j] = ts_[j];
    lagrangeAt(nodes, k + 1, tNew, w, dw);
    // yPred_ = 0 + w_0 y_0 + ... + w_k y_k in one pass (bdf_vector_passes.hpp).
    const double* src[8];
    for (int j = 0; j <= k; ++j) src[j] = ys_[static_cast<size_t>(j)].data();
    combineFromZero(yPred_.data(), src, w, k + 1, yPred_.size());
  } else {
    yPred_ = y_ + h * yp_;
  }
  // Corrector: BDF of order k through tNew and the last k solutions.
  nodes[0] = tNew;
  for (int j = 1; j <= k; ++j) nodes[j] = ts_[j - 1];
  // The corrector's history y_n+1-j, j = 1..k: past solutions, or GSTIFF's re-sampled ones.
  const double* history[8];
  for (int j = 1; j <= k; ++j) history[j - 1] = ys_[static_cast<size_t>(j - 1)].data();
  if (settings_.fixedCoefficients && nh >= 2) {
    // GSTIFF: the past solutions re-sampled at t_n - (j-1) h on the polynomial through the
    // last min(k+1, nh) solutions (the predictor's), so the corrector has constant-step
    // coefficients whatever the step history.
    const int npts = std::min(k + 1, nh);
    double hist[8] = {}, wv[8], dwv[8];
    const double* past[8];
    for (int j = 0; j < npts; ++j) {
      hist[j] = ts_[j];
      past[j] = ys_[static_cast<size_t>(j)].data();
    }
    equallySpaced_.resize(static_cast<size_t>(k));
    for (int j = 1; j <= k; ++j) {
      nodes[j] = t_ - (j - 1) * h;
      const double* hit = std::find(hist, hist + npts, nodes[j]);
      if (hit != hist + npts) {
        history[j - 1] = past[hit - hist];  // read in place, not copied
        continue;
      }
      lagrangeAt(hist, npts, nodes[j], wv, dwv);
      Eigen::VectorXd& v = equallySpaced_[static_cast<size_t>(j - 1)];
      v.resize(y_.size());
      combine(v.data(), past, wv, npts, v.size());  // v = wv_0 y_0 + wv_1 y_1 + ...
      history[j - 1] = v.data();
    }
  }
  bdfWeights(nodes, k + 1, a);
  const double cj = a[0];
  combineFromZero(base_.data(), history, a + 1, k, base_.size());  // 0 + a_1 h_1 + ... + a_k h_k
  if (nh >= k + 1) {
    // DASSL's variable-step error coefficient (Brenan, Campbell and Petzold; docs/integrators.md,
    // "Local error audit on A02"), with psi_i = t_n+1 - t_n+1-i and alpha_i = h / psi_i: the
    // error a step adds to the solution, h times the residual of the exact solution in the
    // corrector, is alpha_k+1 (corrector - predictor) for the variable-coefficient BDF (WSTIFF);
    // GSTIFF's corrector through the predictor polynomial re-sampled at t_n+1 - j h is DASSL's
    // fixed-leading-coefficient form, which after a step change adds |alpha_s - alpha_0|,
    // alpha_s = -(1 + 1/2 + ... + 1/k), alpha_0 = -(alpha_1 + ... + alpha_k). The residual over
    // cj alone (the error of a step from an exact history) read 1 + 1/2 + ... + 1/k times low at
    // constant steps (A02 N = 40 at ERROR = 1e-4: true / estimated median 1.8-2.0).
    double num = 1.0, den = cj;
    for (int j = 1; j <= k; ++j) num *= tNew - nodes[j];
    for (int j = 0; j <= k; ++j) den *= tNew - ts_[j];
    exactHistoryRatio = std::abs(num / den);
    const double alphaNext = h / (tNew - ts_[static_cast<size_t>(k)]);
    errorRatio = alphaNext;
    if (settings_.fixedCoefficients) {
      double alphaS = 0.0, alpha0 = 0.0;
      for (int i = 1; i <= k; ++i) {
        alphaS -= 1.0 / i;
        alpha0 -= h / (tNew - ts_[static_cast<size_t>(i - 1)]);
      }
      errorRatio = std::max(std::abs(alphaNext + alphaS - alpha0), alphaNext);
    }
  } else {
    errorRatio = 1.0;  // Taylor predictor vs backward Euler: equal and opposite h^2/2 y''
    exactHistoryRatio = errorRatio;
  }

  setWeights();

  // Modified Newton. A Jacobian is kept while cj stays within kCjDrift of the one it was
  // formed with and the iteration converges.
  auto refresh = [&]() {
    ypNew_ = cj * yPred_ + base_;  // (overwritten by the iteration before its next use)
    ++stats_.jacobianEvaluations;
    for (int i = 0; i < rowScale_.size(); ++i) {
      rowScale_(i) = std::pow(cj, rowExponent_(i));
      colScale_(i) = std::pow(cj, unknownExponent_(i));
    }
    if (sparse_) {
      problem_.newtonMatrixSparse(tNew, yPred_, ypNew_, cj, sparseJac_);
      for (int c = 0; c < sparseJac_.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator e(sparseJac_, c); e; ++e)
          e.valueRef() = rowScale_(e.row()) * e.value() * colScale_(c);
      // Exact zeros left out of the factorisation where they persist (nonzero_pattern.hpp).
      sparseSolver_.factor(problem_.zerosPersist() ? nonzero_.select(sparseJac_) : sparseJac_);
      stats_.sparseAnalyses = sparseSolver_.analyses();
      stats_.fullFactorizations = sparseSolver_.fullFactorizations();
      stats_.refactorizations = sparseSolver_.refactorizations();
    } else {
      problem_.newtonMatrix(tNew, yPred_, ypNew_, cj, jac_);
      jac_.array().colwise() *= rowScale_.array();
      jac_.array().rowwise() *= colScale_.transpose().array();
      dense_.factor(jac_);
    }
    cjJacobian_ = cj;
    haveJacobian_ = true;
    refreshNext_ = false;
    jacobianCurrent_ = true;
  };
  if (!haveJacobian_ || refreshNext_ || std::abs(cj / cjJacobian_ - 1.0) > kCjDrift) refresh();

  // ADAPTIVITY / h added to the corrector's tolerance (ADAMS's definition; docs/integrators.md,
  // "ADAPTIVITY"), in the weighted units of the convergence test below (ERROR (1 + |y|)).
  const double loosened = settings_.adaptivity / (h * settings_.error);
  for (int attempt = 0; attempt < 2; ++attempt) {
    yNew_ = yPred_;
    // The rate is measured within the step: a rate carried over from the last step would let
    // a step stop after one iteration, which cost the 100-link chain 10x in tip error.
    double previous = 0.0, rate = 0.0;
    double firstResidual = 0.0, lastResidual = 0.0, firstSize = 0.0;
    double firstRaw = 0.0;               // the same, unscaled (see kRawResidualNoise)
    laterChanges_.resize(yNew_.size());  // set at the second iteration (applyCorrectorChange)
    bool atNoise = false;  // accepted by a stall rule (widenForNoise)
    bool converged = false;
    bool onRelativeTarget = false;  // converged on the step's own error, not kTightChange
    for (int it = 0; it < settings_.maxit; ++it) {
      if (settings_.patternGiven && (it == 0 ? !jacobianCurrent_ : settings_.pattern[it % 10])) {
        // PATTERN: re-form at this iterate (refresh() linearises at yPred_).
        std::swap(yPred_, yNew_);
        refresh();
        std::swap(yPred_, yNew_);
      }
      // y' at the iterate: here at the first iteration, by the last update at the others.
      if (it == 0) ypNew_ = cj * yNew_ + base_;
      problem_.residual(tNew, yNew_, ypNew_, g_);
      ++stats_.residualEvaluations;
      // The unscaled residual's size: at the first iteration here, at later ones only where
      // the stall rule below reads it (g_ is unchanged until then).
      if (it == 0) firstRaw = g_.cwiseAbs().maxCoeff<Eigen::PropagateNaN>();
      dy_ = rowScale_.cwiseProduct(g_);
      lastResidual = dy_.cwiseAbs().maxCoeff();
      if (it == 0) firstResidual = lastResidual;
      solver_->solve(dy_);
      // One vectorised pass over the unknowns after the solve: unscale the change, rescale it
      // when the Jacobian was formed at another cj (it approximates cj dG/dy'; DASSL's factor),
      // apply it, form y' = cj y + base there (the next iteration's and, once converged, the
      // step's: PATTERN's refresh() forms the same), and add its size to laterChanges_ after
      // the first iteration (widenForNoise). Then the weighted maximum norm of the change
      // (size; a NaN anywhere makes it NaN); the distance from the predictor's only where the
      // convergence target asks for it (below). The same operations on every entry as
      // separate vector passes, so the same bits (docs/performance.md, "GSTIFF's cost per
      // step, cheaper").
      bdf::CorrectorUpdate update;
      update.cj = cj;
      update.rescale = cjJacobian_ != cj;
      if (update.rescale) update.cjFactor = 2.0 / (1.0 + cj / cjJacobian_);
      using Later = bdf::CorrectorUpdate::Later;
      update.later = it == 0 ? Later::None : it == 1 ? Later::Assign : Later::Add;
      bdf::applyCorrectorChange(update, dy_.data(), colScale_.data(), yNew_.data(), base_.data(),
                                ypNew_.data(), laterChanges_.data(), dy_.size());
      const double size =
          (dy_.array() * correctorWeight_.array()).abs().maxCoeff<Eigen::PropagateNaN>();
      if (!std::isfinite(size)) break;  // a NaN or infinite residual: this attempt failed
      // The worst residual and change are for observers (EPRINT) and for the failure report
      // (noted when an attempt fails, below); not computed per iteration otherwise.
      if (observingIterations()) {
        noteWorst(g_, dy_);
        notifyIteration(
            {tNew, h, k, it + 1, lastWorstEq_, lastWorstRes_, lastWorstVar_, lastWorstChange_});
      }
      if (it > 0) rate = size / std::max(previous, 1e-300);
      if (it == 0) firstSize = size;
      previous = size;
      // Converged when the remaining change, about rate / (1 - rate) times the last one, is
      // small next to this step's own local error (the predictor-corrector difference the
      // error test weighs) or below kTightChange of the tolerance. Relative to the step's
      // error, not to ERROR: HMAX-limited runs take steps whose local error is far below
      // ERROR, hundreds of thousands of them, and a corrector remainder (same sign step after
      // step) would add up over all of them; there the absolute bound governs, as before.
      if (size <= kTightChange + loosened) {
        converged = true;
        break;
      }
      if (it > 0 && rate < 0.9) {
        // Largest |y - y_pred| w. Every entry is finite here: size is, so every change is (a
        // non-finite change times its weight, zero included, is NaN or infinite), and the
        // predictor and the weights are. So the plain maximum is exact.
        const double fromPredictor =
            ((yNew_ - yPred_).array() * correctorWeight_.array()).abs().maxCoeff();
        const double relative = kCorrectorShare * exactHistoryRatio * fromPredictor;
        if (rate / (1.0 - rate) * size <= std::max(kTightChange, relative) + loosened) {
          converged = true;
          onRelativeTarget = relative > kTightChange;
          break;
        }
      }
      // Stopped contracting far below the tolerance: round-off (index-3 velocities carry it
      // amplified by cj), converged.
      if (it > 0 && rate >= 0.9 &&
          (size <= kStalledChange || withinRoundOff(cj) ||
           lastResidual <= kResidualNoise * firstResidual ||
           g_.cwiseAbs().maxCoeff<Eigen::PropagateNaN>() <= kRawResidualNoise * firstRaw)) {
        converged = true;
        atNoise = true;
        break;
      }
      if (it > 1 && rate > 0.9) break;  // diverging
    }
    if (converged && !jacobianCurrent_ && firstSize > kResidualCheckFloor &&
        lastResidual > kResidualStall * firstResidual)
      converged = false;  // stale matrix, residual left standing: retry on a fresh one
    if (converged && onRelativeTarget && !jacobianCurrent_ && rate > kRefreshRate)
      refreshNext_ = true;
    if (converged) {
      if (atNoise) widenForNoise();
      lastSolveAtNoise_ = atNoise;
      stalledMove_ = atNoise && previous > kStalledMove;
      break;
    }
    if (jacobianCurrent_ || attempt == 1) {
      noteWorst(g_, dy_);
      *newtonFailed = true;
      return false;
    }
    refresh();
  }
  // ypNew_ = cj yNew_ + base_ from the converged iteration's update.
  predictorDiff_ = yNew_ - yPred_;
  if (controlledVelocities_) {
    // SI2: its velocities are in this test; their estimates keep the scale they were
    // calibrated on, as the I3 velocity test's (exactHistoryRatio; with DASSL's coefficient on
    // them SI2 GSTIFF at 1e-8 stopped at A02's first flat passage, docs/integrators.md, "Local
    // error audit on A02"). One expression per part: no temporary vector.
    const double others =
        (predictorDiff_.array() * errorWeight_.array() * (1.0 - velocityMask_.array()))
            .abs()
            .maxCoeff<Eigen::PropagateNaN>();
    const double velocities =
        (predictorDiff_.array() * errorWeight_.array() * velocityMask_.array())
            .abs()
            .maxCoeff<Eigen::PropagateNaN>();
    *errorNorm = std::max(errorRatio * others, exactHistoryRatio * velocities);
    if (std::isnan(others) || std::isnan(velocities))
      *errorNorm = std::numeric_limits<double>::quiet_NaN();
  } else {
    *errorNorm = errorRatio * weightedNorm(predictorDiff_, errorWeight_);
  }
  if (!std::isfinite(*errorNorm)) {
    noteWorst(g_, dy_);
    *newtonFailed = true;
    return false;
  }
  velocityError_ = 0.0;
  if (velocityTested_) {
    // kVelocityTestSteps h / (ERROR (1 + |v_n|)) on the I3 velocities only.
    velocityWeight_ = ((kVelocityTestSteps * h) / (settings_.error * (1.0 + y_.array().abs())) *
                       velocityTestMask_.array())
                          .matrix();
    velocityError_ = exactHistoryRatio * weightedNorm(predictorDiff_, velocityWeight_);
    if (!std::isfinite(velocityError_)) {
      noteWorst(g_, dy_);
      *newtonFailed = true;
      return false;
    }
  }
  velocityRejected_ = *errorNorm <= 1.0 && velocityError_ > 1.0;
  if (*errorNorm > 1.0 || velocityRejected_) noteWorst(g_, dy_);  // for the failure report
  return *errorNorm <= 1.0 && !velocityRejected_;
}

// Over ~150 lines: kept whole in the pure-move pass of issue 23; its phases share many locals,
// so a split needs a state struct (left for a change that can be checked on its own).
bool BdfIntegrator::step(double tout) {
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  const double hmin =
      settings_.hmin > 0 ? settings_.hmin : std::max(1e-14, 1e-10 * std::min(settings_.hmax, 1e3));
  // Attempts until one step is accepted (or the step size falls below HMIN). Stepping across a
  // singular instant (docs/integrators.md, as HhtIntegrator::step does): a step accepted on a
  // stalled move (stalledMove_) is not handed to the caller; the next step is taken at once.
  // When no step can leave such a state, the method returns, once per call, to the state it
  // started from (which the caller has seen; its history in entry_) and tries a step twice as
  // long as the way to the stuck point, across it.
  const double tEntry = t_;
  bool returned = false;  // back at the entry state once already
  bool saved = false;     // entry_ holds the entry state
  double tStuck = 0.0;    // where no step could leave
  bool cleared = false;   // the step across was lengthened past tStuck
  bool exact = false;     // take h_ as it is (up to the output time)
  while (t_ < tout - eps) {
    double h = std::min(h_, settings_.hmax);
    // Land exactly on the output time; avoid leaving a sliver for the next step (not for the
    // step across, whose end is chosen).
    if (t_ + h >= tout - eps)
      h = tout - t_;
    else if (t_ + 2.0 * h > tout && !exact)
      h = 0.5 * (tout - t_);
    exact = false;
    bool newtonFailed = false;
    double err = 0.0;
    using Event = BdfStepInfo::Event;
    notifyStep({Event::Attempt, stats_.steps + 1, k_, t_, h, 0.0});
    if (!attemptStep(h, k_, &newtonFailed, &err)) {
      notifyStep({newtonFailed ? Event::CorrectorFailed : Event::ErrorTestFailed, stats_.steps + 1,
                  k_, t_, h, velocityRejected_ ? velocityError_ : err});
      if (newtonFailed) {
        ++stats_.newtonFailures;
        stepsSinceRoughSolve_ = 0;
        h_ = 0.25 * h;
        jacobianCurrent_ = false;
      } else {
        ++stats_.rejectedSteps;
        if (velocityRejected_) {
          // The I3 velocity test alone failed: a shorter step at the same order (the order is
          // chosen on displacements, kVelocityTestSteps).
          h_ = h * std::clamp(0.9 * std::pow(1.0 / velocityError_, 1.0 / (k_ + 1)), 0.2, 0.9);
        } else {
          rejectOnDisplacement(h, err);
        }
        // Across: a shorter step that would end near the stuck point ends past it instead, by
        // kAcrossClearance of the way there (once).
        if (returned && !cleared && t_ == tEntry &&
            std::abs(t_ + h_ - tStuck) < kAcrossClearance * (tStuck - tEntry)) {
          h_ = (1.0 + kAcrossClearance) * (tStuck - tEntry);
          cleared = true;
          exact = true;
        }
        // The matrix was formed for the rejected attempt (its c_j and predictor): for the
        // shorter step it is an older matrix (docs/integrators.md, "Crossing a flat passage at
        // tight tolerances").
        jacobianCurrent_ = false;
      }
      if (h_ < hmin && saved && !returned && t_ > tEntry) {
        const double across = 2.0 * (t_ - tEntry);
        tStuck = t_;
        exact = true;
        restoreEntry();
        h_ = std::min(across, settings_.hmax);
        returned = true;
        refreshNext_ = true;
        consecutiveErrorFailures_ = 0;
        ++stats_.rejectedSteps;
        continue;
      }
      if (h_ < hmin) {
        failure_.time = t_;
        failure_.stepSize = h_;
        failure_.reason = newtonFailed ? "the corrector did not converge"
                                       : "the local error stays above the tolerance";
        failure_.worstEquation = lastWorstEq_;
        failure_.worstResidual = lastWorstRes_;
        failure_.worstVariable = lastWorstVar_;
        failure_.worstChange = lastWorstChange_;
        return false;
      }
      continue;
    }
    // Accept.
    if (stalledMove_ && !saved && t_ == tEntry) {  // the entry state may be needed
      saveEntry();
      saved = true;
    }
    consecutiveErrorFailures_ = 0;
    notifyStep({Event::Accepted, stats_.steps + 1, k_, t_, h, err});
    lastStepOrder_ = k_;
    t_ += h;
    if (std::abs(t_ - tout) <= eps) t_ = tout;
    y_ = yNew_;
    yp_ = ypNew_;
    ts_.push_front(t_);
    // The oldest solution's storage is reused for the newest once the history is full.
    if (static_cast<int>(ys_.size()) >= settings_.kmax + 3) {
      Eigen::VectorXd reused = std::move(ys_.back());
      ys_.pop_back();
      reused = y_;
      ys_.push_front(std::move(reused));
    } else {
      ys_.push_front(y_);
    }
    while (static_cast<int>(ts_.size()) > settings_.kmax + 3) {
      ts_.pop_back();
      ys_.pop_back();
    }
    updateDivided();
    ++stats_.steps;
    ++stepsAtOrder_;
    stepsSinceRoughSolve_ = lastSolveAtNoise_ ? 0 : stepsSinceRoughSolve_ + 1;
    jacobianCurrent_ = false;

    selectNextStep(h, err);
    if (stalledMove_ && !returned && t_ < tout - eps) continue;  // not handed over yet
    handedFrom_ = tEntry;
    return true;
  }
  return true;
}

}  // namespace openmss::solvers
