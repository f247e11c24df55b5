#pragma once
// ABAM: coordinate partitioning (mechanics/coordinate_partitioning.hpp) and CVODE's variable-
// order Adams-Bashforth-Moulton method on the independent positions and velocities
// (docs/integrators.md, "ABAM"). The state offered to the analyses (y, y') is the full DAE
// layout of mechanics/state_layout.hpp, recovered from the independent coordinates at every
// step, so that outputs, requests and reactions work unchanged.
//
// ABAM is for non-stiff models: the Adams step is bounded by the fastest mode. The integrator
// estimates the spectral radius of the reduced Jacobian and warns (warnings()) when the steps
// are held at the stability limit of that mode, naming the remedy (GSTIFF).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/coordinate_partitioning.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/bdf_integrator.hpp"
#include "solvers/integrator.hpp"
#include "solvers/multistep_settings.hpp"

namespace openmss::analysis {

// Settings: solvers::MultistepSettings; ERROR is relative and absolute, on independent positions
// and velocities; KMAX <= 12 (Adams).
class AbamIntegrator final : public solvers::Integrator {
 public:
  AbamIntegrator(const mechanics::MultibodySystem& system,
                 const solvers::MultistepSettings& settings);
  ~AbamIntegrator() override;
  AbamIntegrator(const AbamIntegrator&) = delete;
  AbamIntegrator& operator=(const AbamIntegrator&) = delete;

  // y0, yp0: a consistent state (initial-condition analysis done).
  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool step(double tout) override;

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  double previousTime() const override { return tPrevious_; }
  // CVODE's Adams interpolant of the independent coordinates, expanded to the full state.
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override;
  const solvers::IntegratorStatistics& statistics() const override { return stats_; }
  const solvers::IntegratorFailure& failure() const override { return failure_; }

  // Lines for the .msg (the stiffness warning); each appears once.
  std::vector<std::string> warnings() const override { return warnings_; }
  bool stiffnessDetected() const { return stiff_; }
  // Largest |eigenvalue| of the reduced Jacobian at the last estimate (1/s).
  double spectralRadius() const { return spectralRadius_; }
  int partitions() const { return partitions_; }
  const mechanics::CoordinatePartitioning& partitioning() const { return partitioning_; }

  struct Engine;  // CVODE objects and callbacks (abam_integrator.cpp)

 private:
  bool restart();  // partitions at (t_, y_) and starts CVODE afresh
  void estimateSpectralRadius();
  void watchStiffness(double h);
  void readStatistics();
  void recordFailure(const std::string& reason, double h);

  const mechanics::MultibodySystem& system_;
  solvers::MultistepSettings settings_;
  mechanics::CoordinatePartitioning partitioning_;
  std::unique_ptr<Engine> engine_;
  solvers::IntegratorStatistics stats_, earlier_;  // earlier_: solvers before the last restart
  solvers::IntegratorFailure failure_;
  double t_ = 0.0, tPrevious_ = 0.0;
  Eigen::VectorXd y_, yp_;
  bool repartitionPending_ = false;
  int partitions_ = 0;
  // Stiffness watch.
  double spectralRadius_ = 0.0;
  long stepsSinceEstimate_ = 0;
  long stiffSteps_ = 0;
  bool stiff_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace openmss::analysis
