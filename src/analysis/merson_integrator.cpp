#include "analysis/merson_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/analysis_context.hpp"  // formatNumber
#include "analysis/predicted_residual.hpp"
#include "mechanics/state_layout.hpp"
#include "solvers/hermite_weights.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

// ODE numbers per moving body: r(3) e(4) v(3) w(3), the body block of the layout without mu.
constexpr int kPerBody = 13;

// Step-size controller. The estimate h/30 (2 k1 - 9 k3 + 8 k4 - k5) behaves like h^5 on
// smooth problems, hence gains in units of 1/5. On long chains the step sits at the stability
// limit of the fastest mode, where the estimate rises steeply with h; the elementary controller
// h 0.9 err^-1/5 overshot there and 25-33 % of the attempts were rejected. Gustafsson's PI
// controller (Hairer-Wanner II, IV.2) h_new = h (theta/err_n)^kI (err_{n-1}/err_n)^kP with
// kI = 0.3/5, kP = 0.4/5 damps that oscillation: the proportional factor brakes as soon as the
// error rises from one step to the next, before a rejection. theta = 0.9^5 keeps the error the
// steps aim at where the elementary controller's equilibrium was (accuracy per step unchanged).
// Measured against other gains in docs/integrators.md ("MERSON", step size). After a rejection
// the elementary rule shrinks the step (at most to 0.9x, at least 0.2x); the shrink and growth
// bounds keep one odd estimate from moving the step by more than 5x.
constexpr double kSafety = 0.9;
constexpr double kExponent = 0.2;      // elementary control: after a rejection and the HINIT rule
constexpr double kTargetError = 0.59;  // 0.9^5: the elementary controller's equilibrium
constexpr double kIntegralGain = 0.06;
constexpr double kProportionalGain = 0.08;
constexpr double kMaxGrowth = 5.0;
constexpr double kMaxShrink = 0.2;
// The step after a rejection grows by at most this factor (Gustafsson): the rejected size is
// known to be too large, growing back to it invites the next rejection.
constexpr double kGrowthAfterRejection = 1.0;
// err_{n-1} is floored here so that one exceptionally small estimate (a step landing on an
// output time) does not throttle the next step.
constexpr double kPreviousErrorFloor = 1e-4;
// A step that would leave less than this share of itself before the output time is stretched
// to land on it (instead of a sliver of a step after it).
constexpr double kLandingStretch = 1.05;
// Position tolerance of a projection, as a share of the violation that triggered it: Newton
// on the constraints converges quadratically, so a tight target costs one iteration more at
// most, and the projected state is then clean for many steps.
constexpr double kProjectionTightening = 1e-2;

// Kutta-Merson's stability region reaches about -3.5 on the negative real axis and 3.46 on
// the imaginary axis. A step with h rho beyond kStiffStepRatio (70 % of that bound) is held by
// the stability of the fastest mode rather than by the motion it resolves.
constexpr double kStiffStepRatio = 2.5;
// Being held by stability is not yet stiffness in the sense that matters to the user: on long
// pendulum chains the fast modes carry real motion, the held steps are what that motion needs,
// and an implicit method (lower order, a Newton iteration per step) takes more, not fewer,
// steps (planar N=1000, ERROR=1e-4: GSTIFF 6002 steps, MERSON 1181). The warning asks for
// steps that accuracy alone would allow kAccuracyRoom times larger. That step is estimated
// without the fast mode's help: over a window of kWindowSteps accepted steps (span H), a cubic
// through the states at 0, 1/4, 3/4 and 1 of the window predicts the state at 1/2; the
// discrepancy d (in units of ERROR (1 + |x|), largest component) is the error of a cubic over
// span H and scales like H^4, so H d^(-1/4) is the span over which a cubic - the motion as a
// 3rd-4th order step sees it - stays within ERROR. States only, no slopes: at the stability
// limit the controller keeps the fast mode at an amplitude of about ERROR (it grows h until
// the mode's error estimate reaches the tolerance), which enters d as at most 2.7x that
// amplitude, while slopes would carry it amplified by H rho. Measured (docs/integrators.md,
// "MERSON", stiffness): k/m = 1e8 spring at rest, d ~ 0.4, ratio 81: warns; planar N=1000 at
// 1e-4, d ~ 100 whatever the window (real fast motion), ratio 14-22: no warning, and GSTIFF
// indeed takes 5x more steps there; at 1e-3 the ratio passes 30, and GSTIFF takes 126 steps
// against 1181.
constexpr double kAccuracyRoom = 30.0;
constexpr long kWindowSteps = 64;
// A window counts when at least kHeldShare of its steps are held by stability (the others:
// steps shortened to land on an output time or after a rejection), and the warning needs
// kStiffWindowsBeforeWarning such windows in a row (a start-up transient is not stiffness).
constexpr double kHeldShare = 0.75;
constexpr long kStiffWindowsBeforeWarning = 1;
// Accepted steps between estimates of the spectral radius. Power iterations (two evaluations
// each): kPowerIterations from a fixed start vector for the first estimate; later estimates
// start from the previous dominant vector, which the slowly changing Jacobian leaves nearly
// converged, and stop once the estimate moves by less than kPowerTolerance (at least
// kWarmIterations, at most kPowerIterations).
constexpr long kStepsBetweenEstimates = 200;
constexpr int kPowerIterations = 8;
constexpr int kWarmIterations = 2;
constexpr double kPowerTolerance = 0.02;

}  // namespace

