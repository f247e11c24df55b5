// FIESUB (FIELD with FUNCTION=USER) from user libraries in both calling styles
// (tests/user/explicit_routines.c and .f): a free body on a coupled 6x6 spring-damper, against
// the same FIELD written with KMATRIX/CMATRIX/LENGTH/FORCE, the Newton matrix through the
// routine's 6x6 partials (and through central differences where it gives none) against central
// differences of the residual, and bad user code through the openmss program.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "output/request_file_reader.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/bdf_run.hpp"
#include "support/built_model.hpp"
#include "support/cli_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace openmss {
namespace {

const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;

bool build(const std::string& text, model::Model& m, std::string* messages) {
  return testing::readAndBuildModel(text, "f.adm", m, messages);
}

// A free 2 kg body, displaced, turned and moving, held by FIELD/1 between its CM marker 20
// and ground marker 10: every one of the six components loads it.
std::string bodyModel(const std::string& field) {
  return "field\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=2, CM=20, IP=1, 1.5, 2, QG=0.1, -0.05, 0.2, REULER=10D, 5D, -8D,"
         " VX=0.3, VZ=-0.2, WX=0.4, WY=-0.3\nMARKER/20, PART=2\n" +
         field + "END\n";
}

// Stiffness 100..150 on the diagonal, 5 off it; damping 2..3.5 and 0.3; LENGTH and FORCE.
const double kDiag[6] = {100, 110, 120, 130, 140, 150};
const double kDamp[6] = {2, 2.5, 3, 2, 3.5, 2.5};
const double kLength[6] = {0.01, -0.02, 0.03, 0.0, 0.01, -0.01};
const double kForce[6] = {0.5, 0.0, -0.3, 0.1, 0.0, 0.05};

std::string list(const std::vector<double>& v) {
  std::string s;
  char b[32];
  for (double x : v) {
    std::snprintf(b, sizeof b, "%.17g", x);
    s += (s.empty() ? "" : ", ") + std::string(b);
  }
  return s;
}

std::string matrixField() {
  std::vector<double> k, c;
  for (int col = 0; col < 6; ++col)
    for (int r = 0; r < 6; ++r) {
      k.push_back(r == col ? kDiag[r] : 5.0);
      c.push_back(r == col ? kDamp[r] : 0.3);
    }
  return "FIELD/1, I=20, J=10, KMATRIX=" + list(k) + ", CMATRIX=" + list(c) +
         ", LENGTH=" + list({kLength, kLength + 6}) + ", FORCE=" + list({kForce, kForce + 6}) +
         "\n";
}

// PAR of the test routines (explicit_routines.c): partials given or not, cubic term g.
std::string userField(const std::string& library, const std::string& name, bool partials,
                      double cubic = 0.0, double stopAt = 1e9) {
  std::vector<double> p(kDiag, kDiag + 6);
  p.push_back(5.0);
  p.insert(p.end(), kDamp, kDamp + 6);
  p.push_back(0.3);
  p.insert(p.end(), kLength, kLength + 6);
  p.insert(p.end(), kForce, kForce + 6);
  p.push_back(partials ? 1.0 : 0.0);
  p.push_back(cubic);
  p.push_back(stopAt);
  return "FIELD/1, I=20, J=10, FUNCTION=USER(" + list(p) + "), ROUTINE=\"" + library + "::" + name +
         "\"\n";
}

using test::Trajectory;

Trajectory simulate(const std::string& text) {
  model::Model m;
  std::string messages;
  const bool built = build(text, m, &messages);
  EXPECT_TRUE(built) << messages;
  if (!built) return {};
  return test::integrateModel(m, {0.25, 0.5, 1.0, 2.0});
}

// Returns the largest state difference; asserts the comparison covered every state.
double difference(const Trajectory& a, const Trajectory& b, int* compared) {
  EXPECT_EQ(a.states.size(), 4u);
  EXPECT_EQ(b.states.size(), 4u);
  double worst = 0.0;
  for (size_t k = 0; k < std::min(a.states.size(), b.states.size()); ++k)
    for (int i = 0; i < a.states[k].size(); ++i, ++*compared)
      worst = std::max(worst, std::abs(a.states[k](i) - b.states[k](i)));
  return worst;
}

// With its partials given, the routine's Newton matrix equals the matrix FIELD's up to the
// order of the products, and its load is the same operations: the runs agree to rounding,
// asserted at 1e-12; no more Newton iterations than the matrix FIELD.
TEST(FieldRoutine, CAndFortranFiesubMatchTheMatrixField) {
  const Trajectory e = simulate(bodyModel(matrixField()));
  for (const auto& [name, lib, symbol] : {std::tuple{"C Fiesub", kC, std::string("")},
                                          std::tuple{"FORTRAN FIESUB", kF77, std::string("")}}) {
    const Trajectory u = simulate(bodyModel(userField(lib, symbol, true)));
    int compared = 0;
    const double worst = difference(e, u, &compared);
    EXPECT_GE(compared, 4 * 12);  // 4 times x (6 positions and 6 velocities at least)
    EXPECT_LE(worst, 1e-12) << name;
    EXPECT_LE(u.residuals, e.residuals) << name;
    std::printf(
        "%s: %d states within %.2e of the matrix FIELD; Newton iterations %ld (matrix %ld)\n", name,
        compared, worst, u.residuals, e.residuals);
  }
}

// Without partials the solver central-differences the routine (h = cbrt(eps) max(1, |x|)):
// for this linear law the difference quotients are exact to rounding (~eps |f| / h = 1e-10
// relative), so the Newton iterates differ by a fraction of the corrector's tolerance:
// asserted at 1e-8 (the integrator's ERROR is 1e-9).
TEST(FieldRoutine, CentralDifferencesWhereTheRoutineGivesNoPartials) {
  const Trajectory e = simulate(bodyModel(matrixField()));
  const Trajectory u = simulate(bodyModel(userField(kC, "", false)));
  int compared = 0;
  const double worst = difference(e, u, &compared);
  EXPECT_GE(compared, 4 * 12);
  EXPECT_LE(worst, 1e-8);
  std::printf("C Fiesub, central differences: %d states within %.2e\n", compared, worst);
}

// The Newton matrix through the routine's partials (and through central differences of the
// routine) against central differences of the whole residual, with a cubic term so that the
// partials depend on the state.
TEST(FieldRoutine, NewtonMatrixMatchesCentralDifferences) {
  int checked = 0;
  for (const std::string& field : {userField(kC, "", true, 400.0), userField(kC, "", false, 400.0),
                                   userField(kF77, "", true, 400.0)}) {
    model::Model m;
    std::string messages;
    ASSERT_TRUE(build(bodyModel(field), m, &messages)) << messages;
    const mechanics::MultibodySystem s(m);
    Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
    for (int i = 0; i < y.size(); ++i) {
      y(i) += 0.05 * std::sin(1.3 * i + 0.2);
      yp(i) = 0.2 * std::cos(0.9 * i);
    }
    for (double cj : {0.0, 25.0}) {
      const double worst = testing::checkNewtonMatrix(s, 0.7, y, yp, cj, field.substr(0, 40));
      std::printf("FIESUB Newton matrix (cj = %g): largest relative difference %.2e\n", cj, worst);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
}

// FUNCTION=USER with the matrices, and a missing routine: located errors before any analysis.
TEST(FieldRoutine, BadStatementsAreLocatedErrors) {
  model::Model m;
  std::string all;
  EXPECT_FALSE(
      build(bodyModel("FIELD/1, I=20, J=10, KMATRIX=" + list(std::vector<double>(36, 1.0)) +
                      ", FUNCTION=USER(1), ROUTINE=\"" + kC + "::\"\n"),
            m, &all));
  EXPECT_NE(all.find("f.adm:7:"), std::string::npos) << all;
  EXPECT_NE(all.find("KMATRIX with FUNCTION=USER(...)"), std::string::npos) << all;
  all.clear();
  EXPECT_FALSE(
      build(bodyModel("FIELD/1, I=20, J=10, FUNCTION=USER(1), ROUTINE=\"" + kC + "::No_fie\"\n"), m,
            &all));
  EXPECT_NE(all.find("FIELD/1: the user library"), std::string::npos) << all;
  EXPECT_NE(all.find("exports no FIESUB routine (looked for No_fie, no_fie_, NO_FIE)"),
            std::string::npos)
      << all;
}

// Bad user code in FIESUB is contained by the mechanism every routine shares: the run stops
// naming the routine, the element and the time, with exit status 2, and the request file up
// to that time is complete.
void expectContained(const std::string& name, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::scratch("bad-" + name);
  testing::write(dir / "b.adm", bodyModel(userField(kC, name, true, 0.0, 0.5) +
                                          "REQUEST/1, F2=DX(20,10)\nOUTPUT/REQSAVE\n"));
  const testing::Result r = testing::run("run b.adm --end 2 --dtout 0.05", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("FIESUB (" + name + ") of FIELD/1 stopped the run at TIME = 0.5"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
  std::string err;
  const auto req = output::readRequestFile((dir / "b.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = output::lastStepPerTime(req->steps);
  EXPECT_GE(steps.size(), 10u);  // 0, 0.05, ..., 0.45 at least
  EXPECT_LE(steps.back().time, 0.5 + 1e-12);
}

TEST(FieldRoutine, NanFromFiesubStopsTheRun) { expectContained("Nan_fie", "not a finite number"); }
TEST(FieldRoutine, ErrmesStopInFiesubStopsTheRun) {
  expectContained("Stop_fie", "the field broke");
}

}  // namespace
}  // namespace openmss
