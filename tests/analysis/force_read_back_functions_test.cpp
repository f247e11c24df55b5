// Force read-backs inside force and VARIABLE functions (docs/theory.md §4d), against closed
// forms and the request outputs of the same elements:
//   (a) VARIABLEs reading a spring's SFORCE at I and J equal the spring law at every output,
//       FZ of the slider's marker equals m z'' (every force on it acts there);
//   (b) an action-only force -0.5 SFORCE(spring) halves the stiffness: the damped frequency of
//       k_eff = k / 2 against the closed form;
//   (c) a VARIABLE reading a force that reads that VARIABLE (an algebraic loop, solved with the
//       rest): v = 0.5 v - 8 z gives the force -16 z and the frequency sqrt(16 / m);
//   (d) BUSH, FIELD, SPDP, VFORCE, VTORQ, GFORCE and FX..TM read in VARIABLEs, every component,
//       at I and J, in ground and in a rotated RM, equal the request values of the same calls;
//   (e) the Newton matrices against central differences, their nonzeros inside the resolved
//       structural pattern;
//   (f) cycles of read-backs are refused at input, naming the cycle.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/request_values.hpp"
#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "model/model_builder.hpp"
#include "support/bdf_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

model::Model build(const std::string& text) { return test::buildModelFromText(text, "rb.adm"); }

using testing::expectPatternCovers;

const std::string kSlider =
    "read-backs\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,1.5\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n";

// A 2 kg slider on a vertical translational joint, a spring-damper SFORCE/1 (k = 8, c = 0.3,
// free length 1) between it and the origin and an action-only SFORCE/2 = -0.5 SFORCE(1) along
// z_J: the net force is half the spring's, m z'' = -4 (z - 1) - 0.15 z'.
std::string halvedSpringModel() {
  return kSlider +
         "SFORCE/1, TRANSLATIONAL, I=20, J=10, FUNCTION=-8*(DM(20,10)-1) - 0.3*VR(20,10)\n"
         "SFORCE/2, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=-0.5*SFORCE(1,0,4,0)\n"
         "VARIABLE/1, FUNCTION=SFORCE(1,0,4,0)\n"
         "VARIABLE/2, FUNCTION=SFORCE(1,1,4,0)\n"
         "VARIABLE/3, FUNCTION=FZ(20)\n"
         "VARIABLE/4, FUNCTION=SFORCE(2,0,4,0)\n"
         "VARIABLE/5, FUNCTION=SFORCE(1,0,1,0)\n"
         "END\n";
}

TEST(ForceReadBacks, SpringReadBackIsTheSpringLawAndHalvesTheResponse) {
  const model::Model m = build(halvedSpringModel());
  EXPECT_TRUE(mechanics::readsAccelerationsOrReactions(m));  // FZ(20) reads the joint's
  test::BdfRun run(m, 1e-9, 0.01, true);
  run.start();
  // Closed form of z'' = -2 (z - 1) - 0.075 z', z(0) = 1.5, z'(0) = 0: the stiffness halved
  // (w0^2 = 2, not 4).
  const double sigma = 0.0375, wd = std::sqrt(2.0 - sigma * sigma);
  auto exact = [&](double t) {
    return 1.0 + 0.5 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
  };
  double worstLaw = 0.0, worstMotion = 0.0;
  int outputs = 0;
  for (double t = 0.25; t <= 5.0 + 1e-9; t += 0.25) {
    run.advanceTo(t);
    ++outputs;
    const double z = run.body(0, StateLayout::kR + 2), vz = run.body(0, StateLayout::kV + 2);
    const double law = -8.0 * (z - 1.0) - 0.3 * vz;  // z > 0: the line I-J is +z
    const double zdd = run.yp()(run.system().layout().body(0) + StateLayout::kV + 2);
    // The VARIABLEs are unknowns solved by Newton to 1e-12 (1 + |v|) with the state: the
    // read-back equals the law of that state to round-off.
    EXPECT_NEAR(run.variable(0), law, 1e-11) << t;
    EXPECT_NEAR(run.variable(1), -law, 1e-11) << t;      // at J: the reaction
    EXPECT_NEAR(run.variable(2), 2.0 * zdd, 1e-9) << t;  // FZ(20) = m z''
    EXPECT_NEAR(run.variable(3), -0.5 * law, 1e-11) << t;
    EXPECT_NEAR(run.variable(4), std::abs(law), 1e-11) << t;  // component 1: the magnitude
    worstLaw = std::max(worstLaw, std::abs(run.variable(0) - law));
    // BDF at ERROR = 1e-9 over 5 s (1.1 periods): global error measured ~1e-7; asserted 1e-6.
    EXPECT_NEAR(z, exact(t), 1e-6) << t;
    worstMotion = std::max(worstMotion, std::abs(z - exact(t)));
  }
  EXPECT_EQ(outputs, 20);
  std::printf(
      "spring read-back: %d outputs, largest |VARIABLE - law| %.2e, largest |z - closed"
      " form (k/2)| %.2e\n",
      outputs, worstLaw, worstMotion);
}

