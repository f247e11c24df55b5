// NFORCE (docs/theory.md §6b) against closed forms:
//   (a) a one-I-marker NFORCE with K_zz = 8 and LENGTH z = 1 is the spring -8 (z - 1): a 2 kg
//       slider oscillates at 2 rad/s;
//   (b) a two-I-marker NFORCE coupling two 1 kg sliders as the chain ground-k-m-k-m (k = 8),
//       started in its first normal mode, moves at w1^2 = 4 (3 - sqrt 5); its read-backs
//       NFORCE(id, marker, 4, 0) at both I markers and at J equal -K (q - L) computed by hand
//       (J: minus their sum), and REQUEST FORCE between each I marker and J the same;
//   (c) its Newton matrix against central differences, nonzeros inside the pattern;
//   (d) wrong MATRIX sizes and markers are refused at the statement.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/request_values.hpp"
#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "model/model_builder.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

model::Model build(const std::string& text) { return test::buildModelFromText(text, "nf.adm"); }

TEST(NForce, OneMarkerNForceIsASpring) {
  const model::Model m = build(
      "nforce spring\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,1.5\nMARKER/20, PART=2\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
      "MATRIX/1, SPARSE, ROWS=6, COLUMNS=6, I=3, J=3, VALUES=8\n"
      "MATRIX/2, SPARSE, ROWS=6, COLUMNS=1, I=3, J=1, VALUES=1\n"
      "NFORCE/1, IMARKERS=20, J=10, KMATRIX=1, LENGTH=2\n"
      "VARIABLE/1, FUNCTION=NFORCE(1,20,4,0)\n"
      "END\n");
  ASSERT_EQ(m.nforces.size(), 1u);
  test::BdfRun run(m, 1e-9, 0.01, true);
  run.start();
  double worst = 0.0;
  int outputs = 0;
  for (double t = 0.5; t <= 4.0 + 1e-9; t += 0.5) {
    run.advanceTo(t);
    ++outputs;
    const double z = run.body(0, StateLayout::kR + 2);
    EXPECT_NEAR(run.variable(0), -8.0 * (z - 1.0), 1e-11) << t;  // K (x - L), by hand
    // BDF at ERROR = 1e-9 over 4 s (1.3 periods): asserted 1e-6.
    EXPECT_NEAR(z, 1.0 + 0.5 * std::cos(2.0 * t), 1e-6) << t;
    worst = std::max(worst, std::abs(z - 1.0 - 0.5 * std::cos(2.0 * t)));
  }
  EXPECT_EQ(outputs, 8);
  std::printf("NFORCE spring: largest |z - (1 + 0.5 cos 2t)| over 4 s = %.2e\n", worst);
}

// Two 1 kg sliders on vertical translational joints, z20 = 1 + u1, z30 = 2 + u2, and one NFORCE
// (J = ground marker 10) with K = 8 [[2, -1], [-1, 1]] on (z20, z30): the chain
// ground-k-m1-k-m2. First mode: w1^2 = 4 (3 - sqrt 5), shape (1, (1 + sqrt 5) / 2).
std::string chainModel() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0, a = 0.1;
  char text[2048];
  std::snprintf(text, sizeof text,
                "nforce chain\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
                "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0,0,%.15g\nMARKER/20, PART=2\n"
                "PART/3, MASS=1, CM=30, IP=1,1,1, QG=0,0,%.15g\nMARKER/30, PART=3\n"
                "JOINT/1, TRANSLATIONAL, I=20, J=10\nJOINT/2, TRANSLATIONAL, I=30, J=10\n"
                "MATRIX/1, SPARSE, ROWS=12, COLUMNS=12, I=3,3,9,9, J=3,9,3,9, VALUES=16,-8,-8,8\n"
                "MATRIX/2, SPARSE, ROWS=12, COLUMNS=1, I=3,9, J=1,1, VALUES=1,2\n"
                "MATRIX/3, SPARSE, ROWS=12, COLUMNS=12, I=3,9, J=3,9, VALUES=0.01,0.01\n"
                "NFORCE/1, IMARKERS=20,30, J=10, KMATRIX=1, LENGTH=2\n"
                "VARIABLE/1, FUNCTION=NFORCE(1,20,4,0)\n"
                "VARIABLE/2, FUNCTION=NFORCE(1,30,4,0)\n"
                "VARIABLE/3, FUNCTION=NFORCE(1,10,4,0)\n"
                "VARIABLE/4, FUNCTION=FZ(30)\n"
                "REQUEST/1, FORCE, I=20, J=10\nREQUEST/2, FORCE, I=30, J=10\n"
                "END\n",
                1.0 + a, 2.0 + a * phi);
  return text;
}

