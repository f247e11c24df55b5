#pragma once
// What every time integrator offers the analyses (GSTIFF-, WSTIFF-, DSTIFF-, HHT-style and
// ABAM methods alike): start from consistent values, take one step or run to an output time,
// interpolate inside the last step (output interpolation, SENSOR event location), statistics,
// and, on failure, what the method knew when it gave up. The equations reach the method only
// through solvers/dae_problem.hpp.

#include <Eigen/Dense>
#include <algorithm>
#include <string>
#include <vector>

namespace openmss::solvers {

struct IntegratorStatistics {
  long steps = 0;
  long rejectedSteps = 0;
  long newtonFailures = 0;
  long residualEvaluations = 0;
  long jacobianEvaluations = 0;
  // Of the Newton matrices factorised by the sparse solver (KLU): symbolic analyses (one per new
  // pattern), factorisations with fresh pivoting and refactorisations on the last pivots.
  long sparseAnalyses = 0;
  long fullFactorizations = 0;
  long refactorizations = 0;
  int order = 1;
  double stepSize = 0.0;
};

// What the integrator knew when it gave up (when, which equation, which variable: what a user needs
// to find the cause).
struct IntegratorFailure {
  double time = 0.0;
  double stepSize = 0.0;
  std::string reason;
  int worstEquation = -1;
  double worstResidual = 0.0;
  int worstVariable = -1;
  double worstChange = 0.0;
};

// Called after every corrector iteration when set (DEBUG/EPRINT).
struct IterationInfo {
  double time, stepSize;
  int order, iteration;
  int worstEquation;
  double worstResidual;
  int worstVariable;
  double worstChange;
};

// Called at every step attempt and at its outcome when set (DEBUG/EPRINT).
struct StepInfo {
  enum class Event { Attempt, Accepted, ErrorTestFailed, CorrectorFailed };
  Event event;
  long step;  // number of the step attempted: accepted steps so far + 1
  int order;
  double time;  // start of the step
  double stepSize;
  double errorNorm;  // weighted local error (1 = the tolerance); Accepted, ErrorTestFailed
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  // Consistent initial values (y0, y'0) at t0. Also used to restart after a discontinuity
  // (SENSOR/RESTART): the method forgets its history.
  virtual void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) = 0;
  // As start(), after a discontinuity the method's Newton matrix still approximates well (a
  // CONTACT onset: an IMPACT force's stiffness is zero at first touch, docs/theory.md §6c,
  // "Events"): the history is forgotten, but a method may keep its matrix and factors for its
  // modified Newton iteration (which re-forms them when it converges slowly or fails).
  virtual void restart(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
    start(t0, y0, yp0);
  }
  // The size of the next step attempt (SENSOR/STEPSIZE after a restart), still bounded by the
  // method's HMAX. Returns false when the method cannot take a size from outside (the caller
  // then says that STEPSIZE had no effect).
  virtual bool setNextStepSize(double h) {
    (void)h;
    return false;
  }
  // Takes one accepted step that does not pass tout (it lands on tout exactly when it gets
  // there). Returns false on failure (see failure()).
  virtual bool step(double tout) = 0;
  // Integrates until t() == tout exactly.
  bool advanceTo(double tout) {
    const double eps = 1e-12 * std::max(1.0, tout < 0 ? -tout : tout);
    while (t() < tout - eps)
      if (!step(tout)) return false;
    return true;
  }

  virtual double t() const = 0;
  virtual const Eigen::VectorXd& y() const = 0;
  virtual const Eigen::VectorXd& yp() const = 0;
  // Start of the last accepted step (t() before start()'s first step).
  virtual double previousTime() const = 0;
  // The method's own interpolant at time s in [previousTime(), t()].
  virtual void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const = 0;
  // interpolate()'s y at the listed components only, to the bit, written into y (sized as the
  // state; the other entries are left as they are). The contact event locator bisects on the
  // few bodies of one contact (docs/performance.md, "Contact pile"). The default interpolates
  // everything.
  virtual void interpolateComponents(double s, const std::vector<int>& components,
                                     Eigen::VectorXd& y) const {
    Eigen::VectorXd all, allp;
    interpolate(s, all, allp);
    if (y.size() != all.size()) y = all;
    for (const int i : components) y(i) = all(i);
  }

  virtual const IntegratorStatistics& statistics() const = 0;
  virtual const IntegratorFailure& failure() const = 0;
  // Advice the method has for the user about this run, for the .msg (ABAM's stiffness
  // warning); each line appears once and lines are only ever added.
  virtual std::vector<std::string> warnings() const { return {}; }

  void setIterationObserver(void (*fn)(const IterationInfo&, void*), void* user) {
    iterationObserver_ = fn;
    iterationObserverUser_ = user;
  }
  void setStepObserver(void (*fn)(const StepInfo&, void*), void* user) {
    stepObserver_ = fn;
    stepObserverUser_ = user;
  }

 protected:
  void notifyIteration(const IterationInfo& info) const {
    if (iterationObserver_) iterationObserver_(info, iterationObserverUser_);
  }
  void notifyStep(const StepInfo& info) const {
    if (stepObserver_) stepObserver_(info, stepObserverUser_);
  }
  bool observingSteps() const { return stepObserver_ != nullptr; }
  bool observingIterations() const { return iterationObserver_ != nullptr; }

 private:
  void (*iterationObserver_)(const IterationInfo&, void*) = nullptr;
  void* iterationObserverUser_ = nullptr;
  void (*stepObserver_)(const StepInfo&, void*) = nullptr;
  void* stepObserverUser_ = nullptr;
};

}  // namespace openmss::solvers