MersonIntegrator::MersonIntegrator(const mechanics::MultibodySystem& system,
                                   const MersonSettings& settings)
    : system_(system), settings_(settings) {}

MersonIntegrator::~MersonIntegrator() = default;

void MersonIntegrator::gather(const Eigen::VectorXd& y, Eigen::VectorXd& x) const {
  const StateLayout& l = system_.layout();
  x.resize(kPerBody * l.bodies);
  for (int b = 0; b < l.bodies; ++b)
    x.segment<kPerBody>(kPerBody * b) = y.segment<kPerBody>(l.body(b));
}

void MersonIntegrator::scatter(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const StateLayout& l = system_.layout();
  for (int b = 0; b < l.bodies; ++b)
    y.segment<kPerBody>(l.body(b)) = x.segment<kPerBody>(kPerBody * b);
}

bool MersonIntegrator::derivative(double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
  scatter(x, yWork_);
  ++stats_.residualEvaluations;
  if (!dynamics_->evaluate(t, yWork_, ypWork_)) return false;
  gather(ypWork_, f);
  return true;
}

void MersonIntegrator::start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  t_ = tPrevious_ = t0;
  y_ = y0;
  yp_ = yp0;
  yWork_ = y0;
  ypWork_ = yp0;
  failure_ = {};
  stepsSinceEstimate_ = 0;
  previousError_ = 1.0;
  rejectedLast_ = false;
  // Statistics and warnings run on over restarts (SENSOR): they describe the whole run.
  stats_.order = 4;
  const double hmax = settings_.hmax > 0 ? settings_.hmax : std::numeric_limits<double>::infinity();
  h_ = std::min(settings_.hinit > 0 ? settings_.hinit : 1e-2 * std::pow(settings_.error, kExponent),
                hmax);
  if (!dynamics_) dynamics_ = std::make_unique<mechanics::IndexOneDynamics>(system_);
  if (const std::string why = dynamics_->unsupportedReason(); !why.empty()) {
    recordFailure("INTEGRATOR/MERSON integrates the index-1 equations of motion and " + why, 0.0,
                  nullptr);
    return;
  }
  // The consistent state from outside keeps its multipliers; the slopes come from our own
  // equations so that the first step and the interpolant use exactly what the stages use.
  if (!acceptState(t0, [&] {
        Eigen::VectorXd x;
        gather(y_, x);
        return x;
      }())) {
    recordFailure("the KKT matrix is singular at t = " + formatNumber("%.6E", t0), 0.0, nullptr);
    return;
  }
  xPrevious_ = x_;
  fPrevious_ = f_;
  estimateSpectralRadius();
  restartStiffnessWindow();
  stiffWindows_ = 0;
}

bool MersonIntegrator::setNextStepSize(double h) {
  if (!(h > 0)) return false;
  const double hmax = settings_.hmax > 0 ? settings_.hmax : std::numeric_limits<double>::infinity();
  h_ = std::min(h, hmax);
  return true;
}