// A VARIABLE reading a force that reads the VARIABLE: v = 0.5 v - 8 z, so v = -16 z, and the
// slider (m = 2, spring length 0) oscillates at sqrt(8) rad/s about z = 0.
TEST(ForceReadBacks, AlgebraicLoopThroughAForceIsSolvedWithTheRest) {
  const model::Model m = build(
      "loop\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,0.5\nMARKER/20, PART=2\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
      "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=0.5*VARVAL(1) - 8*DZ(20,10)\n"
      "VARIABLE/1, FUNCTION=SFORCE(1,0,4,0)\n"
      "END\n");
  test::BdfRun run(m, 1e-9, 0.01, true);
  EXPECT_NEAR(run.variable(0), -16.0 * 0.5, 1e-12);  // the initial solve closes the loop
  run.start();
  const double w = std::sqrt(8.0);
  double worst = 0.0;
  int outputs = 0;
  for (double t = 0.5; t <= 4.0 + 1e-9; t += 0.5) {
    run.advanceTo(t);
    ++outputs;
    const double z = run.body(0, StateLayout::kR + 2);
    EXPECT_NEAR(run.variable(0), -16.0 * z, 1e-11) << t;
    // BDF at ERROR = 1e-9 over 4 s (1.8 periods): asserted 2e-6.
    EXPECT_NEAR(z, 0.5 * std::cos(w * t), 2e-6) << t;
    worst = std::max(worst, std::abs(z - 0.5 * std::cos(w * t)));
  }
  EXPECT_EQ(outputs, 8);
  std::printf("read-back loop: largest |z - 0.5 cos(sqrt(8) t)| over 4 s = %.2e\n", worst);
}

// A free body (no gravity) loaded by a BUSHING, a FIELD, a SPRINGDAMPER, a VFORCE, a VTORQUE
// and a GFORCE whose functions read positions, velocities and another element's force; VARIABLEs
// read every component of every element at I and J, in ground and in the rotated marker 30.
std::string elementsModel() {
  std::string s =
      "elements\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "MARKER/11, PART=1, QP=0.2,-0.1,0.3, REULER=20D,10D,5D\nMARKER/12, PART=1, FLOATING\n"
      "PART/2, MASS=1.5, CM=20, IP=0.2,0.3,0.4, QG=0.05,-0.02,0.6, REULER=5D,3D,-2D,"
      " VX=0.3, VZ=-0.2, WY=1, WZ=-2\n"
      "MARKER/20, PART=2, QP=0.1,0,0\nMARKER/21, PART=2\n"
      "MARKER/30, PART=2, REULER=30D,40D,50D\n"
      "BUSHING/1, I=20, J=11, K=400,500,600, C=2,3,4, KT=40,50,60, CT=0.2,0.3,0.4,"
      " FORCE=0,0,5, TORQUE=0.1,0,0\n"
      "FIELD/1, I=21, J=10, KMATRIX=40,0,0,0,0,0, 0,50,0,0,0,0, 0,0,60,0,0,0,"
      " 0,0,0,4,0,0, 0,0,0,0,5,0, 0,0,0,0,0,6, LENGTH=0,0,0.5,0,0,0\n"
      "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=30, C=0.5, LENGTH=0.4\n"
      "VFORCE/1, I=21, JFLOAT=12, RM=11, FX=-3*DX(21,10)\\FY=2*VZ(21,10)"
      "\\FZ=0.1*BUSH(1,0,2,0)\n"
      "VTORQUE/1, I=20, JFLOAT=12, RM=10, TX=-0.5*WX(20,10)\\TZ=0.01*SPDP(1,0,4,0)\n"
      "GFORCE/1, I=20, JFLOAT=12, RM=30, FX=0.2*VFORCE(1,0,3,0)\\FY=1\\FZ=-2*DY(20,10)"
      "\\TX=0.3\\TY=0.1*FIELD(1,1,6,0)\\TZ=-0.2*WZ(20,10)\n";
  const char* calls[] = {"BUSH(1,%d,%d,0)",   "BUSH(1,%d,%d,30)",  "FIELD(1,%d,%d,30)",
                         "SPDP(1,%d,%d,0)",   "VFORCE(1,%d,%d,0)", "VTORQ(1,%d,%d,30)",
                         "GFORCE(1,%d,%d,0)", "GFORCE(1,%d,%d,30)"};
  int id = 1;
  for (const char* call : calls)
    for (int at = 0; at <= 1; ++at)
      for (int c = 1; c <= 8; ++c) {
        char text[64];
        std::snprintf(text, sizeof text, call, at, c);
        s += "VARIABLE/" + std::to_string(id++) + ", FUNCTION=" + text + "\n";
      }
  for (const char* net : {"FX(20)", "FY(20)", "FZ(20,11)", "FM(21)", "TX(20)", "TY(20,10,30)",
                          "TZ(21,10)", "TM(20,10)"})
    s += "VARIABLE/" + std::to_string(id++) + ", FUNCTION=" + net + "\n";
  return s + "END\n";
}

