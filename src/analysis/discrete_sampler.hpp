#pragma once
// Sampling of the GSEs' discrete states (docs/theory.md, "GSE"). Each GSE with ND > 0 is
// sampled at t_k+1 = t_k + T_k, t_0 = 0, with T_k from its GSE_SAMP routine or its
// SAMPLE_PERIOD at t_k. At a sample the integrator stops exactly there, every due GSE gets
// xd <- GSE_UPDATE(x, xd, u, t_k) (all from the values before any of them changes), the
// states that depend on xd are made consistent, and the integrator restarts. Between samples
// xd is constant; at a sample time the outputs already show the new value. xd and t_k live in
// the run state (mechanics/expression_run_state.hpp).

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

class DiscreteSampler {
 public:
  // `run` holds the discrete states and sample times; without it only active() is meaningful.
  explicit DiscreteSampler(const mechanics::MultibodySystem& system,
                           mechanics::ExpressionRunState* run = nullptr);

  bool active() const { return active_; }
  // The earliest next sample time of all GSEs (infinity when none).
  double nextTime() const;
  // Updates the GSEs due at t and makes (y, yp) consistent with the new discrete states.
  void sample(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) const;

 private:
  double nextTime(int k) const;
  const mechanics::MultibodySystem& system_;
  mechanics::ExpressionRunState* run_;
  bool active_ = false;
};

}  // namespace openmss::analysis