bool MersonIntegrator::acceptState(double t, const Eigen::VectorXd& x) {
  scatter(x, y_);
  // Projection when the drift of the index-1 form (it keeps only the acceleration constraints)
  // has reached a share of ERROR; with a share of 0, after every step.
  const double limit = settings_.projectionShare * settings_.error;
  const bool project = limit <= 0.0 || dynamics_->positionViolation(t, y_) > limit ||
                       dynamics_->velocityViolation(t, y_) > limit;
  ++stats_.residualEvaluations;
  if (project) {
    const double tolerance =
        std::max(kProjectionTightening * std::max(limit, 1e-2 * settings_.error), 1e-13);
    // One call: the positions' projection, then one C and one factorisation at the projected
    // positions for both the velocities' projection and the next step's slopes
    // (docs/theory.md §9f).
    bool projected = false;
    const bool evaluated = dynamics_->projectAndEvaluate(t, y_, yp_, tolerance, &projected);
    if (projected) ++projections_;
    if (!evaluated) return false;
  } else if (!dynamics_->evaluate(t, y_, yp_)) {
    return false;
  }
  gather(y_, x_);
  gather(yp_, f_);
  return true;
}

bool MersonIntegrator::step(double tout) {
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  if (t_ >= tout - eps) return true;
  if (!failure_.reason.empty()) return false;
  const double hmax = settings_.hmax > 0 ? settings_.hmax : std::numeric_limits<double>::infinity();
  const double hmin = settings_.hmin > 0 ? settings_.hmin : 1e-12 * (1.0 + std::abs(t_));
  const Eigen::VectorXd& x = x_;
  const Eigen::VectorXd& k1 = f_;
  while (true) {
    const double remaining = tout - t_;
    double h = std::min(h_, hmax);
    const bool landing = h * kLandingStretch >= remaining;
    if (landing) h = remaining;
    const double tNew = landing ? tout : t_ + h;
    if (observingSteps())
      notifyStep({solvers::StepInfo::Event::Attempt, stats_.steps + 1, 4, t_, h, 0.0});
    // Kutta-Merson stages.
    bool ok = true;
    stage_ = x + (h / 3.0) * k1;
    ok = ok && derivative(t_ + h / 3.0, stage_, k2_);
    if (ok) {
      stage_ = x + (h / 6.0) * (k1 + k2_);
      ok = derivative(t_ + h / 3.0, stage_, k3_);
    }
    if (ok) {
      stage_ = x + (h / 8.0) * (k1 + 3.0 * k3_);
      ok = derivative(t_ + 0.5 * h, stage_, k4_);
    }
    if (ok) {
      stage_ = x + h * (0.5 * k1 - 1.5 * k3_ + 2.0 * k4_);
      ok = derivative(tNew, stage_, k5_);
    }
    double errorNorm = std::numeric_limits<double>::infinity();
    if (ok) {
      xNew_ = x + (h / 6.0) * (k1 + 4.0 * k4_ + k5_);
      errors_ = (h / 30.0) * (2.0 * k1 - 9.0 * k3_ + 8.0 * k4_ - k5_);
      errorNorm = 0.0;
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double weight =
            settings_.error * (1.0 + std::max(std::abs(x(i)), std::abs(xNew_(i))));
        errorNorm = std::max(errorNorm, std::abs(errors_(i)) / weight);
      }
      if (!std::isfinite(errorNorm)) errorNorm = std::numeric_limits<double>::infinity();
    }
    if (errorNorm <= 1.0) {
      tPrevious_ = t_;
      xPrevious_ = x_;
      fPrevious_ = f_;
      t_ = tNew;
      if (!acceptState(t_, xNew_)) {
        recordFailure("the KKT matrix is singular at t = " + formatNumber("%.6E", t_), h, nullptr);
        return false;
      }
      ++stats_.steps;
      stats_.stepSize = h;
      const double error = std::max(errorNorm, 1e-10);
      const double ideal =
          std::pow(kTargetError / error, kIntegralGain) *
          std::pow(std::max(previousError_, kPreviousErrorFloor) / error, kProportionalGain);
      const double growthLimit = rejectedLast_ ? kGrowthAfterRejection : kMaxGrowth;
      double next = h * std::clamp(ideal, kMaxShrink, growthLimit);
      previousError_ = errorNorm;
      rejectedLast_ = false;
      // A step shortened to land on tout does not shorten the next one beyond what its own
      // error allows.
      if (landing) next = std::max(next, std::min(h_, h * ideal));
      h_ = std::min(next, hmax);
      if (observingSteps())
        notifyStep({solvers::StepInfo::Event::Accepted, stats_.steps, 4, tPrevious_, h, errorNorm});
      watchStiffness(h);
      return true;
    }
    ++stats_.rejectedSteps;
    if (observingSteps() && ok)
      notifyStep(
          {solvers::StepInfo::Event::ErrorTestFailed, stats_.steps + 1, 4, t_, h, errorNorm});
    // After a rejection the step only shrinks; a failed evaluation (a stage state where the
    // KKT matrix is singular) quarters it.
    const double factor =
        ok ? std::clamp(kSafety * std::pow(errorNorm, -kExponent), kMaxShrink, kSafety) : 0.25;
    h_ = h * factor;
    rejectedLast_ = true;
    if (h_ < hmin) {
      if (!ok)
        recordFailure("the KKT matrix is singular at t = " + formatNumber("%.6E", t_) +
                          " (every step down to HMIN reaches a singular configuration)",
                      h, nullptr);
      else
        recordFailure(
            "the local error stays above ERROR with steps down to HMIN = " +
                formatNumber("%.3E", hmin),
            h, &errors_);
      return false;
    }
  }
}