TEST(ForceReadBacks, EveryComponentEqualsTheRequestValue) {
  const model::Model m = build(elementsModel());
  ASSERT_EQ(m.variables.size(), 8u * 2u * 8u + 8u);
  test::BdfRun run(m, 1e-7, 0.01, true);
  run.start();
  int compared = 0, nonzero = 0;
  double worst = 0.0;
  for (double t : {0.0, 0.1, 0.3}) {
    if (t > 0.0) run.advanceTo(t);
    for (size_t k = 0; k < m.variables.size(); ++k) {
      ASSERT_EQ(m.variables[k].function.measures.size(), 1u);
      const double request =
          measureValue(run.system(), m.variables[k].function.measures[0], t, run.y(), run.yp());
      // The VARIABLE is a Newton unknown converged to 1e-12 (1 + |v|).
      EXPECT_NEAR(run.variable(static_cast<int>(k)), request, 1e-10 * (1.0 + std::abs(request)))
          << "VARIABLE/" << k + 1 << " at t=" << t;
      worst = std::max(worst, std::abs(run.variable(static_cast<int>(k)) - request));
      ++compared;
      if (std::abs(request) > 1e-6) ++nonzero;
    }
  }
  EXPECT_EQ(compared, 3 * 136);
  // Most components are loaded (a few, e.g. a VFORCE's torque, are zero by construction).
  EXPECT_GT(nonzero, 3 * 100);
  std::printf("read-backs vs requests: %d values (%d nonzero), largest difference %.2e\n", compared,
              nonzero, worst);
}

TEST(ForceReadBacks, NewtonMatricesMatchCentralDifferences) {
  for (const std::string& text : {halvedSpringModel(), elementsModel()}) {
    const model::Model m = build(text);
    test::BdfRun run(m, 1e-7, 0.01, true);
    Eigen::VectorXd y = run.y(), yp = run.yp();
    const auto& l = run.system().layout();
    for (int k = 0; k < l.constraintEquations; ++k) y(l.lambda(k)) += 0.1 * (k + 1);
    Eigen::MatrixXd jac;
    const double worst = testing::checkNewtonMatrix(run.system(), 0.0, y, yp, 29.0, m.title, &jac);
    const int nonzeros = expectPatternCovers(run.system(), jac);
    std::printf(
        "%s: Newton matrix %dx%d (%d entries compared, %d nonzero), largest relative "
        "difference %.2e\n",
        m.title.c_str(), l.size(), l.size(), l.size() * l.size(), nonzeros, worst);
    EXPECT_GT(nonzeros, l.size());
  }
}

std::string diagnose(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "cycle.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d));
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  return all;
}

TEST(ForceReadBacks, CyclesAreRefusedNamingTheElements) {
  const std::string two =
      diagnose(kSlider +
               "SFORCE/1, TRANSLATIONAL, I=20, J=10, FUNCTION=-8*DM(20,10) + SFORCE(2,0,4,0)\n"
               "SFORCE/2, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=-0.5*SFORCE(1,0,4,0)\n"
               "END\n");
  EXPECT_NE(two.find("cycle.adm:8:1: error: SFORCE/1: force read-backs form a cycle that cannot "
                     "be ordered: SFORCE/1 reads SFORCE/2 reads SFORCE/1."),
            std::string::npos)
      << two;
  // FZ(20) sums every force on marker 20, SFORCE/1's own included.
  const std::string own = diagnose(
      kSlider + "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=-0.1*FZ(20)\nEND\n");
  EXPECT_NE(own.find("SFORCE/1 reads SFORCE/1 (its own force)"), std::string::npos) << own;
  // Through a VARIABLE there is no cycle: the VARIABLE is an unknown (the loop test above).
}

}  // namespace
}  // namespace openmss::analysis
