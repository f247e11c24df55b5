// COUSUB/COUXX/COUXX2 (COUPLER with FUNCTION=USER) from user libraries in both calling styles
// (tests/user/coupler_routines.c and .f): three joints coupled, against the same COUPLER
// written with SCALES (linear law) and the same constraint written as a GCON (cubic law);
// the user's partials against central differences of COUSUB; the equation's row, rates and
// Newton matrix against central differences; located errors; bad user code through the
// openmss program.

#include "user/coupler_routine.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
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
#include "support/constraint_derivative_check.hpp"
#include "support/newton_matrix_check.hpp"
#include "support/random_state.hpp"

namespace openmss {
namespace {

const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;

bool build(const std::string& text, model::Model& m, std::string* messages) {
  return testing::readAndBuildModel(text, "c.adm", m, messages);
}

// Two revolute joints about z and a translational joint along (1, 2, 0), gravity along -y:
// every joint is driven (gravity 1: the turns stay well within +-pi, where the GCON's AZ
// does not wrap), the coupler leaves two degrees of freedom. The element is line 20.
std::string threeJoints(const std::string& coupler) {
  return "coupler\nUNITS/ SYSTEM=NONE\nACCGRAV/ JGRAV=-1\n"
         "PART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1, QP=1,0,0\n"
         "MARKER/12, PART=1, QP=0,2,0, ZP=1,2,0\n"
         "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=0.3,0,0\nMARKER/21, PART=2\n"
         "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3, QP=1.2,0.1,0\n"
         "MARKER/31, PART=3, QP=1,0,0\n"
         "PART/4, MASS=2, CM=40, IP=1,1,1\nMARKER/40, PART=4, QP=0.5,2,0.1\n"
         "MARKER/41, PART=4, QP=0,2,0, ZP=1,2,0\n"
         "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=31, J=11\n"
         "JOINT/3, TRANSLATIONAL, I=41, J=12\n" +
         coupler + "END\n";
}

// phi = d1 + 0.5 d2 - 0.25 d3 + g d2^3 (coupler_routines.c).
std::string userCoupler(const std::string& routine, double cubic = 0.0, double stopAt = 1e9) {
  char b[160];
  std::snprintf(b, sizeof b,
                "COUPLER/1, JOINTS=1,2,3, TYPE=R:R:T, FUNCTION=USER(1, 0.5, -0.25, %.17g, %.17g)",
                cubic, stopAt);
  return std::string(b) + (routine.empty() ? "" : ", ROUTINE=" + routine) + "\n";
}
const std::string kScales = "COUPLER/1, JOINTS=1,2,3, TYPE=R:R:T, SCALES=1, 0.5, -0.25\n";

std::string quoted(const std::string& lib, const std::string& names) {
  return "\"" + lib + "::" + names + "\"";
}

using test::Trajectory;

Trajectory simulate(const std::string& text) {
  model::Model m;
  std::string messages;
  const bool built = build(text, m, &messages);
  EXPECT_TRUE(built) << messages;
  if (!built) return {};
  return test::integrateModel(m, {0.25, 0.5, 1.0, 1.5});
}

// The positions and velocities of the three moving parts (the multipliers are scaled
// differently by the two formulations of a GCON, so they are left out): the largest
// difference, and the count compared.
double difference(const Trajectory& a, const Trajectory& b, int* compared) {
  EXPECT_EQ(a.states.size(), 4u);
  EXPECT_EQ(b.states.size(), 4u);
  double worst = 0.0;
  for (size_t k = 0; k < std::min(a.states.size(), b.states.size()); ++k)
    for (int i = 0; i < 3 * 13; ++i, ++*compared)
      worst = std::max(worst, std::abs(a.states[k](i) - b.states[k](i)));
  return worst;
}

// With COUXX and COUXX2 the equation's value, row and acceleration term are the SCALES
// equation's operations (the second partials are zero and add exact zeros): the runs agree to
// rounding, asserted at 1e-12, with no more residual evaluations.
TEST(CouplerRoutine, CAndFortranCousubMatchTheScalesCoupler) {
  const Trajectory e = simulate(threeJoints(kScales));
  ASSERT_EQ(e.states.size(), 4u);
  EXPECT_GT(std::abs(e.states[3](0)) + std::abs(e.states[3](1)), 1e-2);  // it moved
  for (const auto& [name, lib] : {std::pair{"C Cousub", kC}, std::pair{"FORTRAN COUSUB", kF77}}) {
    const Trajectory u = simulate(threeJoints(userCoupler(quoted(lib, ""))));
    int compared = 0;
    const double worst = difference(e, u, &compared);
    EXPECT_EQ(compared, 4 * 39);
    EXPECT_LE(worst, 1e-12) << name;
    EXPECT_LE(u.residuals, e.residuals) << name;
    std::printf("%s: %d states within %.2e of the SCALES coupler; residuals %ld (SCALES %ld)\n",
                name, compared, worst, u.residuals, e.residuals);
  }
}

// ROUTINE=lib::Cousub names COUSUB alone: its partials come from central differences
// (step cbrt(eps) max(1, |d|), second differences eps^(1/4)); for the linear law these are
// exact to rounding (~1e-10 relative), so the Newton iterates differ by a fraction of the
// corrector's tolerance: asserted at 1e-8 (ERROR is 1e-9).
TEST(CouplerRoutine, CentralDifferencesWhereTheLibraryGivesNoPartials) {
  const Trajectory e = simulate(threeJoints(kScales));
  const Trajectory u = simulate(threeJoints(userCoupler(quoted(kC, "Cousub"))));
  int compared = 0;
  const double worst = difference(e, u, &compared);
  EXPECT_EQ(compared, 4 * 39);
  EXPECT_LE(worst, 1e-8);
  std::printf("C Cousub, central differences: %d states within %.2e\n", compared, worst);
}

// The cubic law through COUXX/COUXX2 (C and FORTRAN, three names given) against the same
// constraint as a GCON of AZ and DZ (the joints' displacements from the data set's
// configuration, which is where all three are zero): two formulations of one DAE, agreeing to
// the integrator's tolerance; asserted at 1e-7 (ERROR = 1e-9 per step over ~40 steps).
TEST(CouplerRoutine, CubicLawMatchesTheSameGcon) {
  const Trajectory e =
      simulate(threeJoints("GCON/1, I=21, FUNCTION=AZ(21,10) + 0.5*AZ(31,11) - 0.25*DZ(41,12,12) + "
                           "2*AZ(31,11)**3\n"));
  ASSERT_EQ(e.states.size(), 4u);
  for (const auto& [name, text] :
       {std::pair{"C", userCoupler(quoted(kC, "Cousub") + ", " + quoted(kC, "Couxx") + ", " +
                                       quoted(kC, "Couxx2"),
                                   2.0)},
        std::pair{"FORTRAN", userCoupler(quoted(kF77, ""), 2.0)}}) {
    const Trajectory u = simulate(threeJoints(text));
    int compared = 0;
    const double worst = difference(e, u, &compared);
    EXPECT_EQ(compared, 4 * 39);
    EXPECT_LE(worst, 1e-7) << name;
    std::printf("%s cubic COUSUB: %d states within %.2e of the GCON\n", name, compared, worst);
  }
}

// COUXX and COUXX2 against central differences of COUSUB at scattered displacements: first
// partials step 1e-5 (error ~1e-10), second partials step 1e-4 on the first differences'
// formula (error ~1e-8); asserted at 1e-7 relative.
TEST(CouplerRoutine, UserPartialsMatchCentralDifferencesOfCousub) {
  int checked = 0;
  for (const std::string& lib : {kC, kF77}) {
    user::CouplerDescription d;
    d.element.subject = "COUPLER/1";
    d.element.id = 1;
    d.element.par = {1.0, 0.5, -0.25, 2.0};
    d.count = 3;
    const user::RoutineName names[3] = {{lib, ""}, {lib, ""}, {lib, ""}};
    const bool explicitly[3] = {false, true, true};
    std::string error;
    const auto r = user::loadCouplerRoutine(d, names, explicitly, true, ".", error);
    ASSERT_TRUE(r) << error;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 5; ++trial) {
      const double x[3] = {u(rng), u(rng), u(rng)};
      double phi, first[3], second[9];
      r->evaluate(0.0, x, 3, 2, &phi, first, second);
      auto at = [&](int k, double h, int l = 0, double g = 0.0) {
        double z[3] = {x[0], x[1], x[2]}, v, f[3], s[9];
        z[k] += h;
        z[l] += g;
        r->evaluate(0.0, z, 3, 0, &v, f, s);
        return v;
      };
      for (int k = 0; k < 3; ++k, ++checked) {
        const double h = 1e-5;
        const double fd = (at(k, h) - at(k, -h)) / (2 * h);
        EXPECT_NEAR(first[k], fd, 1e-7 * (1 + std::abs(fd))) << lib << " d/d" << k;
        for (int l = 0; l < 3; ++l, ++checked) {
          const double g = 1e-4;
          const double fd2 =
              (at(k, g, l, g) - at(k, g, l, -g) - at(k, -g, l, g) + at(k, -g, l, -g)) / (4 * g * g);
          EXPECT_NEAR(second[k + 3 * l], fd2, 1e-6 * (1 + std::abs(fd2))) << lib << k << l;
        }
      }
    }
  }
  EXPECT_EQ(checked, 2 * 5 * 12);
}

// The equation's row, rates (the acceleration term through COUXX2) and the Newton matrix
// against central differences, with the routine's partials (C and FORTRAN), and the Newton
// matrix through the solver's differences of COUSUB (ROUTINE=lib::Cousub) against the one
// through COUXX/COUXX2. That last one is not checked against differences of the residual: the
// residual then holds differenced first partials, whose rounding (eps |phi| / h, h = 6e-6)
// the check's own step (1e-6) would amplify to ~1e-5 |lambda|. Its second partials are second
// differences of COUSUB (truncation zero for the cubic, rounding eps |phi| / h^2 ~ 1e-8), so
// the two matrices agree to 1e-6 relative.
TEST(CouplerRoutine, RowRatesAndNewtonMatrixMatchCentralDifferences) {
  int checked = 0;
  Eigen::MatrixXd exact;
  for (const std::string& c : {userCoupler(quoted(kC, ""), 2.0), userCoupler(quoted(kF77, ""), 2.0),
                               userCoupler(quoted(kC, "Cousub"), 2.0)}) {
    model::Model m;
    std::string messages;
    ASSERT_TRUE(build(threeJoints(c), m, &messages)) << messages;
    const mechanics::MultibodySystem s(m);
    std::mt19937 rng(3);
    const Eigen::VectorXd y = testing::randomState(s, rng);
    testing::checkConstraintRows(s, m, y, 0.3);
    testing::checkConstraintRates(s, m, y, 0.3);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(y.size());
    if (checked < 2) {
      Eigen::MatrixXd jac;
      const double worst = testing::checkNewtonMatrix(s, 0.3, y, yp, 21.0, c.substr(0, 60), &jac);
      std::printf("COUSUB Newton matrix: largest relative difference %.2e\n", worst);
      if (checked == 0) exact = jac;
    } else {
      Eigen::MatrixXd jac;
      s.newtonMatrix(0.3, y, yp, 21.0, jac);
      ASSERT_EQ(jac.rows(), exact.rows());
      double worst = 0.0;
      for (int r = 0; r < jac.rows(); ++r)
        for (int k = 0; k < jac.cols(); ++k)
          worst =
              std::max(worst, std::abs(jac(r, k) - exact(r, k)) / (1.0 + std::abs(exact(r, k))));
      EXPECT_LE(worst, 1e-6);
      std::printf("COUSUB Newton matrix by differences: within %.2e of COUXX/COUXX2's\n", worst);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(CouplerRoutine, BadStatementsAreLocatedErrors) {
  auto errors = [](const std::string& coupler) {
    model::Model m;
    std::string all;
    EXPECT_FALSE(build(threeJoints(coupler), m, &all));
    return all;
  };
  std::string all =
      errors("COUPLER/1, JOINTS=1,2,3, TYPE=R:R:T, SCALES=1,2,3, FUNCTION=USER(1), ROUTINE=" +
             quoted(kC, "") + "\n");
  EXPECT_NE(all.find("c.adm:20:"), std::string::npos) << all;
  EXPECT_NE(all.find("SCALES with FUNCTION=USER(...)"), std::string::npos) << all;
  all = errors(userCoupler(quoted(kC, "No_cou")));
  EXPECT_NE(all.find("COUPLER/1: the user library"), std::string::npos) << all;
  EXPECT_NE(all.find("exports no COUSUB routine (looked for No_cou, no_cou_, NO_COU)"),
            std::string::npos)
      << all;
  all = errors(userCoupler(quoted(kC, "Cousub") + ", " + quoted(kC, "Couxx")));
  EXPECT_NE(all.find("ROUTINE has 2 values"), std::string::npos) << all;
  all = errors(
      userCoupler(quoted(kC, "Cousub") + ", " + quoted(kC, "Couxx") + ", " + quoted(kC, "No_xx2")));
  EXPECT_NE(all.find("exports no COUXX2 routine"), std::string::npos) << all;
  all =
      errors("COUPLER/1, JOINTS=1,2,3, TYPE=R:R:T, SCALES=1,2,3, ROUTINE=" + quoted(kC, "") + "\n");
  EXPECT_NE(all.find("ROUTINE= without FUNCTION=USER(...)"), std::string::npos) << all;
}

// Bad user code in COUSUB: the run stops naming the routine, the element and the time, with
// exit status 2, and the request file up to that time is complete.
void expectContained(const std::string& name, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::scratch("bad-" + name);
  testing::write(dir / "b.adm", threeJoints(userCoupler(quoted(kC, name), 0.0, 0.5) +
                                            "REQUEST/1, F2=DX(30,11)\nOUTPUT/REQSAVE\n"));
  const testing::Result r = testing::run("run b.adm --end 2 --dtout 0.05", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("COUSUB (" + name + ") of COUPLER/1 stopped the run at TIME = 0.5"),
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

TEST(CouplerRoutine, NanFromCousubStopsTheRun) {
  expectContained("Nan_cou", "not a finite number");
}
TEST(CouplerRoutine, ErrmesStopInCousubStopsTheRun) {
  expectContained("Stop_cou", "the coupler broke");
}

}  // namespace
}  // namespace openmss
