// A pendulum built from two GCONs (docs/theory.md §5c) integrated by the dynamic analysis:
// DX**2 + DY**2 - L**2 = 0 keeps a point mass at distance L from the pivot and DZ = 0 in the
// plane. Released from rest at angle a0, its quarter period is sqrt(L/g) K(sin(a0/2)) (K the
// complete elliptic integral of the first kind) and the constraint force at the bottom is
// m g (3 - 2 cos a0) towards the pivot. Both are closed forms independent of the solver.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return std::numbers::pi / (2.0 * a);
}

TEST(GconPendulum, QuarterPeriodAndBottomTensionMatchClosedForms) {
  const double length = 2.0, g = 9.80665, a0 = 0.3, mass = 1.5;
  char text[1024];
  std::snprintf(text, sizeof text,
                "pendulum by GCON\n"
                "PART/1, GROUND\n"
                "MARKER/10, PART=1\n"
                "PART/2, MASS=%.17g, CM=20, IP=0.1,0.2,0.3\n"
                "MARKER/20, PART=2, QP=%.17g,%.17g,0\n"
                "GCON/1, I=20, FUNCTION=DX(20,10)**2+DY(20,10)**2-%.17g\n"
                "GCON/2, I=20, FUNCTION=DZ(20,10)\n"
                "ACCGRAV/ JGRAV=-9.80665\n"
                "END\n",
                mass, length * std::sin(a0), -length * std::cos(a0), length * length);
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "gp.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  ASSERT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-12, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  ASSERT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  MultibodyDae dae(s);
  solvers::MultistepSettings settings;
  settings.error = 1e-8;
  settings.hmax = 1e-3;
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, y, yp);
  const double quarter = std::sqrt(length / g) * ellipticK(std::sin(0.5 * a0));
  const double dt = 1e-3;
  double previousX = y(StateLayout::kR), previousT = 0.0, crossing = -1.0, tension = 0.0;
  for (int k = 1; k <= 1000 && crossing < 0.0; ++k) {
    ASSERT_TRUE(bdf.advanceTo(dt * k)) << bdf.failure().reason;
    const double x = bdf.y()(StateLayout::kR);
    if (previousX > 0.0 && x <= 0.0) {
      // x'' vanishes at the bottom, so linear interpolation errs by O(dt^3).
      crossing = previousT + dt * previousX / (previousX - x);
      Eigen::Vector3d force, torque;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int e = 0; e < 2; ++e) {
        s.elementReaction(mechanics::MultibodySystem::ConstraintElement::Gcon, e,
                          m.gcons[e].iMarker, bdf.y().data(), force, torque);
        sum += force;
      }
      // Near the bottom the tension is flat in the angle (dT/da = 0): the sample a fraction
      // of a step away from it is within ~1e-7 relative.
      tension = sum.y();
      EXPECT_NEAR(sum.x(), 0.0, 2e-3 * mass * g);
    }
    previousX = x;
    previousT = dt * k;
  }
  ASSERT_GT(crossing, 0.0);
  const double expectedTension = mass * g * (3.0 - 2.0 * std::cos(a0));
  std::printf("quarter period %.9f s (closed form %.9f, rel. error %.1e); bottom tension %.6f N "
              "(closed form %.6f)\n",
              crossing, quarter, std::abs(crossing - quarter) / quarter, tension,
              expectedTension);
  // At ERROR = 1e-8 the BDF phase error over a quarter period is far below 1e-6 relative.
  EXPECT_NEAR(crossing, quarter, 1e-6 * quarter);
  EXPECT_NEAR(tension, expectedTension, 1e-5 * expectedTension);
}

}  // namespace
}  // namespace openmss::analysis
