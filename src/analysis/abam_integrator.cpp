#include "analysis/abam_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "analysis/analysis_context.hpp"  // formatNumber
#include "analysis/predicted_residual.hpp"

namespace openmss::analysis {
namespace {

// Re-partition when the dependent block's pivot ratio falls to this share of its value at
// partitioning (the choice of dependent coordinates is going bad), or when a body has turned
// this far (rad) from its reference orientation (the rotation-vector coordinates stay well
// inside |z| < pi, where they are unique and T(z) is well conditioned).
constexpr double kPivotDegradation = 0.1;
constexpr double kLargestRotation = 1.0;
// h |lambda_max| above which an Adams step is held by the stability of the fastest mode rather
// than by accuracy: accuracy at any useful ERROR needs h |lambda| well below 1 for a mode that
// actually moves (a 4th-order method at h |lambda| = 0.5 errs by ~1e-3 per step), so steps
// beyond it mean the mode is a stiff one the method must not follow.
constexpr double kStiffStepRatio = 0.5;
// Accepted steps beyond that ratio before the warning (a start-up transient is not stiffness).
constexpr long kStiffStepsBeforeWarning = 20;
// Accepted steps between estimates of the spectral radius.
constexpr long kStepsBetweenEstimates = 200;

}  // namespace

struct AbamIntegrator::Engine {
  const mechanics::CoordinatePartitioning* partitioning = nullptr;
  SUNContext context = nullptr;
  void* cvode = nullptr;
  N_Vector x = nullptr, work = nullptr, weights = nullptr, localErrors = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear = nullptr;
  Eigen::VectorXd xWork, xdotWork, yWork, ypWork;
  std::string lastMessage;

  explicit Engine(const mechanics::CoordinatePartitioning& p) : partitioning(&p) {
    SUNContext_Create(nullptr, &context);
  }
  ~Engine() { release(); if (context) SUNContext_Free(&context); }
  void release() {
    if (cvode) CVodeFree(&cvode);
    if (linear) SUNLinSolFree(linear);
    if (matrix) SUNMatDestroy(matrix);
    for (N_Vector* v : {&x, &work, &weights, &localErrors})
      if (*v) { N_VDestroy(*v); *v = nullptr; }
    linear = nullptr;
    matrix = nullptr;
  }

  static Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
    return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
  }

  static int rhs(realtype t, N_Vector x, N_Vector xdot, void* user) {
    auto* e = static_cast<Engine*>(user);
    e->xWork = view(x);
    // A configuration the constraints cannot reach (Newton fails) is recoverable: CVODE
    // retries with a smaller step.
    if (!e->partitioning->expand(t, e->xWork, e->yWork, e->ypWork, &e->xdotWork)) return 1;
    view(xdot) = e->xdotWork;
    return 0;
  }

  static void errorHandler(int, const char*, const char*, char* message, void* user) {
    static_cast<Engine*>(user)->lastMessage = message;
  }
};

AbamIntegrator::AbamIntegrator(const mechanics::MultibodySystem& system,
                               const solvers::MultistepSettings& settings)
    : system_(system), settings_(settings), partitioning_(system) {}

AbamIntegrator::~AbamIntegrator() = default;

void AbamIntegrator::start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  t_ = tPrevious_ = t0;
  y_ = y0;
  yp_ = yp0;
  stats_ = earlier_ = {};
  failure_ = {};
  partitions_ = 0;
  stiff_ = false;
  stiffSteps_ = 0;
  warnings_.clear();
  engine_ = std::make_unique<Engine>(partitioning_);
  engine_->yWork = y0;
  repartitionPending_ = false;
  // The reduced ODE holds the mechanical coordinates only: DIFF, LSE and TFSISO states would
  // stand still. Refused rather than integrated wrongly.
  if (system_.layout().userDifferential > 0) {
    recordFailure("ABAM integrates the mechanical coordinates only and this model has DIFF, "
                  "LSE or TFSISO states; use INTEGRATOR/GSTIFF",
                  0.0);
    return;
  }
  if (!restart()) recordFailure("the constraint Jacobian has no usable pivots", 0.0);
}