void MersonIntegrator::interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  const double h = t_ - tPrevious_;
  if (s == t_ || h <= 0.0) {
    y = y_;
    yp = yp_;
    return;
  }
  const double th = (s - tPrevious_) / h;
  const solvers::HermiteWeights w = solvers::hermiteWeights(th);
  const Eigen::VectorXd x =
      w.h00 * xPrevious_ + (w.h10 * h) * fPrevious_ + w.h01 * x_ + (w.h11 * h) * f_;
  y = y_;
  scatter(x, y);
  ++stats_.residualEvaluations;
  if (!dynamics_->evaluate(s, y, yp)) {
    y = y_;
    yp = yp_;
  }
}

void MersonIntegrator::estimateSpectralRadius() {
  // Power iteration on J^2, J = df/dx by forward differences along the iterate: a complex pair
  // +-i omega (the undamped modes of a mechanism) has J^2 = -omega^2 on its plane, where plain
  // power iteration on J would rotate without converging; sqrt(|J^2 v| / |v|) -> rho.
  const Eigen::Index n = x_.size();
  if (n == 0) return;
  const bool warm = powerVector_.size() == n;
  if (!warm) {
    powerVector_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i)
      powerVector_(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i + 1));
  }
  Eigen::VectorXd& v = powerVector_;
  Eigen::VectorXd jv, jjv, xPerturbed, fPerturbed;
  const double scale = 1e-7 * (1.0 + x_.norm());
  auto apply = [&](const Eigen::VectorXd& direction, Eigen::VectorXd& out) {
    const double size = direction.norm();
    if (!(size > 0)) return false;
    const double delta = scale / size;
    xPerturbed = x_ + delta * direction;
    if (!derivative(t_, xPerturbed, fPerturbed)) return false;
    out = (fPerturbed - f_) / delta;
    return true;
  };
  double estimate = 0.0;
  for (int k = 0; k < kPowerIterations; ++k) {
    if (!apply(v, jv) || !apply(jv, jjv)) {  // keep the last estimate, restart cold next time
      powerVector_.resize(0);
      return;
    }
    const double growth = jjv.norm() / v.norm();
    const double previous = estimate;
    estimate = std::sqrt(growth);
    if (!(growth > 0)) break;
    v = jjv / jjv.norm();
    if (warm && k + 1 >= kWarmIterations &&
        std::abs(estimate - previous) <= kPowerTolerance * estimate)
      break;
  }
  ++spectralEstimates_;
  spectralRadius_ = estimate;
  stepsSinceEstimate_ = 0;
}