TEST(NForce, ChainMovesInItsNormalModeAndReadsBackKTimesDisplacement) {
  const model::Model m = build(chainModel());
  test::BdfRun run(m, 1e-9, 0.01, true);
  run.start();
  const double w1 = std::sqrt(4.0 * (3.0 - std::sqrt(5.0))), phi = (1.0 + std::sqrt(5.0)) / 2.0;
  double worstForce = 0.0, worstMotion = 0.0;
  int outputs = 0;
  for (double t = 0.5; t <= 5.0 + 1e-9; t += 0.5) {
    run.advanceTo(t);
    ++outputs;
    const double u1 = run.body(0, StateLayout::kR + 2) - 1.0;
    const double u2 = run.body(1, StateLayout::kR + 2) - 2.0;
    // -K (q - L) by hand, then J's reaction: minus the sum (the forces are collinear with J).
    const double f1 = -(16.0 * u1 - 8.0 * u2), f2 = -(-8.0 * u1 + 8.0 * u2);
    EXPECT_NEAR(run.variable(0), f1, 1e-11) << t;
    EXPECT_NEAR(run.variable(1), f2, 1e-11) << t;
    EXPECT_NEAR(run.variable(2), -(f1 + f2), 1e-11) << t;
    EXPECT_NEAR(run.variable(3), f2, 1e-9) << t;  // FZ(30): the NFORCE is all that loads 30 in z
    // REQUEST FORCE between an I marker and J: the NFORCE's load on that I marker (plus the
    // translational joint's reaction, zero along its axis z).
    const auto r1 = requestColumns(run.system(), m.requests[0], t, run.y(), run.yp());
    const auto r2 = requestColumns(run.system(), m.requests[1], t, run.y(), run.yp());
    EXPECT_NEAR(r1[3], f1, 1e-9) << t;
    EXPECT_NEAR(r2[3], f2, 1e-9) << t;
    worstForce =
        std::max({worstForce, std::abs(run.variable(0) - f1), std::abs(run.variable(1) - f2)});
    // BDF at ERROR = 1e-9 over 5 s: asserted 1e-6.
    EXPECT_NEAR(u1, 0.1 * std::cos(w1 * t), 1e-6) << t;
    EXPECT_NEAR(u2, 0.1 * phi * std::cos(w1 * t), 1e-6) << t;
    worstMotion = std::max(worstMotion, std::abs(u2 - 0.1 * phi * std::cos(w1 * t)));
  }
  EXPECT_EQ(outputs, 10);
  std::printf("NFORCE chain: %d outputs, largest read-back error %.2e, largest mode error %.2e\n",
              outputs, worstForce, worstMotion);
}

TEST(NForce, NewtonMatrixMatchesCentralDifferences) {
  std::string text = chainModel();
  // With damping (CMATRIX) so the velocity columns are exercised too.
  text.replace(text.find("LENGTH=2"), 8, "LENGTH=2, CMATRIX=3");
  const model::Model m = build(text);
  test::BdfRun run(m, 1e-9, 0.01, true);
  Eigen::VectorXd y = run.y(), yp = run.yp();
  const auto& l = run.system().layout();
  y(l.body(0) + StateLayout::kV + 2) = 0.4;
  y(l.body(1) + StateLayout::kV + 2) = -0.3;
  Eigen::MatrixXd jac;
  const double worst = testing::checkNewtonMatrix(run.system(), 0.0, y, yp, 19.0, "nforce", &jac);
  const int nonzeros = testing::expectPatternCovers(run.system(), jac);
  // The coupling entry: the force row of body 0 along z is m v' - F with F = -16 u1 + 8 u2, so
  // its derivative with respect to z of body 1 is -8 (K_12).
  EXPECT_NEAR(jac(l.body(0) + StateLayout::kV + 2, l.body(1) + StateLayout::kR + 2), -8.0, 1e-9);
  std::printf(
      "NFORCE Newton matrix: %d x %d entries compared, %d nonzero, largest relative "
      "difference %.2e\n",
      l.size(), l.size(), nonzeros, worst);
}

TEST(NForce, WrongDataIsLocated) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      "bad nforce\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0,0,1\nMARKER/20, PART=2\n"
      "MATRIX/1, SPARSE, ROWS=6, COLUMNS=6, I=3, J=3, VALUES=8\n"
      "NFORCE/1, IMARKERS=20,20, J=10, KMATRIX=1\n"  // 8: 12x12 needed
      "NFORCE/2, IMARKERS=20, J=10, KMATRIX=7\n"     // 9: no MATRIX/7
      "NFORCE/3, IMARKERS=20, J=10, KMATRIX=1\n"     // 10: fine
      "VARIABLE/1, FUNCTION=NFORCE(3,30,4,0)\n"      // 11: no marker 30
      "VARIABLE/2, FUNCTION=NFORCE(3,20,9,0)\n"      // 12: component 9
      "END\n",
      "bad.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d));
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  for (const char* e : {"bad.adm:8:", "NFORCE/1: KMATRIX: MATRIX/1 is 6x6 but must be 12x12",
                        "bad.adm:9:", "NFORCE/2: KMATRIX=7: MATRIX/7 does not exist",
                        "bad.adm:11:", "VARIABLE/1: NFORCE: marker 30 does not exist",
                        "bad.adm:12:", "VARIABLE/2: NFORCE: the component must be 1 to 8"})
    EXPECT_NE(all.find(e), std::string::npos) << e << "\n" << all;
  EXPECT_EQ(all.find("NFORCE/3:"), std::string::npos) << all;
}

}  // namespace
}  // namespace openmss::analysis
