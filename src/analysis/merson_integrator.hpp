#pragma once
// MERSON: the explicit Kutta-Merson 4(3) Runge-Kutta pair on the index-1 equations of motion
// (mechanics/index_one_dynamics.hpp; docs/integrators.md, "MERSON"; docs/theory.md §9d). An
// OpenMSS extension, not an ADAMS integrator. The ODE state is, per moving body, the CM
// position r, the Euler parameters e, the CM velocity v and the body angular velocity w; the
// multipliers (and mu = 0) come from the KKT solve of every evaluation. The state offered to
// the analyses (y, y') is the full DAE layout of mechanics/state_layout.hpp, so outputs,
// requests and reactions work unchanged.
//
// MERSON is for non-stiff models (pendulum chains, mechanisms without stiff bushings): each
// step costs five evaluations and no Jacobian, and the step is bounded by the stability of
// the fastest mode. The integrator estimates that mode and warns (warnings()) when the steps
// are held by it far below what accuracy alone would allow, naming the remedy (GSTIFF).

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "mechanics/index_one_dynamics.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

struct MersonSettings {
  // ERROR: each step's local error estimate, component by component over r, e, v and w, is
  // held to ERROR (1 + |x|) (the largest weighted component, as GSTIFF's norm).
  double error = 1e-3;
  double hinit = 0.0;  // first step; 0: ERROR^(1/5) / 100 (bounded by HMAX)
  double hmax = 0.0;   // 0 or infinity: no limit
  double hmin = 0.0;   // 0: 1e-12 (1 + |t|), the round-off floor
  // After each accepted step the state is projected onto the position and velocity
  // constraints when their largest violation exceeds this share of ERROR (0: every step).
  // Every step is the default: on the 100-link chains it cost no more evaluations than a
  // threshold of 0.1 ERROR and ended 3-20x closer to the reference (docs/integrators.md).
  double projectionShare = 0.0;
};

class MersonIntegrator final : public solvers::Integrator {
 public:
  MersonIntegrator(const mechanics::MultibodySystem& system, const MersonSettings& settings);
  ~MersonIntegrator() override;
  MersonIntegrator(const MersonIntegrator&) = delete;
  MersonIntegrator& operator=(const MersonIntegrator&) = delete;

  // y0, yp0: a consistent state (initial-condition analysis done). Also the restart after a
  // discontinuity: the step size starts again from HINIT.
  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool setNextStepSize(double h) override;
  bool step(double tout) override;

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  double previousTime() const override { return tPrevious_; }
  // Cubic Hermite in the ODE state from its values and slopes at both ends of the last step,
  // expanded to the full state by one evaluation (multipliers, accelerations).
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  // residualEvaluations counts every evaluation of the index-1 equations (stages, stiffness
  // estimates, interpolations); jacobianEvaluations counts 0: the method forms no Jacobian.
  const solvers::IntegratorStatistics& statistics() const override { return stats_; }
  const solvers::IntegratorFailure& failure() const override { return failure_; }

  std::vector<std::string> warnings() const override { return warnings_; }
  bool stiffnessDetected() const { return stiff_; }
  // Largest |eigenvalue| of the ODE Jacobian at the last estimate (1/s).
  double spectralRadius() const { return spectralRadius_; }
  long projections() const { return projections_; }
  long spectralEstimates() const { return spectralEstimates_; }
  // Of the last complete stiffness window (32 accepted steps): the mean step taken and the step
  // the motion would allow for accuracy alone (see merson_integrator.cpp, kAccuracyRoom).
  double heldStep() const { return heldStep_; }
  double accuracyStep() const { return accuracyStep_; }

 private:
  // x' = f(t, x) through the index-1 equations; false when the KKT matrix is singular.
  bool derivative(double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) const;
  void gather(const Eigen::VectorXd& y, Eigen::VectorXd& x) const;
  void scatter(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  bool acceptState(double t, const Eigen::VectorXd& x);
  void estimateSpectralRadius();
  void watchStiffness(double h);
  void restartStiffnessWindow();
  // The step the motion of the current (complete) window would allow for accuracy alone.
  double windowAccuracyStep() const;
  void recordFailure(const std::string& reason, double h, const Eigen::VectorXd* errors);

  const mechanics::MultibodySystem& system_;
  MersonSettings settings_;
  std::unique_ptr<mechanics::IndexOneDynamics> dynamics_;
  mutable solvers::IntegratorStatistics stats_;
  solvers::IntegratorFailure failure_;
  double t_ = 0.0, tPrevious_ = 0.0, h_ = 0.0;
  Eigen::VectorXd y_, yp_;
  // ODE state and slope at the end (x_, f_) and start (xPrevious_, fPrevious_) of the last step.
  Eigen::VectorXd x_, f_, xPrevious_, fPrevious_;
  // Stage work space.
  Eigen::VectorXd k2_, k3_, k4_, k5_, stage_, xNew_, errors_;
  mutable Eigen::VectorXd yWork_, ypWork_;
  long projections_ = 0;
  // Step-size control: the error estimate of the last accepted step (the PI controller's
  // err_{n-1}) and whether the last attempt was rejected.
  double previousError_ = 1.0;
  bool rejectedLast_ = false;
  // Stiffness watch (the rule: merson_integrator.cpp, kAccuracyRoom).
  double spectralRadius_ = 0.0;
  Eigen::VectorXd powerVector_;  // dominant direction of the last estimate (warm start)
  long spectralEstimates_ = 0;
  long stepsSinceEstimate_ = 0;
  // The current window of accepted steps: its sampled times and ODE states (every quarter).
  std::vector<double> windowTimes_;
  std::vector<Eigen::VectorXd> windowStates_;
  long windowSteps_ = 0;
  long windowHeldSteps_ = 0;  // steps so far held by stability (h rho >= kStiffStepRatio)
  double windowStepSum_ = 0.0;
  long stiffWindows_ = 0;                       // consecutive windows that meet the rule
  double accuracyStep_ = 0.0, heldStep_ = 0.0;  // of the last completed window
  bool stiff_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace openmss::analysis