void MersonIntegrator::restartStiffnessWindow() {
  windowTimes_.assign(1, t_);
  windowStates_.assign(1, x_);
  windowSteps_ = 0;
  windowHeldSteps_ = 0;
  windowStepSum_ = 0.0;
}

double MersonIntegrator::windowAccuracyStep() const {
  // Cubic (Lagrange) through samples 0, 1, 3, 4 evaluated at the time of sample 2.
  const int nodes[4] = {0, 1, 3, 4};
  const double tm = windowTimes_[2];
  Eigen::VectorXd predicted = Eigen::VectorXd::Zero(windowStates_[2].size());
  for (int a : nodes) {
    double weight = 1.0;
    for (int b : nodes)
      if (b != a) weight *= (tm - windowTimes_[b]) / (windowTimes_[a] - windowTimes_[b]);
    predicted += weight * windowStates_[a];
  }
  const Eigen::VectorXd& actual = windowStates_[2];
  double d = 0.0;
  for (Eigen::Index i = 0; i < actual.size(); ++i)
    d = std::max(
        d, std::abs(actual(i) - predicted(i)) / (settings_.error * (1.0 + std::abs(actual(i)))));
  const double span = windowTimes_[4] - windowTimes_[0];
  const double hmax = settings_.hmax > 0 ? settings_.hmax : std::numeric_limits<double>::infinity();
  const double step = d > 0 ? span * std::pow(d, -0.25) : std::numeric_limits<double>::infinity();
  return std::min(step, hmax);
}

void MersonIntegrator::watchStiffness(double h) {
  if (++stepsSinceEstimate_ >= kStepsBetweenEstimates) estimateSpectralRadius();
  if (stiff_) return;
  ++windowSteps_;
  windowStepSum_ += h;
  if (h * spectralRadius_ >= kStiffStepRatio) ++windowHeldSteps_;
  if (windowSteps_ % (kWindowSteps / 4) != 0) return;
  windowTimes_.push_back(t_);
  windowStates_.push_back(x_);
  if (windowSteps_ < kWindowSteps) return;
  const double meanStep = windowStepSum_ / static_cast<double>(windowSteps_);
  accuracyStep_ = windowAccuracyStep();
  heldStep_ = meanStep;
  const bool held =
      kHeldShare * static_cast<double>(windowSteps_) <= static_cast<double>(windowHeldSteps_);
  restartStiffnessWindow();
  stiffWindows_ = held && accuracyStep_ >= kAccuracyRoom * meanStep ? stiffWindows_ + 1 : 0;
  if (stiffWindows_ < kStiffWindowsBeforeWarning) return;
  stiff_ = true;
  warnings_.push_back(
      "MERSON: the model is stiff. The equations of motion have an eigenvalue of magnitude " +
      formatNumber("%.3E", spectralRadius_) + " 1/s (time constant " +
      formatNumber("%.3E", 1.0 / spectralRadius_) +
      " s) whose stability holds the explicit steps to " +
      formatNumber("%.3E", meanStep) + " s (around t = " + formatNumber("%.6E", t_) +
      "), while the motion would allow steps of about " + formatNumber("%.3E", accuracyStep_) +
      " s for ERROR. INTEGRATOR/GSTIFF (or WSTIFF, DSTIFF) is not bound by this mode and can "
      "take the larger steps.");
}

void MersonIntegrator::recordFailure(const std::string& reason, double h,
                                     const Eigen::VectorXd* errors) {
  failure_ = {};
  failure_.time = t_;
  failure_.stepSize = h;
  failure_.reason = reason;
  notePredictedResidual(system_, t_, h, y_, yp_, failure_);
  const StateLayout& l = system_.layout();
  // The variable with the largest weighted local-error estimate of the last attempt.
  if (!errors || errors->size() != x_.size()) return;
  double worstWeighted = -1.0;
  for (Eigen::Index i = 0; i < errors->size(); ++i) {
    const double c = std::abs((*errors)(i)) / (1.0 + std::abs(x_(i)));
    if (!(c > worstWeighted)) continue;
    worstWeighted = c;
    const int b = static_cast<int>(i) / kPerBody;
    failure_.worstVariable = l.body(b) + static_cast<int>(i) % kPerBody;
    failure_.worstChange = std::abs((*errors)(i));
  }
}

}  // namespace openmss::analysis