bool AbamIntegrator::restart() {
  Engine& e = *engine_;
  earlier_ = stats_;
  e.release();
  if (!partitioning_.partition(y_)) return false;
  ++partitions_;
  repartitionPending_ = false;
  const int n = 2 * partitioning_.degreesOfFreedom();
  if (n == 0) return true;  // no degrees of freedom: kinematics only (step() expands)
  for (N_Vector* v : {&e.x, &e.work, &e.weights, &e.localErrors}) *v = N_VNew_Serial(n, e.context);
  Eigen::VectorXd x;
  partitioning_.reduce(y_, x);
  Engine::view(e.x) = x;
  e.cvode = CVodeCreate(CV_ADAMS, e.context);
  CVodeSetErrHandlerFn(e.cvode, &Engine::errorHandler, &e);
  CVodeInit(e.cvode, &Engine::rhs, t_, e.x);
  CVodeSetUserData(e.cvode, &e);
  CVodeSStolerances(e.cvode, settings_.error, settings_.error);
  // Newton iteration (dense, difference-quotient Jacobian of the small reduced ODE) rather than
  // functional iteration: the latter diverges as soon as h |lambda_max| nears 1, which would turn
  // a mildly stiff model into a failure instead of the warning below.
  e.matrix = SUNDenseMatrix(n, n, e.context);
  e.linear = SUNLinSol_Dense(e.x, e.matrix, e.context);
  CVodeSetLinearSolver(e.cvode, e.linear, e.matrix);
  CVodeSetMaxOrd(e.cvode, std::clamp(settings_.kmax, 1, 12));
  if (std::isfinite(settings_.hmax) && settings_.hmax > 0) CVodeSetMaxStep(e.cvode, settings_.hmax);
  if (settings_.hmin > 0) CVodeSetMinStep(e.cvode, settings_.hmin);
  if (settings_.hinit > 0) CVodeSetInitStep(e.cvode, settings_.hinit);
  CVodeSetMaxNonlinIters(e.cvode, std::max(1, settings_.maxit));
  estimateSpectralRadius();
  return true;
}

void AbamIntegrator::estimateSpectralRadius() {
  // Reduced Jacobian by central differences of x' = f(t, x) (2 dof columns), then its largest
  // eigenvalue magnitude.
  Engine& e = *engine_;
  Eigen::VectorXd x;
  partitioning_.reduce(y_, x);
  const Eigen::Index n = x.size();
  Eigen::MatrixXd jac(n, n);
  Eigen::VectorXd fp, fm, yw = y_, ypw;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double d = 1e-6 * std::max(1.0, std::abs(x(j)));
    Eigen::VectorXd xp = x, xm = x;
    xp(j) += d;
    xm(j) -= d;
    if (!partitioning_.expand(t_, xp, yw, ypw, &fp) || !partitioning_.expand(t_, xm, yw, ypw, &fm))
      return;  // keep the last estimate
    jac.col(j) = (fp - fm) / (2.0 * d);
  }
  partitioning_.expand(t_, x, yw, ypw, nullptr);  // leave Newton's guess at the current state
  spectralRadius_ = n > 0 ? jac.eigenvalues().cwiseAbs().maxCoeff() : 0.0;
  stepsSinceEstimate_ = 0;
  (void)e;
}

void AbamIntegrator::watchStiffness(double h) {
  if (++stepsSinceEstimate_ >= kStepsBetweenEstimates) estimateSpectralRadius();
  if (stiff_ || h * spectralRadius_ < kStiffStepRatio) return;
  if (++stiffSteps_ < kStiffStepsBeforeWarning) return;
  stiff_ = true;
  warnings_.push_back(
      "ABAM: the model is stiff. The reduced Jacobian has an eigenvalue of magnitude " +
      formatNumber("%.3E", spectralRadius_) + " 1/s (time constant " +
      formatNumber("%.3E", 1.0 / spectralRadius_) + " s) and the Adams steps (" +
      formatNumber("%.3E", h) +
      " s at t = " + formatNumber("%.6E", t_) +
      ") are held by its stability, not by accuracy. ABAM is meant for non-stiff models; "
      "use INTEGRATOR/GSTIFF (or WSTIFF, DSTIFF) for this model.");
}

