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
#include "solvers/integrator.hpp"

namespace openmss::solvers {

struct BdfSettings {
  double error = 1e-3;  // ERROR: local error tolerance (relative and absolute)
  double hinit = 0.0;   // HINIT: first step (0: chosen by the caller)
  double hmax = std::numeric_limits<double>::infinity();  // HMAX
  double hmin = 0.0;    // HMIN: smallest step before the run fails
  int kmax = 6;         // KMAX: highest order
  int maxit = 10;       // MAXIT: corrector iterations per attempt
};

// The names the BDF family used before the common interface (solvers/integrator.hpp).
using BdfStatistics = IntegratorStatistics;
using BdfFailure = IntegratorFailure;
using BdfIterationInfo = IterationInfo;
using BdfStepInfo = StepInfo;

class BdfIntegrator final : public Integrator {
 public:
  BdfIntegrator(DaeProblem& problem, const BdfSettings& settings);

  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool step(double tout) override;

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  double previousTime() const override { return ts_.size() > 1 ? ts_[1] : t_; }
  // The corrector polynomial of the last step (order k through the last k+1 solutions).
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  const IntegratorStatistics& statistics() const override { return stats_; }
  const IntegratorFailure& failure() const override { return failure_; }

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
  int lastStepOrder_ = 1;  // order of the last accepted step (its interpolant)

  // Newton matrix and its factorisation, kept while they serve.
  Eigen::MatrixXd jac_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd rowScale_, colScale_;
  double cjJacobian_ = 0.0;
  bool jacobianCurrent_ = false;
  bool haveJacobian_ = false;

  // Work vectors (no allocation in the step loop).
  Eigen::VectorXd yNew_, ypNew_, yPred_, base_, g_, dy_, predictorDiff_;
  int lastWorstEq_ = -1, lastWorstVar_ = -1;
  double lastWorstRes_ = 0.0, lastWorstChange_ = 0.0;
};

}  // namespace openmss::solvers
