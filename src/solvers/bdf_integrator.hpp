#pragma once
// A variable-order (1..KMAX), variable-step BDF predictor-corrector for index-3 DAEs, in the
// manner of ADAMS's GSTIFF (docs/theory.md, "Integration"): Lagrange predictor through past
// solutions, BDF corrector solved by modified Newton, local error estimated from the
// predictor-corrector difference on displacements, steps landing on output times.

#include <Eigen/Dense>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "solvers/dae_problem.hpp"
#include "solvers/dense_linear_solver.hpp"
#include "solvers/nonzero_pattern.hpp"
#include "solvers/integrator.hpp"
#include "solvers/multistep_settings.hpp"
#include "solvers/sparse_linear_solver.hpp"

namespace openmss::solvers {

// The names the BDF family used before the common interface (solvers/integrator.hpp).
using BdfStatistics = IntegratorStatistics;
using BdfFailure = IntegratorFailure;
using BdfIterationInfo = IterationInfo;
using BdfStepInfo = StepInfo;

class BdfIntegrator final : public Integrator {
 public:
  BdfIntegrator(DaeProblem& problem, const MultistepSettings& settings);

  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  // Keeps the Newton matrix, its factors and its scaling (docs/integrators.md, "Restarts").
  void restart(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool step(double tout) override;
  bool setNextStepSize(double h) override {  // SENSOR/STEPSIZE
    h_ = h;
    return true;
  }

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  // The time of the state handed over before the last step() (the start of the steps it took;
  // more than one when it stepped across a singular instant, step()).
  double previousTime() const override { return handedFrom_; }
  // The corrector polynomial of the last step (order k through the last k+1 solutions).
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  void interpolateComponents(double s, const std::vector<int>& components,
                             Eigen::VectorXd& y) const override;
  const IntegratorStatistics& statistics() const override { return stats_; }
  // How often an order >= 3 was abandoned because the step it held shrank below the one order 2
  // had taken: the signature of an undamped mode that the order amplifies.
  long stabilityLimitDetections() const { return stabilityLimitDetections_; }
  const IntegratorFailure& failure() const override { return failure_; }

  // Problems with at least this many unknowns that offer a sparse Newton matrix are solved with
  // it and KLU; smaller ones with a dense matrix and LU (measured in bench/jacobian_bench.cpp
  // and docs/theory.md, "Sparse Newton matrix").
  static constexpr int kSparseThreshold = 100;
  // "KLU" or "dense LU": the linear solver of the current run.
  const char* linearSolverName() const { return solver_->name(); }
  // The solver of the sparse path (KLU or the supernodal LU by its rule), for tests.
  SparseLinearSolver& sparseLinearSolver() { return sparseSolver_; }

 private:
  bool attemptStep(double h, int k, bool* newtonFailed, double* errorNorm);
  // Largest |v_i| w_i: the weighted maximum norm for the weights w (errorWeight_ or
  // correctorWeight_). NaN when v holds a NaN or an infinity anywhere (0 * inf is NaN): a
  // non-finite unknown fails the attempt.
  static double weightedNorm(const Eigen::VectorXd& v, const Eigen::VectorXd& w);
  void setWeights();
  // True when every differential change of the last iteration (dy_) is at the round-off of its
  // unknown at yNew_ (kRoundOffUlps in the .cpp): a stalled iteration there has converged.
  bool withinRoundOff(double cj);
  void noteWorst(const Eigen::VectorXd& g, const Eigen::VectorXd& dy);
  // Local error estimate of order q at step h from the divided-difference diagonal of the
  // accepted history (diagonal_); -1 when the history is too short.
  double orderErrorEstimate(int q, double h) const;
  // Extends diagonal_ by the newest accepted solution (ys_[0] at ts_[0]): one vector operation
  // per level instead of the full table per estimate.
  void updateDivided();
  // After a displacement error-test failure at step h with estimate err: the next h_ and k_.
  void rejectOnDisplacement(double h, double err);
  // The noise a solve accepted by a stall rule carries (kStalledChange and the rules after it
  // in the .cpp): laterChanges_ spread over each role, then the error weights widened by it.
  void widenForNoise();
  // After an accepted step h with error estimate err: the next order k_ and step h_ (the
  // order-selection and stability-limit rules, bdf_order_selection.cpp).
  void selectNextStep(double h, double err);

  // Stepping across a singular instant (docs/integrators.md, "Stepping across a singular
  // instant"): everything a step changes, saved at the state step() started from when its
  // first step was accepted on a stalled move, and put back to step across from there.
  struct Resumable {
    double t = 0.0;
    Eigen::VectorXd y, yp;
    std::deque<double> ts;
    std::deque<Eigen::VectorXd> ys;
    std::vector<Eigen::VectorXd> diagonal;
    double h = 0.0;
    int k = 1, stepsAtOrder = 0, lastStepOrder = 1;
    double lowOrderStep = 0.0;
    long highOrderBarredUntil = 0, stabilityBar = 0, stepsSinceRoughSolve = 0;
    bool lastSolveAtNoise = false;
    std::deque<double> heldLow, heldOwn;
    int order = 1;
    double stepSize = 0.0;
  };
  void saveEntry();
  void restoreEntry();

  DaeProblem& problem_;
  MultistepSettings settings_;
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
  // Stability-limit detection for orders >= 3 (docs/integrators.md, "Order selection"): the
  // last step accepted at order <= 2, the step count up to which orders >= 3 stay barred after
  // a detection, and the length of the next bar (doubled at every detection).
  double lowOrderStep_ = 0.0;
  long highOrderBarredUntil_ = 0;
  long stabilityBar_ = 0;
  long stabilityLimitDetections_ = 0;
  // Steps accepted since the last rough solve (a corrector failure, or a solve accepted by a
  // stall rule at its noise): the shrink trigger skips the steps whose history still holds one
  // (docs/integrators.md, "Order selection"). lastSolveAtNoise_: the last converged solve was
  // accepted at noise.
  long stepsSinceRoughSolve_ = 0;
  bool lastSolveAtNoise_ = false;
  // The last solve was accepted by a stall rule with changes above kStalledMove of the
  // tolerance (a move along the Newton matrix's near-null direction, not round-off).
  bool stalledMove_ = false;
  Resumable entry_;
  double handedFrom_ = 0.0;  // previousTime()
  // Error estimates of orders k-1 and k over the run of steps taken at the current order with
  // one unchanged step size (oldest first; at most kGrowthWindow + 1 entries).
  std::deque<double> heldLow_, heldOwn_;

  // Newton matrix and its factorisation, kept while they serve: dense, or sparse on the
  // problem's fixed pattern (sparse_), factorised by solver_.
  bool sparse_ = false;
  Eigen::MatrixXd jac_;
  Eigen::SparseMatrix<double> sparseJac_;
  NonzeroPattern nonzero_;  // the entries of sparseJac_ factorised
  DenseLinearSolver dense_;
  SparseLinearSolver sparseSolver_;
  LinearSolver* solver_ = &dense_;
  // Per-unknown masks fixed at start(): 1 where the unknown is under error control / has a
  // derivative in G (velocities of an index-3 problem have one but no error control).
  Eigen::VectorXd errorMask_, differentialMask_;
  // 1 for velocity unknowns (their round-off grows with cj), 0 otherwise; 1 for positions; and
  // the floor built from them per attempt (withinRoundOff).
  Eigen::VectorXd velocityMask_, positionMask_, roundOffFloor_;
  Eigen::VectorXi rowExponent_, unknownExponent_;
  // Inverse tolerance weights of the current step, 1 / (ERROR (1 + |y_n,i|)), masked: for the
  // error test (error-controlled unknowns) and for the corrector's convergence test.
  Eigen::VectorXd errorWeight_, correctorWeight_;
  int consecutiveErrorFailures_ = 0;
  // The I3 velocity test (kVelocityTestSteps in the .cpp): 1 for velocities outside the
  // displacement error test; their weights kVelocityTestSteps h / (ERROR (1 + |v|)); whether
  // the problem has any; the last attempt's estimate, and whether it alone rejected the step.
  Eigen::VectorXd velocityTestMask_, velocityWeight_;
  bool velocityTested_ = false;
  // Velocities inside the displacement test (SI2): their estimate keeps the exact-history scale.
  bool controlledVelocities_ = false;
  double velocityError_ = 0.0;
  bool velocityRejected_ = false;
  // diagonal_[l] = y[t_n, ..., t_n-l], the divided differences through the newest l+1 accepted
  // solutions (l <= KMAX+2); previousDiagonal_ is the one of the step before (work storage).
  std::vector<Eigen::VectorXd> diagonal_, previousDiagonal_;
  std::vector<Eigen::VectorXd> equallySpaced_;  // fixed-coefficient history (GSTIFF)
  Eigen::VectorXd rowScale_, colScale_;
  double cjJacobian_ = 0.0;
  bool jacobianCurrent_ = false;
  bool haveJacobian_ = false;
  // The last step converged slowly on an older matrix (kRefreshRate in the .cpp): re-form it
  // at the next attempt.
  bool refreshNext_ = false;

  // Work vectors (no allocation in the step loop).
  Eigen::VectorXd yNew_, ypNew_, yPred_, base_, g_, dy_, predictorDiff_;
  // Sum of |change| over the iterations after the first, per unknown (widenForNoise).
  Eigen::VectorXd laterChanges_;
  int lastWorstEq_ = -1, lastWorstVar_ = -1;
  double lastWorstRes_ = 0.0, lastWorstChange_ = 0.0;
};

}  // namespace openmss::solvers
