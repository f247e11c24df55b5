#pragma once
// From the INTEGRATOR settings (statement or command) to a running integrator: ADAMS's
// defaults resolved against the output step (docs/integrators.md, "Defaults"), the method
// chosen (GSTIFF, WSTIFF, HHT, NEWMARK from solvers/; DSTIFF from solvers/ida_integrator; ABAM
// and MERSON from analysis/abam_integrator and analysis/merson_integrator), the formulation
// (I3, or SI2 for the BDF family) and output interpolation. The dynamic driver
// (analysis/dynamic_run.cpp) talks to the result through solvers/integrator.hpp only; its
// state is always the I3 state of the MultibodySystem.

#include <memory>
#include <optional>
#include <string>

#include "mechanics/multibody_system.hpp"
#include "model/analysis_settings.hpp"
#include "solvers/dae_problem.hpp"
#include "solvers/integrator.hpp"
#include "solvers/pivot_order.hpp"

namespace openmss::analysis {

// The settings with every default resolved to a number.
struct IntegratorPlan {
  model::IntegratorType type = model::IntegratorType::Gstiff;
  model::IntegratorFormulation formulation = model::IntegratorFormulation::I3;
  double error = 1e-3, hinit = 0.0, hmin = 0.0, hmax = 0.0;
  int kmax = 6, maxit = 10;
  bool interpolate = false;
  double alpha = 0.0, beta = 0.25, gamma = 0.5;
  bool patternGiven = false;
  bool pattern[10] = {};
  bool modifiedCorrector = false;  // CORRECTOR=MODIFIED (GSTIFF, WSTIFF)
  double adaptivity = 0.0;         // ADAPTIVITY (GSTIFF, WSTIFF; 0: none)
  // Not from the settings: the run's pivot order (AnalysisContext::pivotOrder), GSTIFF,
  // WSTIFF and DSTIFF.
  solvers::PivotOrder pivotOrder = solvers::PivotOrder::Default;
};

// Why these settings cannot run here (nullopt when they can): a method without an
// implementation in this build.
std::optional<std::string> integratorUnavailable(const model::IntegratorSettings& settings);

// ADAMS's defaults for what the settings leave open, given the output step of the SIMULATE.
IntegratorPlan resolveIntegrator(const model::IntegratorSettings& settings, double outputStep);

// "GSTIFF I3", "HHT I3", ... as the .msg banner names the method.
std::string integratorBanner(const IntegratorPlan& plan);
// One .msg line with the parameters in effect.
std::string integratorParameters(const IntegratorPlan& plan);

// The integrator for `plan`, integrating `i3` (the system's index-3 DAE; the SI2 formulation
// builds its own problem on `system` and the result still presents the I3 state). `endTime`
// bounds the steps taken freely when the plan interpolates its outputs.
std::unique_ptr<solvers::Integrator> makeIntegrator(const IntegratorPlan& plan,
                                                    const mechanics::MultibodySystem& system,
                                                    solvers::DaeProblem& i3, double endTime);

}  // namespace openmss::analysis
