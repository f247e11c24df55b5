// The general-function and conversion utilities a user routine calls (user/openmss_usersub.h),
// called directly: values against closed forms, derivatives (IORD 1, 2 and IMPACT's partials)
// against central differences, RCNVRT round trips and known rotations.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/rotation.hpp"
#include "user/openmss_usersub.h"

namespace {

// Central difference of f at x with step h: error h^2 |f'''| / 6 plus rounding eps |f| / h;
// h = 1e-5 on these O(1) smooth functions gives about 1e-10: asserted at 1e-7.
template <class F>
double slope(const F& f, double x, double h = 1e-5) {
  return (f(x + h) - f(x - h)) / (2 * h);
}

TEST(UtilitySubroutines, StepValueAndDerivativesMatchClosedFormAndDifferences) {
  int err = 1, compared = 0;
  auto step = [&](double x, int iord) {
    double v = 0.0;
    c_step(x, 1.0, 2.0, 3.0, 5.0, iord, &v, &err);
    EXPECT_EQ(err, 0);
    return v;
  };
  for (double x : {0.5, 1.3, 2.0, 2.7, 3.5}) {
    const double s = std::clamp((x - 1.0) / 2.0, 0.0, 1.0);
    EXPECT_NEAR(step(x, 0), 2.0 + 3.0 * s * s * (3 - 2 * s), 1e-15);
    EXPECT_NEAR(step(x, 1), slope([&](double y) { return step(y, 0); }, x), 1e-7);
    EXPECT_NEAR(step(x, 2), slope([&](double y) { return step(y, 1); }, x), 1e-7);
    compared += 3;
  }
  double v = 0.0;
  c_step(0.0, 1.0, 0.0, 1.0, 1.0, 0, &v, &err);  // x1 <= x0
  EXPECT_EQ(err, 1);
  EXPECT_EQ(compared, 15);
}

TEST(UtilitySubroutines, PolyChebyForcosAndShf) {
  int err = 1;
  const double a[3] = {1.0, -2.0, 0.5};
  double v = 0.0;
  c_poly(2.0, 0.5, a, 3, 0, &v, &err);  // 1 - 2 u + 0.5 u^2, u = 1.5
  EXPECT_NEAR(v, 1.0 - 3.0 + 0.5 * 2.25, 1e-15);
  c_poly(2.0, 0.5, a, 3, 1, &v, &err);  // -2 + u
  EXPECT_NEAR(v, -0.5, 1e-15);
  c_cheby(2.0, 0.5, a, 3, 0, &v, &err);  // 1 - 2 u + 0.5 (2 u^2 - 1)
  EXPECT_NEAR(v, 1.0 - 3.0 + 0.5 * (2 * 2.25 - 1), 1e-15);
  c_forcos(0.3, 0.0, 2.0, a, 3, 0, &v, &err);  // 1 - 2 cos(0.6) + 0.5 cos(1.2)
  EXPECT_NEAR(v, 1.0 - 2.0 * std::cos(0.6) + 0.5 * std::cos(1.2), 1e-15);
  c_shf(0.3, 0.1, 2.0, 3.0, 0.2, 1.0, 2, &v, &err);  // -a w^2 sin(w (x - x0) - phi)
  EXPECT_NEAR(v, -2.0 * 9.0 * std::sin(3.0 * 0.2 - 0.2), 1e-14);
  EXPECT_EQ(err, 0);
}

// HAVSIN, FORSIN and BISTOP (issue 18's list; the expression functions they share are tested in
// tests/expr): closed forms. HAVSIN h0 + (h1 - h0)/2 (1 - cos(pi (x - x0)/(x1 - x0))) and its
// slope; FORSIN a0 + sum a_j sin(j w (x - x0)); BISTOP zero inside the gap, k (x1 - x)^e +
// cmax |xdot| below it and -k (x - x2)^e - cmax xdot above it (past the STEP's width d).
TEST(UtilitySubroutines, HavsinForsinAndBistop) {
  int err = 1;
  double v = 0.0;
  c_havsin(1.5, 1.0, 3.0, 2.0, 5.0, 0, &v, &err);
  EXPECT_NEAR(v, 4.0, 1e-15);
  c_havsin(1.5, 1.0, 3.0, 2.0, 5.0, 1, &v, &err);
  EXPECT_NEAR(v, std::acos(-1.0), 1e-14);
  c_havsin(2.5, 1.0, 3.0, 2.0, 5.0, 0, &v, &err);
  EXPECT_EQ(v, 5.0);
  const double a[3] = {1.0, -2.0, 0.5};
  c_forsin(0.3, 0.0, 2.0, a, 3, 0, &v, &err);
  EXPECT_NEAR(v, 1.0 - 2.0 * std::sin(0.6) + 0.5 * std::sin(1.2), 1e-15);
  EXPECT_EQ(err, 0);
  double out[3] = {1.0, 1.0, 1.0};
  c_bistop(1.5, 0.3, 1.0, 2.0, 1e3, 1.5, 20.0, 0.1, 0, out, &err);
  EXPECT_EQ(out[0], 0.0);
  c_bistop(0.8, -0.3, 1.0, 2.0, 1e3, 1.5, 20.0, 0.1, 0, out, &err);
  EXPECT_NEAR(out[0], 1e3 * std::pow(0.2, 1.5) + 20.0 * 0.3, 1e-12);
  c_bistop(2.2, 0.3, 1.0, 2.0, 1e3, 1.5, 20.0, 0.1, 0, out, &err);
  EXPECT_NEAR(out[0], -1e3 * std::pow(0.2, 1.5) - 20.0 * 0.3, 1e-12);
  EXPECT_EQ(err, 0);
}

TEST(UtilitySubroutines, ImpactPartialsMatchCentralDifferences) {
  int err = 1, compared = 0;
  auto force = [&](double x, double v) {
    double out[3];
    c_impact(x, v, 1.0, 1e3, 1.5, 20.0, 0.1, 0, out, &err);
    return out[0];
  };
  for (double x : {0.8, 0.95}) {
    double out[3];
    c_impact(x, -0.3, 1.0, 1e3, 1.5, 20.0, 0.1, 0, out, &err);
    EXPECT_EQ(err, 0);
    // k (x1 - x)^e - STEP(x, x1 - d, cmax, x1, 0) xdot; the STEP is cmax = 20 at x = 0.8 and
    // halfway (10) at x = 0.95.
    const double damping = x < 0.9 ? 20.0 : 10.0;
    EXPECT_NEAR(out[0], 1e3 * std::pow(1.0 - x, 1.5) + damping * 0.3, 1e-12);
    const double dx = slope([&](double y) { return force(y, -0.3); }, x, 1e-7);
    const double dv = slope([&](double y) { return force(x, y); }, -0.3, 1e-7);
    EXPECT_NEAR(out[1], dx, 1e-5 * std::abs(dx));
    EXPECT_NEAR(out[2], dv, 1e-6 * (1 + std::abs(dv)));
    compared += 3;
  }
  EXPECT_EQ(compared, 6);
}

TEST(UtilitySubroutines, RcnvrtRoundTripsAndKnownRotations) {
  const double euler[3] = {0.3, 0.5, 0.7};
  double q[4], back[3], cosines[9], ypr[3], b123[3], again[9];
  int istat = 1;
  c_rcnvrt("EULER", euler, "EULPAR", q, &istat);
  ASSERT_EQ(istat, 0);
  c_rcnvrt("EULPAR", q, "EULER", back, &istat);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], euler[k], 1e-14);
  c_rcnvrt("EULER", euler, "COSINES", cosines, &istat);
  const Eigen::Matrix3d a = openmss::matrixFromEuler313(0.3, 0.5, 0.7);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(cosines[k], a(k % 3, k / 3), 1e-15);  // column-wise
  // A pure rotation about z by 0.4: psi = 0.4, yaw = 0.4.
  const double yaw[3] = {0.4, 0.0, 0.0};
  c_rcnvrt("EULER", yaw, "YPR", ypr, &istat);
  EXPECT_NEAR(ypr[0], 0.4, 1e-15);
  EXPECT_NEAR(ypr[1], 0.0, 1e-15);
  EXPECT_NEAR(ypr[2], 0.0, 1e-15);
  c_rcnvrt("COSINES", cosines, "B123", b123, &istat);
  c_rcnvrt("B123", b123, "COSINES", again, &istat);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(again[k], cosines[k], 1e-14);
  c_rcnvrt("EULER", euler, "NONSENSE", back, &istat);
  EXPECT_EQ(istat, 1);
}

