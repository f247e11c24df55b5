#pragma once
// A variable-order (1..KMAX), variable-step BDF predictor-corrector for index-3 DAEs, in the
// manner of ADAMS's GSTIFF (docs/theory.md, "Integration"): Lagrange predictor through past
// solutions, BDF corrector solved by modified Newton, local error estimated from the
// predictor-corrector difference on displacements, steps landing on output times.

#include <deque>
#include <limits>
#include <string>

#include <Eigen/Dense>

#include "solvers/dae_problem.hpp"

namespace openmss::solvers {

struct BdfSettings {
  double error = 1e-3;  // ERROR: local error tolerance (relative and absolute)
  double hinit = 0.0;   // HINIT: first step (0: chosen by the caller)
  double hmax = std::numeric_limits<double>::infinity();  // HMAX
  double hmin = 0.0;    // HMIN: smallest step before the run fails
  int kmax = 6;         // KMAX: highest order
  int maxit = 10;       // MAXIT: corrector iterations per attempt
};

struct BdfStatistics {
  long steps = 0;
  long rejectedSteps = 0;
  long newtonFailures = 0;
  long residualEvaluations = 0;
  long jacobianEvaluations = 0;
  int order = 1;
  double stepSize = 0.0;
};

// What the integrator knew when it gave up (seed: "when, which equation, which variable").
struct BdfFailure {
  double time = 0.0;
  double stepSize = 0.0;
  std::string reason;
  int worstEquation = -1;
  double worstResidual = 0.0;
  int worstVariable = -1;
  double worstChange = 0.0;
};

// Called after every corrector iteration when set (DEBUG/EPRINT).
struct BdfIterationInfo {
  double time, stepSize;
  int order, iteration;
  int worstEquation;
  double worstResidual;
  int worstVariable;
  double worstChange;
};

// Called at every step attempt and at its outcome when set (DEBUG/EPRINT).
struct BdfStepInfo {
  enum class Event { Attempt, Accepted, ErrorTestFailed, CorrectorFailed };
  Event event;
  long step;         // number of the step attempted: accepted steps so far + 1
  int order;
  double time;       // start of the step
  double stepSize;
  double errorNorm;  // weighted local error (1 = the tolerance); Accepted, ErrorTestFailed
};

class BdfIntegrator {
 public:
  BdfIntegrator(DaeProblem& problem, const BdfSettings& settings);

  // Consistent initial values (y0, y'0) at t0.
  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0);
  // Integrates until t == tout exactly. Returns false on failure (see failure()).
  bool advanceTo(double tout);

  double t() const { return t_; }
  const Eigen::VectorXd& y() const { return y_; }
  const Eigen::VectorXd& yp() const { return yp_; }
  const BdfStatistics& statistics() const { return stats_; }
  const BdfFailure& failure() const { return failure_; }
  void setIterationObserver(void (*fn)(const BdfIterationInfo&, void*), void* user) {
    observer_ = fn;
    observerUser_ = user;
  }
  void setStepObserver(void (*fn)(const BdfStepInfo&, void*), void* user) {
    stepObserver_ = fn;
    stepObserverUser_ = user;
  }

 private:
  bool attemptStep(double h, int k, bool* newtonFailed, double* errorNorm);
  double weightedNorm(const Eigen::VectorXd& v, const Eigen::VectorXd& ref, bool errorOnly) const;
  void noteWorst(const Eigen::VectorXd& g, const Eigen::VectorXd& dy);
  double orderErrorEstimate(int q, double h) const;

  DaeProblem& problem_;
  BdfSettings settings_;
  BdfStatistics stats_;
  BdfFailure failure_;

  double t_ = 0.0;
  Eigen::VectorXd y_, yp_;
  std::deque<double> ts_;           // accepted times, most recent first
  std::deque<Eigen::VectorXd> ys_;  // accepted solutions, most recent first
  double h_ = 0.0;
  int k_ = 1;
  int stepsAtOrder_ = 0;

  // Newton matrix and its factorisation, kept while they serve.
  Eigen::MatrixXd jac_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd rowScale_, colScale_;
  double cjJacobian_ = 0.0;
  bool jacobianCurrent_ = false;
  bool haveJacobian_ = false;

  // Work vectors (no allocation in the step loop).
  Eigen::VectorXd yNew_, ypNew_, yPred_, base_, g_, dy_, predictorDiff_;
  void (*observer_)(const BdfIterationInfo&, void*) = nullptr;
  void* observerUser_ = nullptr;
  void (*stepObserver_)(const BdfStepInfo&, void*) = nullptr;
  void* stepObserverUser_ = nullptr;
  int lastWorstEq_ = -1, lastWorstVar_ = -1;
  double lastWorstRes_ = 0.0, lastWorstChange_ = 0.0;
};

}  // namespace openmss::solvers