bool AbamIntegrator::step(double tout) {
  Engine& e = *engine_;
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  if (t_ >= tout - eps) return true;
  if (!failure_.reason.empty()) return false;
  if (repartitionPending_ && !restart()) {
    recordFailure("the constraint Jacobian has no usable pivots", 0.0);
    return false;
  }
  if (partitioning_.degreesOfFreedom() == 0) {
    // A kinematically driven model: the constraints alone give the state at tout.
    Eigen::VectorXd x(0), y = y_, yp;
    if (!partitioning_.expand(tout, x, y, yp, nullptr)) {
      recordFailure("the constraints cannot be satisfied (position Newton failed)", tout - t_);
      return false;
    }
    tPrevious_ = t_;
    t_ = tout;
    y_ = y;
    yp_ = yp;
    ++stats_.steps;
    return true;
  }
  CVodeSetStopTime(e.cvode, tout);
  double tReturned = t_;
  const int flag = CVode(e.cvode, tout, e.x, &tReturned, CV_ONE_STEP);
  readStatistics();
  if (flag < 0) {
    double h = 0.0;
    CVodeGetCurrentStep(e.cvode, &h);
    std::string reason;
    switch (flag) {
      case CV_TOO_MUCH_WORK: reason = "too many steps without reaching the output time"; break;
      case CV_TOO_MUCH_ACC: reason = "the requested accuracy cannot be reached in floating point"; break;
      case CV_ERR_FAILURE: reason = "the local error stays above the tolerance (repeated error-test failures)"; break;
      case CV_CONV_FAILURE: reason = "the corrector did not converge (repeated Newton failures)"; break;
      case CV_RHSFUNC_FAIL:
      case CV_REPTD_RHSFUNC_ERR:
      case CV_UNREC_RHSFUNC_ERR:
      case CV_FIRST_RHSFUNC_ERR:
        reason = "the dependent coordinates could not be recovered (the constraints' Newton "
                 "iteration or the KKT solve failed)";
        break;
      default: reason = "the Adams integrator failed (" + e.lastMessage + ")"; break;
    }
    recordFailure(reason, h);
    return false;
  }
  double tCurrent = tReturned, hLast = 0.0;
  CVodeGetCurrentTime(e.cvode, &tCurrent);
  CVodeGetLastStep(e.cvode, &hLast);
  tPrevious_ = tCurrent - hLast;
  t_ = std::abs(tReturned - tout) <= eps ? tout : tReturned;
  Eigen::VectorXd x = Engine::view(e.x), y = y_, yp;
  if (!partitioning_.expand(t_, x, y, yp, nullptr)) {
    recordFailure("the dependent coordinates could not be recovered at the end of the step", hLast);
    return false;
  }
  y_ = y;
  yp_ = yp;
  watchStiffness(hLast);
  if (partitioning_.pivotQuality(y_) < kPivotDegradation ||
      partitioning_.largestRotation(y_) > kLargestRotation)
    repartitionPending_ = true;  // at the next step: the interpolant of this one stays valid
  if (observingSteps()) {
    CVodeGetErrWeights(e.cvode, e.weights);
    CVodeGetEstLocalErrors(e.cvode, e.localErrors);
    notifyStep({solvers::StepInfo::Event::Accepted, stats_.steps, stats_.order, tPrevious_,
                hLast, N_VWrmsNorm(e.localErrors, e.weights)});
  }
  return true;
}

void AbamIntegrator::interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  Engine& e = *engine_;
  if (s == t_ || partitioning_.degreesOfFreedom() == 0 || !e.cvode) {
    y = y_;
    yp = yp_;
    if (s != t_) partitioning_.expand(s, Eigen::VectorXd(0), y, yp, nullptr);
    return;
  }
  CVodeGetDky(e.cvode, s, 0, e.work);
  const Eigen::VectorXd x = Engine::view(e.work);
  y = y_;
  if (!partitioning_.expand(s, x, y, yp, nullptr)) {
    y = y_;
    yp = yp_;
  }
}

void AbamIntegrator::readStatistics() {
  Engine& e = *engine_;
  if (!e.cvode) return;
  long value = 0;
  stats_ = earlier_;
  CVodeGetNumSteps(e.cvode, &value);
  stats_.steps += value;
  CVodeGetNumErrTestFails(e.cvode, &value);
  stats_.rejectedSteps += value;
  CVodeGetNumNonlinSolvConvFails(e.cvode, &value);
  stats_.newtonFailures += value;
  CVodeGetNumRhsEvals(e.cvode, &value);
  stats_.residualEvaluations += value;
  CVodeGetNumJacEvals(e.cvode, &value);
  stats_.jacobianEvaluations += value;
  int order = 1;
  CVodeGetLastOrder(e.cvode, &order);
  stats_.order = order;
  double h = 0.0;
  CVodeGetLastStep(e.cvode, &h);
  stats_.stepSize = h;
}

void AbamIntegrator::recordFailure(const std::string& reason, double h) {
  failure_ = {};
  failure_.time = t_;
  failure_.stepSize = h;
  failure_.reason = reason;
  notePredictedResidual(system_, t_, h, y_, yp_, failure_);
  // The variable with the largest weighted local error among the independent coordinates.
  Engine& e = *engine_;
  if (!e.cvode || CVodeGetEstLocalErrors(e.cvode, e.localErrors) != CV_SUCCESS ||
      CVodeGetErrWeights(e.cvode, e.weights) != CV_SUCCESS)
    return;
  const auto ele = Engine::view(e.localErrors);
  const auto w = Engine::view(e.weights);
  const int dof = partitioning_.degreesOfFreedom();
  const auto& l = system_.layout();
  double worstWeighted = -1.0;
  for (int k = 0; k < ele.size(); ++k) {
    const double c = std::abs(ele(k) * w(k));
    if (c <= worstWeighted) continue;
    worstWeighted = c;
    const int j = partitioning_.independent()[static_cast<size_t>(k % dof)];
    const int o = l.body(j / 6);
    const bool velocity = k >= dof;
    const bool translation = j % 6 < 3;
    failure_.worstVariable =
        o + (translation ? (velocity ? mechanics::StateLayout::kV : mechanics::StateLayout::kR) + j % 6
                         : mechanics::StateLayout::kW + j % 6 - 3);
    failure_.worstChange = std::abs(ele(k));
  }
}

}  // namespace openmss::analysis
