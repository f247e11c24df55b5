// The index-3 pendulum of the DAE test sets (Hairer/Wanner; Brenan, Campbell, Petzold): a unit
// mass on a massless rod of unit length pivoted at the origin, gravity 1 along -y, released at
// (1, 0) with velocity (0, 1). Reference position at t = 1 from the test set:
// x = 0.867348640604551746, y = 0.497701050476373918.
// The rod is a revolute joint; the body's own inertia is 1e-10 so that it behaves as a point
// mass (it shifts x(1) by about 1e-10, far below the tolerances asserted).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/integrator_factory.hpp"
#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::analysis {
namespace {

constexpr double kX1 = 0.867348640604551746;
constexpr double kY1 = 0.497701050476373918;

const char* kDataSet =
    "DAE test-set pendulum\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1e-10,1e-10,1e-10, VX=0, VY=1, VZ=0\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-1\n"
    "END\n";

struct Outcome {
  double x, y;
  long steps;
};

Outcome integrate(double error, double hmax) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kDataSet, "pendulum.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::removeRedundantConstraints(s, y);
  EXPECT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-12, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  MultibodyDae dae(s);
  solvers::MultistepSettings settings;
  settings.error = error;
  settings.hmax = hmax;
  settings.hinit = 1e-4;
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, y, yp);
  EXPECT_TRUE(bdf.advanceTo(1.0)) << bdf.failure().reason;
  return {bdf.y()(0), bdf.y()(1), bdf.statistics().steps};
}

TEST(DaePendulum, MatchesTheTestSetAtTightTolerance) {
  const Outcome o = integrate(1e-8, 0.1);
  std::printf("ERROR=1e-8: x(1) error %.2e, y(1) error %.2e, %ld steps\n", o.x - kX1, o.y - kY1,
              o.steps);
  EXPECT_NEAR(o.x, kX1, 1e-6);
  EXPECT_NEAR(o.y, kY1, 1e-6);
}

// MultistepSettings::error bounds the local error of each step; the global error at t = 1 is their
// accumulation over the ~20 steps taken, measured at 2.2e-3. Bounded here by 5 x ERROR. A run's
// ERROR (INTEGRATOR/ERROR=) goes through the factory, which holds each step to a tenth of it:
// PendulumByIntegrator below checks the global error against ERROR itself.
TEST(DaePendulum, StaysNearTheRequestedErrorAtLooseTolerance) {
  const Outcome o = integrate(1e-3, 0.1);
  std::printf("ERROR=1e-3: x(1) error %.2e, y(1) error %.2e, %ld steps\n", o.x - kX1, o.y - kY1,
              o.steps);
  EXPECT_NEAR(o.x, kX1, 5e-3);
  EXPECT_NEAR(o.y, kY1, 5e-3);
}

// The local tolerance bounds each step's error; their accumulation over the ~25 steps is bounded
// by 5 x the tolerance, as in StaysNearTheRequestedErrorAtLooseTolerance. Measured: 3.8e-4 at
// 1e-4 and 1.9e-7 at 1e-7 with the I3 velocity test (docs/integrators.md); 6.9e-5 and 7.0e-7
// without it (20 and 44 steps).
TEST(DaePendulum, ConvergesAsTheToleranceTightens) {
  const Outcome o4 = integrate(1e-4, 0.1), o7 = integrate(1e-7, 0.1);
  const double e4 = std::hypot(o4.x - kX1, o4.y - kY1);
  const double e7 = std::hypot(o7.x - kX1, o7.y - kY1);
  std::printf("global error at ERROR=1e-4: %.2e, at ERROR=1e-7: %.2e\n", e4, e7);
  EXPECT_LT(e4, 5e-4);
  EXPECT_LT(e7, 1e-5);
  EXPECT_LT(e7, e4 / 10.0);
}

// Every BDF integrator and formulation through the INTEGRATOR factory, as a run would make
// them (HMAX = 0.1, HINIT = 1e-4 given).
struct Variant {
  model::IntegratorType type;
  model::IntegratorFormulation formulation;
};

Outcome integrateWith(const Variant& v, double error) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kDataSet, "pendulum.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::removeRedundantConstraints(s, y);
  EXPECT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-12, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  MultibodyDae dae(s);
  model::IntegratorSettings settings;
  settings.type = v.type;
  settings.formulation = v.formulation;
  settings.error = error;
  settings.hmax = 0.1;
  settings.hinit = 1e-4;
  EXPECT_FALSE(integratorUnavailable(settings).has_value());
  const auto integrator = makeIntegrator(resolveIntegrator(settings, 0.1), s, dae, 1.0);
  integrator->start(0.0, y, yp);
  EXPECT_TRUE(integrator->advanceTo(1.0)) << integrator->failure().reason;
  return {integrator->y()(0), integrator->y()(1), integrator->statistics().steps};
}

class PendulumByIntegrator : public ::testing::TestWithParam<Variant> {};

TEST_P(PendulumByIntegrator, MatchesTheTestSetAtTightAndLooseTolerance) {
  const Variant v = GetParam();
  for (const double error : {1e-8, 1e-3}) {
    const Outcome o = integrateWith(v, error);
    const double bound = error == 1e-8 ? 1e-6 : error;
    std::printf("%s %s ERROR=%g: x(1) error %.2e, y(1) error %.2e, %ld steps\n",
                model::integratorTypeName(v.type), model::formulationName(v.formulation), error,
                o.x - kX1, o.y - kY1, o.steps);
    EXPECT_NEAR(o.x, kX1, bound) << "ERROR=" << error;
    EXPECT_NEAR(o.y, kY1, bound) << "ERROR=" << error;
  }
}

using IT = model::IntegratorType;
using IF = model::IntegratorFormulation;
INSTANTIATE_TEST_SUITE_P(
    BdfFamily, PendulumByIntegrator,
    ::testing::Values(Variant{IT::Gstiff, IF::I3}, Variant{IT::Wstiff, IF::I3},
                      Variant{IT::Gstiff, IF::Si2}, Variant{IT::Wstiff, IF::Si2}),
    [](const ::testing::TestParamInfo<Variant>& p) {
      return std::string(model::integratorTypeName(p.param.type)) + "_" +
             model::formulationName(p.param.formulation);
    });

}  // namespace
}  // namespace openmss::analysis
