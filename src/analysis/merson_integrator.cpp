#include "analysis/merson_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "mechanics/state_layout.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

// ODE numbers per moving body: r(3) e(4) v(3) w(3), the body block of the layout without mu.
constexpr int kPerBody = 13;

// Step-size controller. The estimate h/30 (2 k1 - 9 k3 + 8 k4 - k5) behaves like h^5 on
// smooth problems, hence the exponent 1/5 (the prototype that matched Simbody's RK-Merson step
// counts used it); 0.9 keeps the next step's predicted error below the tolerance; growth and
// shrink bounds keep one odd estimate from moving the step by more than 5x.
constexpr double kSafety = 0.9;
constexpr double kExponent = 0.2;
constexpr double kMaxGrowth = 5.0;
constexpr double kMaxShrink = 0.2;
// A step that would leave less than this share of itself before the output time is stretched
// to land on it (instead of a sliver of a step after it).
constexpr double kLandingStretch = 1.05;
// Position tolerance of a projection, as a share of the violation that triggered it: Newton
// on the constraints converges quadratically, so a tight target costs one iteration more at
// most, and the projected state is then clean for many steps.
constexpr double kProjectionTightening = 1e-2;

// Kutta-Merson's stability region reaches about -3.5 on the negative real axis and 3.46 on
// the imaginary axis. Steps with h rho beyond kStiffStepRatio (70 % of that bound) are held by
// the stability of the fastest mode, not by accuracy: a mode that moves needs h |lambda| ~< 1
// for a 4th-order method at any useful ERROR (its local error at h |lambda| = 2.5 is of the
// order of the mode itself), so such a mode is one the method must not follow.
constexpr double kStiffStepRatio = 2.5;
// Accepted steps beyond that ratio before the warning (a start-up transient is not stiffness).
constexpr long kStiffStepsBeforeWarning = 20;
// Accepted steps between estimates of the spectral radius, and power iterations per estimate
// (two evaluations each).
constexpr long kStepsBetweenEstimates = 200;
constexpr int kPowerIterations = 8;

std::string format(const char* pattern, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, value);
  return buf;
}

}  // namespace

MersonIntegrator::MersonIntegrator(const mechanics::MultibodySystem& system,
                                   const MersonSettings& settings)
    : system_(system), settings_(settings) {}

MersonIntegrator::~MersonIntegrator() = default;

void MersonIntegrator::gather(const Eigen::VectorXd& y, Eigen::VectorXd& x) const {
  const StateLayout& l = system_.layout();
  x.resize(kPerBody * l.bodies);
  for (int b = 0; b < l.bodies; ++b) x.segment<kPerBody>(kPerBody * b) = y.segment<kPerBody>(l.body(b));
}

