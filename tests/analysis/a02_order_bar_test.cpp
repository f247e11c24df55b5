// The BDF's stability-limit detection (docs/integrators.md, "Order selection and the stability
// limit") must not mistake the steps cut at a singular configuration for a stability limit
// (docs/integrators.md, "A rough solve is not a stability limit").
//
// Model: IFToMM A02 with N = 40 windows (bench/model_generators.cpp, docs/validation.md "IFToMM
// A02"), SI2 GSTIFF at ERROR = 1e-4, 11 s (11 flat passages). Truth: the exact motion is a
// smooth one-degree-of-freedom rotation, A phi'' = -g B cos phi, so no mode grows and the
// detection has nothing to find; and its energy A phi'^2 / 2 + g B sin phi is conserved.
// Before the fix the detection fired once, at t = 10.56 s, on a step cut by a corrector failure
// at the flat passage and by the noise of the solves accepted there; order 2 was then held for
// 50 steps and its damping took 5.5e-4 of the energy (measured: -6.7e-4 at 11 s; +5.1e-5 with
// the fix). The detection itself is not visible through the integrator interface; its effect,
// steps at order 2 long after the start-up, is (through the step observer).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "analysis/integrator_factory.hpp"
#include "analysis/multibody_dae.hpp"
#include "model_generators.hpp"
#include "solvers/integrator.hpp"
#include "support/integrator_test_models.hpp"

namespace {

using namespace openmss;

constexpr int kWindows = 40;
constexpr double kEnd = 11.0;
constexpr double kOutputStep = 0.05;  // the benchmark's 400 outputs per 20 s
// After the start-up (orders 1-2 over the first few milliseconds) the detection is what drops
// the order to 2 and holds it there; the error test alone lowers it one order per rejection.
constexpr double kStartUp = 0.5;

// Accepted steps taken at order 2 or below after the start-up.
struct LowOrderSteps {
  long count = 0;
  static void onStep(const solvers::StepInfo& info, void* self) {
    if (info.event == solvers::StepInfo::Event::Accepted && info.time > kStartUp && info.order <= 2)
      ++static_cast<LowOrderSteps*>(self)->count;
  }
};

TEST(A02OrderBar, FlatPassagesAreNotTakenForAStabilityLimit) {
  const auto mechanism = test::assemble(bench::fourBarChainAdm(kWindows));
  const mechanics::MultibodySystem& system = *mechanism->system;
  const Eigen::VectorXd& y = mechanism->y;

  model::IntegratorSettings settings;
  settings.type = model::IntegratorType::Gstiff;
  settings.formulation = model::IntegratorFormulation::Si2;
  settings.error = 1e-4;
  const analysis::IntegratorPlan plan = analysis::resolveIntegrator(settings, kOutputStep);
  analysis::MultibodyDae dae(system);
  auto integrator = analysis::makeIntegrator(plan, system, dae, kEnd);
  LowOrderSteps lowOrder;
  integrator->setStepObserver(&LowOrderSteps::onStep, &lowOrder);
  integrator->start(0.0, y, mechanism->yp);

  // The first rocker's angle rate from its centre about its pivot (the bench tool's reading).
  const int r0 = system.layout().body(0);
  const double pivot = y(r0);
  auto energy = [&](const Eigen::VectorXd& s) {
    const double n = kWindows, a = (n + 1) / 3.0 + n, b = (n + 1) * 0.5 + n;
    const double x = s(r0) - pivot, z = s(r0 + 1);
    const double rate = (x * s(r0 + 8) - z * s(r0 + 7)) / (x * x + z * z);
    return 0.5 * a * rate * rate + 9.81 * b * z / std::hypot(x, z);
  };
  const double e0 = energy(y);

  int flat = 0;
  double previousHeight = y(r0 + 1);
  const long outputs = std::lround(kEnd / kOutputStep);
  for (long i = 1; i <= outputs; ++i) {
    const double tout = kOutputStep * static_cast<double>(i);
    while (integrator->t() < tout - 1e-12 * tout)
      ASSERT_TRUE(integrator->step(tout)) << "at t = " << integrator->t();
    const double height = integrator->y()(r0 + 1);
    if ((height > 0) != (previousHeight > 0)) ++flat;
    previousHeight = height;
  }
  EXPECT_GE(flat, 11);
  // No mode grows in this motion: any detection is a misfire (before the rule: 50 steps at
  // order 2 after t = 10.56 s; with it, none).
  EXPECT_EQ(lowOrder.count, 0);
  // The energy's drift from the steps' truncation over the first five turns stays below 8e-5
  // of the energy (measured, docs/validation.md "IFToMM A02"); the misfire took 5.5e-4 at once.
  // 2e-4 separates them with a factor of 2.5 on each side.
  EXPECT_LT(std::abs(energy(integrator->y()) - e0) / e0, 2e-4);
}

}  // namespace
