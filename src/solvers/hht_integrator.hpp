#pragma once
// HHT and NEWMARK: the Newmark family for index-3 mechanical DAEs (docs/integrators.md, "HHT
// and NEWMARK"), in the manner of Negrut, Rampalli, Ottarsson and Sajdak's HHT-I3: positions
// follow Newmark's beta rule, velocities the gamma rule, the force balance is evaluated
// (1 + alpha) at the new step and -alpha at the old one (HHT's alpha shift), and the
// position constraints hold exactly at every step. The unknowns' roles (position, velocity,
// multiplier) come from DaeProblem::role; a first-order state (DIFF) follows the gamma rule.
// ALPHA = 0 with BETA, GAMMA free is NEWMARK. Step size from the position truncation error
// (beta - 1/6) h^3 q''' and the I3 velocity test (the gamma rule's velocity truncation error
// weighed as the displacement it makes over two steps, docs/integrators.md "HHT's velocity
// test"), steps landing on output times, modified Newton on the corrector.

#include <Eigen/Dense>
#include <limits>

#include "solvers/dae_problem.hpp"
#include "solvers/integrator.hpp"
#include "solvers/klu_linear_solver.hpp"
#include "solvers/nonzero_pattern.hpp"

namespace openmss::solvers {

struct HhtSettings {
  double error = 1e-3;  // ERROR: local error tolerance (relative and absolute; positions, and
                        // velocities through the I3 velocity test)
  double hinit = 0.0;   // HINIT (0: HMAX / 100)
  double hmax = std::numeric_limits<double>::infinity();  // HMAX
  double hmin = 0.0;          // HMIN: smallest step before the run fails (0: 1e-10 HMAX)
  int maxit = 10;             // MAXIT: corrector iterations per attempt
  double alpha = -0.3;        // ALPHA in [-1/3, 0]
  double beta = 0.4225;       // (1 - alpha)^2 / 4 for HHT
  double gamma = 0.8;         // (1 - 2 alpha) / 2 for HHT
  bool patternGiven = false;  // PATTERN, as in MultistepSettings
  bool pattern[10] = {true, false, false, false, true, false, false, false, true, false};

  // HHT's beta and gamma for a given alpha (second order, unconditionally stable).
  static HhtSettings hht(double alpha) {
    HhtSettings s;
    s.alpha = alpha;
    s.beta = (1.0 - alpha) * (1.0 - alpha) / 4.0;
    s.gamma = (1.0 - 2.0 * alpha) / 2.0;
    return s;
  }
};

class HhtIntegrator final : public Integrator {
 public:
  HhtIntegrator(DaeProblem& problem, const HhtSettings& settings);

  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool step(double tout) override;

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  double previousTime() const override { return tPrevious_; }
  // Cubic Hermite through the step's end values and derivatives (linear for multipliers).
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  const IntegratorStatistics& statistics() const override { return stats_; }
  const IntegratorFailure& failure() const override { return failure_; }
  // "KLU" when the run solves its Newton matrix sparse (problems that offer one, with at least
  // BdfIntegrator::kSparseThreshold unknowns, as the BDF family), else "dense LU".
  const char* linearSolverName() const { return sparse_ ? klu_.name() : "dense LU"; }

 private:
  bool attemptStep(double h, bool* newtonFailed, double* errorNorm);
  void formNewtonMatrix(double tNew, double h);
  // The same matrix on the problem's sparse pattern, factorised by KLU (formNewtonMatrix's
  // sparse branch; docs/theory.md, "Sparse Newton matrix").
  void formSparseNewtonMatrix(double tNew);
  // Overwrites x with the solution of the last factorised (scaled) Newton matrix.
  void solveNewton(Eigen::VectorXd& x);
  double weightedNorm(const Eigen::VectorXd& v, const Eigen::VectorXd& ref, bool errorOnly) const;
  void noteWorst(const Eigen::VectorXd& g, const Eigen::VectorXd& dy);

  DaeProblem& problem_;
  HhtSettings settings_;
  IntegratorStatistics stats_;
  IntegratorFailure failure_;
  Eigen::VectorXi role_;  // DaeProblem::Role of each unknown

  double t_ = 0.0, tPrevious_ = 0.0, h_ = 0.0;
  Eigen::VectorXd y_, yp_, acc_;  // acc_: q'' of positions (Newmark's acceleration)
  Eigen::VectorXd yPrev_, ypPrev_;
  // The state step() started from, the last one handed to the caller: a step whose corrector
  // stalled along a near-null direction is not handed over, and when no step can leave its
  // end, the method returns here and steps across (step(); docs/integrators.md, "Stepping
  // across a singular instant").
  Eigen::VectorXd yEntry_, ypEntry_, accEntry_;
  bool stalledMove_ = false;  // the last solve was accepted by a stall rule, changes not small

  Eigen::MatrixXd jac_, jacB_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  // Sparse: A = dG/dy (sparseA_) and A + B (sparseJac_, then the Newton matrix itself), on
  // the problem's pattern, factorised by klu_ with its pivots reused while they serve.
  bool sparse_ = false;
  Eigen::SparseMatrix<double> sparseA_, sparseJac_;
  NonzeroPattern nonzero_;  // the entries of sparseJac_ factorised
  KluLinearSolver klu_;
  Eigen::VectorXd rowScale_, colScale_, slope_;
  double hJacobian_ = 0.0;
  bool haveJacobian_ = false, jacobianCurrent_ = false;
  bool refreshNext_ = false;  // the last step converged slowly on an older matrix

  Eigen::VectorXd yNew_, ypNew_, yPred_, ypPred_, g_, gOld_, gOldPred_, dy_;
  int lastWorstEq_ = -1, lastWorstVar_ = -1;
  double lastWorstRes_ = 0.0, lastWorstChange_ = 0.0;
};

}  // namespace openmss::solvers
