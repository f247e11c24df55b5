// VTOSUB (VTORQUE with FUNCTION=USER) from a C-style user library (tests/user/element_routines.c,
// Vtosub: a torsional spring-damper through SYSFNC AZ and WZ): the same VTORQUE written with a
// TZ expression, and the closed form of the damped torsional oscillator it makes.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/bdf_run.hpp"

namespace openmss {
namespace {

// A body (Izz = 1, CM at the origin) on a revolute joint about z, spinning at 2 rad/s, held by
// the VTORQUE T_z = -5 AZ - 0.5 WZ.
std::string oscillator(const std::string& vtorque) {
  return "oscillator\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "MARKER/30, PART=1, FLOATING\nPART/2, MASS=1, CM=20, IP=1,1,1, WZ=2\n"
         "MARKER/20, PART=2\nJOINT/1, REVOLUTE, I=20, J=10\n"
         "VTORQUE/1, I=20, JFLOAT=30, RM=10, " +
         vtorque + "\nEND\n";
}

// The body's rotation about z from its Euler parameters.
double angle(const Eigen::VectorXd& y) {
  using L = mechanics::StateLayout;
  return 2.0 * std::atan2(y(L::kE + 3), y(L::kE));
}

// Expression and routine: the routine's partials are central differences of SYSFNC's exact
// values (error ~1e-10 relative), so the Newton iterates differ by a fraction of the corrector
// tolerance: asserted at 1e-8 (ERROR = 1e-9). The closed form theta = (2 / wd) e^(-t/4)
// sin(wd t), wd = sqrt(5 - 1/16): measured 8.8e-9, asserted at 1e-7 (ERROR 1e-9 per step).
TEST(VtorqueRoutine, VtosubMatchesTheExpressionAndTheClosedForm) {
  const std::string lib = OPENMSS_TEST_C_ROUTINES;
  const auto times = {0.25, 0.5, 1.0, 1.5};
  const test::Trajectory e = test::integrateModel(
      test::buildModelFromText(oscillator("TX=0, TY=0, TZ=-5*(AZ(20,10)-0)-0.5*WZ(20,10)"),
                               "v.adm"),
      times);
  const test::Trajectory u = test::integrateModel(
      test::buildModelFromText(
          oscillator("FUNCTION=USER(5, 0.5, 0, 20, 10), ROUTINE=\"" + lib + "::Vtosub\""), "v.adm"),
      times);
  ASSERT_EQ(e.states.size(), 4u);
  ASSERT_EQ(u.states.size(), 4u);
  const double wd = std::sqrt(5.0 - 1.0 / 16.0);
  size_t k = 0;
  double worst = 0.0, worstExact = 0.0;
  for (double t : times) {
    const double exact = 2.0 / wd * std::exp(-0.25 * t) * std::sin(wd * t);
    worst = std::max(worst, std::abs(angle(u.states[k]) - angle(e.states[k])));
    worstExact = std::max(worstExact, std::abs(angle(u.states[k]) - exact));
    ++k;
  }
  EXPECT_GT(std::abs(angle(u.states[1])), 0.3);  // it turned
  EXPECT_LE(worst, 1e-8);
  EXPECT_LE(worstExact, 1e-7);
  std::printf("VTOSUB: angle within %.2e of the TZ expression, %.2e of the closed form\n", worst,
              worstExact);
}

}  // namespace
}  // namespace openmss
