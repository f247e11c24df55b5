// INTEGRATOR/ADAPTIVITY=r (docs/integrators.md, "ADAPTIVITY"): as ADAMS defines it, r / h is
// added to the corrector's tolerance of GSTIFF and WSTIFF at a step h, so the corrector stops
// earlier, the more so at small steps; the other integrators run as without it, with a warning.
// Truth: the DAE test-set pendulum (dae_pendulum_test.cpp; reference x(1), y(1) from the test
// set), with GSTIFF (fixed coefficients) and WSTIFF at the local tolerance 1e-6, about 75 steps
// of 0.013 s, so r / h is about 0.75 (r = 1e-8) and 7.5 (r = 1e-7) local tolerances:
//   * ADAPTIVITY takes effect: the corrector needs fewer residual evaluations per step (measured
//     3.60 / 2.33 / 2.01 with GSTIFF and 3.97 / 2.37 / 2.11 with WSTIFF at r = 0, 1e-8, 1e-7);
//   * a small ADAPTIVITY, as ADAMS advises (1e-8 to start with), keeps the answer: the runs
//     without it end 5.8e-5 (GSTIFF) and 5.7e-5 (WSTIFF) from the reference in y, and r = 1e-8
//     moves that by 5e-7 (measured); asserted: all within 1e-4 of the reference and r = 1e-8
//     within 5e-6 of r = 0 (ten times the measured change, a twelfth of the global error).
// And the statement and the plan: accepted with a positive value on GSTIFF and WSTIFF, an
// error at its column for a value <= 0, a warning on HHT (no effect), the .msg parameter line.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/integrator_factory.hpp"
#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/integrator_test_models.hpp"

namespace openmss::analysis {
namespace {

using test::kPendulum;
constexpr double kX1 = test::kPendulumX1;
constexpr double kY1 = test::kPendulumY1;
constexpr double kLocalError = 1e-6;

using Outcome = test::PendulumOutcome;

Outcome integrate(bool fixedCoefficients, double adaptivity) {
  solvers::MultistepSettings settings;
  settings.error = kLocalError;
  settings.hmax = 0.1;
  settings.hinit = 1e-4;
  settings.fixedCoefficients = fixedCoefficients;
  settings.adaptivity = adaptivity;
  return test::integratePendulum(settings);
}

double perStep(const Outcome& o) {
  return static_cast<double>(o.residuals) / static_cast<double>(o.steps);
}

TEST(Adaptivity, LoosensTheCorrectorAndKeepsTheAnswerWhenSmall) {
  int compared = 0;
  for (const bool gstiff : {true, false}) {
    const char* name = gstiff ? "GSTIFF" : "WSTIFF";
    const Outcome none = integrate(gstiff, 0.0);
    const Outcome small = integrate(gstiff, 1e-8);
    const Outcome large = integrate(gstiff, 1e-7);
    std::printf(
        "%s local ERROR 1e-6: ADAPTIVITY 0 / 1e-8 / 1e-7: residual evaluations per step "
        "%.3f / %.3f / %.3f (%ld / %ld / %ld steps); y(1) error %.2e / %.2e / %.2e\n",
        name, perStep(none), perStep(small), perStep(large), none.steps, small.steps, large.steps,
        none.y - kY1, small.y - kY1, large.y - kY1);
    EXPECT_LT(perStep(small), perStep(none)) << name;
    EXPECT_LT(perStep(large), perStep(small)) << name;
    for (const Outcome* o : {&none, &small, &large}) {
      EXPECT_NEAR(o->x, kX1, 1e-4) << name;
      EXPECT_NEAR(o->y, kY1, 1e-4) << name;
    }
    EXPECT_NEAR(small.x, none.x, 5e-6) << name;
    EXPECT_NEAR(small.y, none.y, 5e-6) << name;
    compared += 2;
  }
  EXPECT_EQ(compared, 4);
}

std::string errorsOf(const std::string& integrator, model::Model& m, std::string* warnings) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(test::beforeEnd(kPendulum, integrator + "\n"), "p.adm", ds, d);
  model::buildModel(ds, m, d);
  std::string errors;
  for (const auto& x : d.all()) {
    if (x.severity == Severity::Error) errors += format(x) + "\n";
    if (x.severity == Severity::Warning && warnings) *warnings += format(x) + "\n";
  }
  return errors;
}

TEST(Adaptivity, TheStatementAndThePlan) {
  model::Model gstiff, wstiff, zero, hht;
  std::string warnings;
  EXPECT_EQ(errorsOf("INTEGRATOR/GSTIFF, ADAPTIVITY=1E-8", gstiff, &warnings), "");
  ASSERT_TRUE(gstiff.integrator.adaptivity.has_value());
  EXPECT_EQ(*gstiff.integrator.adaptivity, 1e-8);
  EXPECT_EQ(errorsOf("INTEGRATOR/WSTIFF, SI2, ADAPTIVITY=2E-9", wstiff, &warnings), "");
  EXPECT_EQ(warnings, "");
  const std::string refused = errorsOf("INTEGRATOR/GSTIFF, ADAPTIVITY=0", zero, nullptr);
  EXPECT_NE(refused.find("p.adm:10:20: error: INTEGRATOR"), std::string::npos) << refused;
  EXPECT_NE(refused.find("ADAPTIVITY"), std::string::npos) << refused;
  EXPECT_EQ(errorsOf("INTEGRATOR/HHT, ADAPTIVITY=1E-8", hht, &warnings), "");
  EXPECT_NE(warnings.find("p.adm:10:17: warning: INTEGRATOR: ADAPTIVITY loosens the corrector "
                          "of GSTIFF and WSTIFF only; it has no effect on HHT"),
            std::string::npos)
      << warnings;

  const IntegratorPlan bdf = resolveIntegrator(gstiff.integrator, 0.01);
  EXPECT_EQ(bdf.adaptivity, 1e-8);
  EXPECT_NE(integratorParameters(bdf).find(", ADAPTIVITY = 1e-08"), std::string::npos)
      << integratorParameters(bdf);
  const IntegratorPlan other = resolveIntegrator(hht.integrator, 0.01);
  EXPECT_EQ(other.adaptivity, 0.0);
  EXPECT_EQ(integratorParameters(other).find("ADAPTIVITY"), std::string::npos);
}

}  // namespace
}  // namespace openmss::analysis
