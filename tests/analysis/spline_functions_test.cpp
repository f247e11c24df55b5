// Spline functions inside analyses, through the library API at full precision:
//  * a MOTION driven by AKISPL(TIME, 0, id) on a revolute: the kinematic solution's angle,
//    angular velocity and angular acceleration equal the spline's value and first and second
//    derivatives (evaluated directly on the Spline object) to 1e-10 — the motion's time jet
//    carries the spline's exact derivatives and the solves are direct;
//  * a tabulated spring, SFORCE FUNCTION=CUBSPL(DM(i,j), 0, id), whose table samples the cubic
//    F(L) = -(k s + c s^3), s = L - L0: CUBSPL (not-a-knot) reproduces the cubic exactly, so the
//    static equilibrium must satisfy k s + c s^3 = m g, solved here independently by Newton to
//    1e-15; agreement 1e-8 (statics_test.cpp's tolerance and reasons).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/statics.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

void build(const std::string& text, model::Model& model) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "spline.adm", ds, d);
  ASSERT_TRUE(model::buildModel(ds, model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
}

TEST(SplineFunctions, AkimaMotionDrivesARevolute) {
  model::Model model;
  build(
      "spline motion\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1, QG=1,0,0\nMARKER/20, PART=2\nMARKER/21, PART=2, QP=0,0,0\n"
      "MARKER/22, PART=2, QP=-1,0,0\n"
      "JOINT/1, REVOLUTE, I=22, J=10\n"
      "MOTION/1, JOINT=1, ROTATION, FUNCTION=AKISPL(TIME, 0, 5)\n"
      "SPLINE/5, X=0, 0.4, 0.9, 1.3, 2.0, 2.6\n"
      ", Y=0, 0.3, 0.2, 0.9, 1.4, 1.1\n"
      "END\n",
      model);
  const Spline& spline = *model.splines.at(0).spline;
  mechanics::MultibodySystem system(model);
  Eigen::VectorXd y = system.initialState(), yp;
  mechanics::removeRedundantConstraints(system, y);
  const int o = system.layout().body(0);
  double worst = 0.0;
  for (int n = 0; n <= 30; ++n) {
    // Times between the knots and beyond the last one (parabolic extrapolation).
    const double t = 0.05 + 0.1 * n;
    ASSERT_TRUE(mechanics::assemblePositions(system, t, y, 1e-14, 30).converged) << t;
    mechanics::solveVelocities(system, t, y);
    ASSERT_TRUE(mechanics::solveAccelerations(system, t, y, yp)) << t;
    double d[5];
    spline.curveDerivatives(SplineMethod::Akima, 0, t, d);
    const Eigen::Vector4d e = y.segment<4>(o + StateLayout::kE);
    const double angle = 2.0 * std::atan2(e(3), e(0));
    const double wz = y(o + StateLayout::kW + 2);
    const double alpha = yp(o + StateLayout::kW + 2);
    EXPECT_NEAR(angle, d[0], 1e-10) << t;
    EXPECT_NEAR(wz, d[1], 1e-10) << t;
    EXPECT_NEAR(alpha, d[2], 1e-9) << t;
    // The CM (1 from the pin) follows the angle.
    EXPECT_NEAR(y(o + StateLayout::kR), std::cos(d[0]), 1e-10) << t;
    worst = std::max({worst, std::abs(angle - d[0]), std::abs(wz - d[1]), std::abs(alpha - d[2])});
  }
  std::printf("AKISPL motion: largest |angle, w, alpha - spline| = %.3g\n", worst);
}

TEST(SplineFunctions, TabulatedSpringStaticEquilibrium) {
  const double m = 2.0, g = 9.81, k = 100.0, c = 50.0, l0 = 1.0;
  std::string xs, ys;
  for (int i = 0; i <= 8; ++i) {
    const double length = 0.5 + 0.25 * i;
    const double s = length - l0;
    char buf[80];
    std::snprintf(buf, sizeof buf, "%s%.17g", i == 0 ? "" : ",", length);
    xs += buf;
    std::snprintf(buf, sizeof buf, "%s%.17g", i == 0 ? "" : ",", -(k * s + c * s * s * s));
    ys += buf;
  }
  model::Model model;
  build(
      "tabulated spring\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "MARKER/11, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,-1\nMARKER/20, PART=2\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
      "SFORCE/1, TRANSLATION, I=20, J=11, FUNCTION=CUBSPL(DM(20,11), 0, 7)\n"
      "SPLINE/7, X=" +
          xs + "\n, Y=" + ys + "\nACCGRAV/ KGRAV=-9.81\nEND\n",
      model);
  mechanics::MultibodySystem system(model);
  Eigen::VectorXd y = system.initialState();
  mechanics::removeRedundantConstraints(system, y);
  ASSERT_TRUE(mechanics::assemblePositions(system, 0.0, y, 1e-12, 25).converged);
  model::EquilibriumSettings settings;
  settings.error = 1e-12;
  settings.imbalance = 1e-10;
  const EquilibriumResult r = solveStaticEquilibrium(system, 0.0, y, settings);
  ASSERT_EQ(r.status, EquilibriumResult::Status::Converged);
  // Closed form: k s + c s^3 = m g by Newton.
  double s = m * g / k;
  for (int i = 0; i < 50; ++i) s -= (k * s + c * s * s * s - m * g) / (k + 3.0 * c * s * s);
  const double z = y(system.layout().body(0) + StateLayout::kR + 2);
  std::printf("tabulated spring: z = %.15f, closed form %.15f\n", z, -(l0 + s));
  EXPECT_NEAR(z, -(l0 + s), 1e-8);
}

}  // namespace
}  // namespace openmss::analysis
