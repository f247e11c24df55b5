#pragma once
// DSTIFF: the DASSL-family BDF of SUNDIALS IDA on a DaeProblem (docs/integrators.md, "DSTIFF").
// IDA supplies the predictor, the fixed-leading-coefficient BDF corrector, order and step
// selection and the interpolant; we supply the residual, the exact Newton matrix, which unknowns
// are algebraic and which are under error control, and a linear solver that factors the Newton
// matrix in the balanced form DaeProblem::rowScaleExponent describes (index-3 mechanics would
// otherwise lose its pivots as the step shrinks).

#include <memory>

#include <Eigen/Dense>

#include "solvers/bdf_integrator.hpp"
#include "solvers/dae_problem.hpp"
#include "solvers/integrator.hpp"
#include "solvers/multistep_settings.hpp"

namespace openmss::solvers {

// Why IDA stopped (its return codes, translated).
enum class IdaOutcome {
  Ok,
  TooMuchWork,         // IDA_TOO_MUCH_WORK: mxstep steps without reaching tout
  TooMuchAccuracy,     // IDA_TOO_MUCH_ACC
  ErrorTestFailures,   // IDA_ERR_FAIL: repeated local-error test failures
  ConvergenceFailures, // IDA_CONV_FAIL: repeated corrector failures
  LinearSolverFailed,  // IDA_LSETUP_FAIL / IDA_LSOLVE_FAIL: singular Newton matrix
  ResidualFailed,      // IDA_RES_FAIL / IDA_REP_RES_ERR / IDA_FIRST_RES_FAIL
  ConstraintFailures,  // IDA_CONSTR_FAIL
  OtherFailure,
};

class IdaIntegrator final : public Integrator {
 public:
  IdaIntegrator(DaeProblem& problem, const MultistepSettings& settings);
  ~IdaIntegrator() override;
  IdaIntegrator(const IdaIntegrator&) = delete;
  IdaIntegrator& operator=(const IdaIntegrator&) = delete;

  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool step(double tout) override;

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  double previousTime() const override { return tPrevious_; }
  // IDA's own interpolant (IDAGetDky), valid over the last step.
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  const IntegratorStatistics& statistics() const override { return stats_; }
  const IntegratorFailure& failure() const override { return failure_; }
  IdaOutcome outcome() const { return outcome_; }

  struct Engine;  // the SUNDIALS objects and callbacks (ida_integrator.cpp)

 private:
  void readStatistics();
  void recordFailure(int flag);

  DaeProblem& problem_;
  MultistepSettings settings_;
  std::unique_ptr<Engine> engine_;
  IntegratorStatistics stats_;
  IntegratorFailure failure_;
  IdaOutcome outcome_ = IdaOutcome::Ok;
  double t_ = 0.0, tPrevious_ = 0.0;
  Eigen::VectorXd y_, yp_;
  // Stepping across a singular instant (step(); docs/integrators.md, "Stepping across a
  // singular instant"): the state the call started from, kept when its first step was accepted
  // on a stalled move; the start of IDA's last step (interpolate() spans the steps before it
  // with a cubic Hermite from the entry state); and the counters of the IDA runs before the
  // last re-initialisation, which resets IDA's own.
  Eigen::VectorXd yEntry_, ypEntry_;
  bool spanFromEntry_ = false;  // the last call handed over more than one step
  double lastStepStart_ = 0.0;
  IntegratorStatistics countedBefore_;
};

}  // namespace openmss::solvers
