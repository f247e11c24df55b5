#pragma once
// An integrator seen through the expression run state: every accepted step and every (re)start
// records the accepted state in the run state (mechanics/expression_run_state.hpp), so the
// cumulative angles and DELAY histories follow exactly the states the method accepts, whatever
// drives it (output grid, SENSOR events, GSE sample restarts). Rejected steps and corrector
// iterations happen inside the wrapped step() and never reach the run state.

#include <string>
#include <vector>

#include "mechanics/expression_run_state.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

class RunStateIntegrator final : public solvers::Integrator {
 public:
  RunStateIntegrator(solvers::Integrator& inner, mechanics::ExpressionRunState& run,
                     const mechanics::MultibodySystem& system)
      : inner_(inner), run_(run), system_(system) {}

  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override {
    inner_.start(t0, y0, yp0);
    record();
  }
  bool setNextStepSize(double h) override { return inner_.setNextStepSize(h); }
  // A step that leaves a PTCV point or a CVCV contact past an OPEN curve's end is accepted
  // and then reported as the run's failure (ADAMS stops there too; docs/theory.md §5d).
  bool step(double tout) override {
    if (!inner_.step(tout)) return false;
    record();
    if (!run_.curveRunOff().empty()) {
      runOff_ = inner_.failure();
      runOff_.time = inner_.t();
      runOff_.reason = run_.curveRunOff();
      runOff_.worstEquation = runOff_.worstVariable = -1;
      return false;
    }
    return true;
  }
  double t() const override { return inner_.t(); }
  const Eigen::VectorXd& y() const override { return inner_.y(); }
  const Eigen::VectorXd& yp() const override { return inner_.yp(); }
  double previousTime() const override { return inner_.previousTime(); }
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override {
    inner_.interpolate(s, y, yp);
  }
  const solvers::IntegratorStatistics& statistics() const override { return inner_.statistics(); }
  const solvers::IntegratorFailure& failure() const override {
    return runOff_.reason.empty() ? inner_.failure() : runOff_;
  }
  std::vector<std::string> warnings() const override { return inner_.warnings(); }

 private:
  void record() { run_.accept(system_, inner_.t(), inner_.y(), inner_.yp()); }

  solvers::Integrator& inner_;
  mechanics::ExpressionRunState& run_;
  const mechanics::MultibodySystem& system_;
  solvers::IntegratorFailure runOff_;  // set once a curve run-off ends the run
};

}  // namespace openmss::analysis