void MersonIntegrator::scatter(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const StateLayout& l = system_.layout();
  for (int b = 0; b < l.bodies; ++b) y.segment<kPerBody>(l.body(b)) = x.segment<kPerBody>(kPerBody * b);
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
  stiffSteps_ = 0;
  stepsSinceEstimate_ = 0;
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
    recordFailure("the KKT matrix is singular at t = " + format("%.6E", t0), 0.0, nullptr);
    return;
  }
  xPrevious_ = x_;
  fPrevious_ = f_;
  estimateSpectralRadius();
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
  const bool project =
      limit <= 0.0 || dynamics_->positionViolation(t, y_) > limit ||
      dynamics_->velocityViolation(t, y_) > limit;
  if (project) {
    const double tolerance =
        std::max(kProjectionTightening * std::max(limit, 1e-2 * settings_.error), 1e-13);
    if (dynamics_->project(t, y_, tolerance)) ++projections_;
  }
  ++stats_.residualEvaluations;
  if (!dynamics_->evaluate(t, y_, yp_)) return false;
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
        recordFailure("the KKT matrix is singular at t = " + format("%.6E", t_), h, nullptr);
        return false;
      }
      ++stats_.steps;
      stats_.stepSize = h;
      const double ideal = kSafety * std::pow(std::max(errorNorm, 1e-10), -kExponent);
      double next = h * std::clamp(ideal, kMaxShrink, kMaxGrowth);
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
      notifyStep({solvers::StepInfo::Event::ErrorTestFailed, stats_.steps + 1, 4, t_, h, errorNorm});
    // After a rejection the step only shrinks; a failed evaluation (a stage state where the
    // KKT matrix is singular) quarters it.
    const double factor =
        ok ? std::clamp(kSafety * std::pow(errorNorm, -kExponent), kMaxShrink, kSafety) : 0.25;
    h_ = h * factor;
    if (h_ < hmin) {
      if (!ok)
        recordFailure("the KKT matrix is singular at t = " + format("%.6E", t_) +
                          " (every step down to HMIN reaches a singular configuration)",
                      h, nullptr);
      else
        recordFailure("the local error stays above ERROR with steps down to HMIN = " +
                          format("%.3E", hmin),
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
  const double h00 = (1.0 + 2.0 * th) * (1.0 - th) * (1.0 - th);
  const double h10 = th * (1.0 - th) * (1.0 - th);
  const double h01 = th * th * (3.0 - 2.0 * th);
  const double h11 = th * th * (th - 1.0);
  const Eigen::VectorXd x =
      h00 * xPrevious_ + (h10 * h) * fPrevious_ + h01 * x_ + (h11 * h) * f_;
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
  Eigen::VectorXd v(n), jv, jjv, xPerturbed, fPerturbed;
  for (Eigen::Index i = 0; i < n; ++i) v(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i + 1));
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
    if (!apply(v, jv) || !apply(jv, jjv)) return;  // keep the last estimate
    const double growth = jjv.norm() / v.norm();
    estimate = std::sqrt(growth);
    if (!(growth > 0)) break;
    v = jjv / jjv.norm();
  }
  spectralRadius_ = estimate;
  stepsSinceEstimate_ = 0;
}

void MersonIntegrator::watchStiffness(double h) {
  if (++stepsSinceEstimate_ >= kStepsBetweenEstimates) estimateSpectralRadius();
  if (stiff_) return;
  if (h * spectralRadius_ < kStiffStepRatio) {
    stiffSteps_ = 0;
    return;
  }
  if (++stiffSteps_ < kStiffStepsBeforeWarning) return;
  stiff_ = true;
  warnings_.push_back(
      "MERSON: the model is stiff. The equations of motion have an eigenvalue of magnitude " +
      format("%.3E", spectralRadius_) + " 1/s (time constant " +
      format("%.3E", 1.0 / spectralRadius_) + " s) and the explicit steps (" + format("%.3E", h) +
      " s at t = " + format("%.6E", t_) +
      ") are held by its stability, not by accuracy. MERSON is meant for non-stiff models; "
      "INTEGRATOR/GSTIFF (or WSTIFF, DSTIFF) is not bound by this mode: use it when the fast "
      "mode is a stiff spring, bushing or contact (on long pendulum chains MERSON can still be "
      "the faster method; compare the run times).");
}

void MersonIntegrator::recordFailure(const std::string& reason, double h,
                                     const Eigen::VectorXd* errors) {
  failure_ = {};
  failure_.time = t_;
  failure_.stepSize = h;
  failure_.reason = reason;
  // The equation that the step could not satisfy: the DAE residual at a forward-Euler
  // prediction from the last accepted state (at that state itself every residual is zero).
  const StateLayout& l = system_.layout();
  const int n = l.size();
  if (y_.size() != n || yp_.size() != n) return;
  const Eigen::VectorXd yPredicted = y_ + h * yp_;
  Eigen::VectorXd g(n);
  system_.residual(t_ + h, yPredicted.data(), yp_.data(), g.data());
  for (int i = 0; i < n; ++i) {
    const double r = std::abs(g(i));
    if (failure_.worstEquation < 0 || !std::isfinite(r) || r > failure_.worstResidual) {
      failure_.worstEquation = i;
      failure_.worstResidual = r;
      if (!std::isfinite(r)) break;
    }
  }
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