extern "C" void tcnvrt_(const char* sys1, const double* coord1, const char* sys2, double* coord2,
                        int* istat, std::size_t lsys1, std::size_t lsys2);

// TCNVRT against points whose coordinates are known in every system, and round trips.
TEST(UtilitySubroutines, TcnvrtKnownPointsAndRoundTrips) {
  int istat = 1, compared = 0;
  // (1, 1, sqrt 2): r = sqrt 2, theta = pi/4; rho = 2, phi (from +z) = pi/4.
  const double p[3] = {1.0, 1.0, std::sqrt(2.0)};
  double cyl[3], sph[3], back[3];
  c_tcnvrt("CARTESIAN", p, "CYLINDRICAL", cyl, &istat);
  ASSERT_EQ(istat, 0);
  const double wantCyl[3] = {std::sqrt(2.0), std::atan(1.0), std::sqrt(2.0)};
  for (int k = 0; k < 3; ++k, ++compared) EXPECT_NEAR(cyl[k], wantCyl[k], 1e-15);
  c_tcnvrt("cartesian", p, "SPHERICAL", sph, &istat);  // names in any case
  ASSERT_EQ(istat, 0);
  const double wantSph[3] = {2.0, std::atan(1.0), std::atan(1.0)};
  for (int k = 0; k < 3; ++k, ++compared) EXPECT_NEAR(sph[k], wantSph[k], 1e-15);
  c_tcnvrt("SPHERICAL", sph, "CYLINDRICAL", back, &istat);
  for (int k = 0; k < 3; ++k, ++compared) EXPECT_NEAR(back[k], cyl[k], 1e-15);
  c_tcnvrt("CYLINDRICAL", cyl, "CARTESIAN", back, &istat);
  for (int k = 0; k < 3; ++k, ++compared) EXPECT_NEAR(back[k], p[k], 1e-15);
  // The gfortran name, as a FORTRAN 77 caller passes it: blank-padded CHARACTER arguments with
  // their lengths appended.
  double f77[3];
  tcnvrt_("CARTESIAN   ", p, "CYLINDRICAL ", f77, &istat, 12, 12);
  EXPECT_EQ(istat, 0);
  for (int k = 0; k < 3; ++k, ++compared) EXPECT_EQ(f77[k], cyl[k]);
  EXPECT_EQ(compared, 15);
  c_tcnvrt("POLAR", p, "CARTESIAN", back, &istat);
  EXPECT_EQ(istat, 1);
}

// TIMEGT is TIMGET; ANALYS, DATOUT, MODIFY outside CONSUB fail with istat 1.
TEST(UtilitySubroutines, TimegtAndTheConsubOnlyUtilities) {
  double a = -1.0, b = -2.0;
  c_timget(&a);
  c_timegt(&b);
  EXPECT_EQ(a, b);
  int istat = 0;
  c_analys("DYNAMICS", "run", 0.0, 1.0, 1, &istat);
  EXPECT_EQ(istat, 1);
  istat = 0;
  c_datout(&istat);
  EXPECT_EQ(istat, 1);
  istat = 0;
  c_modify("PART/1, MASS=10", &istat);
  EXPECT_EQ(istat, 1);
}

TEST(UtilitySubroutines, GetcpuIsDeterministic) {
  double t = 1.0;
  c_getcpu(&t);
  EXPECT_EQ(t, 0.0);
}

}  // namespace
