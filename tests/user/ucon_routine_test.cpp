// UCOSUB/UCOVAR (UCON with FUNCTION=USER) from user libraries in both calling styles
// (tests/user/ucon_routines.c and .f): the same constraints written as UCONs and as built-in
// constraints (JPRIM INPLANE, GCON DM - L); a pendulum made of UCONs against its closed-form
// period and its energy; the equation's row, rates and Newton matrix against central
// differences; statics, kinematics, SI2 and SAVE/RELOAD through a session; located errors;
// bad user code through the openmss program.

#include "user/ucon_routine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/bdf_run.hpp"
#include "support/built_model.hpp"
#include "support/cli_run.hpp"
#include "support/constraint_derivative_check.hpp"
#include "support/newton_matrix_check.hpp"
#include "support/random_state.hpp"
#include "user/user_library.hpp"

namespace openmss {
namespace {

namespace fs = std::filesystem;
const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;

std::string quoted(const std::string& lib, const std::string& name) {
  return "\"" + lib + "::" + name + "\"";
}
std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// A body on a spherical joint at the origin (marker 21 on it, 10 on ground), its CM marker 20
// at (1, 0, 0.3), distinct inertias and a spin about its x axis, gravity along -y; `element`
// holds the CM at z = 0.3 (line 13 of the text).
std::string heightModel(const std::string& element) {
  return "height\nUNITS/ SYSTEM=MKS\nACCGRAV/ JGRAV=-9.81\n"
         "PART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1, QP=0,0,0.3\n"
         "PART/2, MASS=2, CM=20, IP=0.5,1,1.5, WX=1\nMARKER/20, PART=2, QP=1,0,0.3\n"
         "MARKER/21, PART=2\nJOINT/1, SPHERICAL, I=21, J=10\n"
         "REQUEST/1, F2=DX(20,10), F3=DY(20,10), F4=DZ(20,10)\nOUTPUT/ REQSAVE\n" +
         element + "END\n";
}

// The pendulum: a body of mass 2 whose CM (marker 20) is held at distance L = 1 from the origin
// and in the plane z = 0, released at theta0 = 1 rad from the downward vertical; gravity 9.81.
constexpr double kTheta0 = 1.0, kG = 9.81, kL = 1.0;
std::string pendulum(const std::string& constraints, const std::string& extra = "") {
  return "pendulum\nUNITS/ SYSTEM=MKS\nACCGRAV/ JGRAV=-9.81\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=" +
         num(kL * std::sin(kTheta0)) + "," + num(-kL * std::cos(kTheta0)) +
         ",0\nREQUEST/1, F2=DX(20,10), F3=DY(20,10), F4=DZ(20,10)\nOUTPUT/ REQSAVE\n" +
         constraints + extra + "END\n";
}
std::string uconPendulum(const std::string& lib, const std::string& name = "",
                         const std::string& stop = "") {
  const std::string routine = lib.empty() ? "" : ", ROUTINE=" + quoted(lib, name);
  return "UCON/1, FUNCTION=USER(2, 2, 0, 0, 0, 1" + stop + ")" + routine +
         "\nUCON/2, FUNCTION=USER(1, 2, 0" + stop + ")" + routine + "\n";
}
const std::string kBuiltInPendulum =
    "GCON/1, I=20, FUNCTION=DM(20,10) - 1\nJPRIM/1, INPLANE, I=20, J=10\n";

model::Model build(const std::string& text) { return test::buildModelFromText(text, "u.adm"); }

using test::Trajectory;
Trajectory simulate(const std::string& text) {
  return test::integrateModel(build(text), {0.25, 0.5, 1.0, 1.5});
}

// The largest difference of the moving part's positions and velocities (the multipliers are
// scaled differently by different formulations), and the count compared.
double difference(const Trajectory& a, const Trajectory& b, int* compared) {
  EXPECT_EQ(a.states.size(), 4u);
  EXPECT_EQ(b.states.size(), 4u);
  double worst = 0.0;
  for (size_t k = 0; k < std::min(a.states.size(), b.states.size()); ++k)
    for (int i = 0; i < 13; ++i, ++*compared)
      worst = std::max(worst, std::abs(a.states[k](i) - b.states[k](i)));
  return worst;
}

// F = z - 0.3 with ARRAY = 1: the value, the row and the acceleration term are the INPLANE
// equation's operations (its normal is exactly (0, 0, 1), so the other products add exact
// zeros), so the runs agree to rounding; asserted at 1e-12.
TEST(UconRoutine, HeightUconMatchesJprimInplane) {
  const Trajectory e = simulate(heightModel("JPRIM/1, INPLANE, I=20, J=11\n"));
  ASSERT_EQ(e.states.size(), 4u);
  EXPECT_GT(std::abs(e.states[3](1)), 1e-2);  // it swung
  for (const auto& [name, lib] : {std::pair{"C Ucosub", kC}, std::pair{"FORTRAN UCOSUB", kF77}}) {
    const Trajectory u = simulate(
        heightModel("UCON/1, FUNCTION=USER(1, 2, 0.3), ROUTINE=" + quoted(lib, "") + "\n"));
    int compared = 0;
    const double worst = difference(e, u, &compared);
    EXPECT_EQ(compared, 4 * 13);
    EXPECT_LE(worst, 1e-12) << name;
    std::printf("%s: %d states within %.2e of the JPRIM INPLANE run\n", name, compared, worst);
  }
}

// The pendulum's UCONs against GCON DM(20,10) - 1 and JPRIM INPLANE: two formulations of one
// DAE. Their residuals are the same operations (|r| summed in the same order) and only the
// Newton matrices differ, by rounding (the GCON differentiates |r| by AD, UCOSUB gives r/|r|
// and its second partials), which changes the converged iterates by far less than their last
// correction: measured identical; asserted at 1e-12. C and FORTRAN the same.
TEST(UconRoutine, DistanceUconMatchesGcon) {
  const Trajectory e = simulate(pendulum(kBuiltInPendulum));
  ASSERT_EQ(e.states.size(), 4u);
  EXPECT_LT(e.states[3](0), 0.0);  // swung through the bottom: x went from sin(1) to < 0
  const Trajectory c = simulate(pendulum(uconPendulum(kC)));
  const Trajectory f = simulate(pendulum(uconPendulum(kF77)));
  int compared = 0;
  const double worst = difference(e, c, &compared);
  EXPECT_LE(worst, 1e-12);
  int compared2 = 0;
  const double between = difference(c, f, &compared2);
  EXPECT_LE(between, 1e-12);
  EXPECT_EQ(compared + compared2, 2 * 4 * 13);
  std::printf("UCON pendulum: within %.2e of the GCON; C and FORTRAN within %.2e\n", worst,
              between);
}

// The period of the pendulum of amplitude theta0: T = 4 sqrt(L/g) K(sin(theta0/2)), K by the
// arithmetic-geometric mean; measured between the first and third upward zero crossings of x
// (two periods), the crossings interpolated linearly on a 1e-3 grid (|x''| ~ 0 there: error
// << 1e-9). ERROR = 1e-10: measured 1.2e-10 relative, asserted at 1e-8. The energy (its
// rotation stays at rest: the constraints act at the CM) is conserved to the same tolerance
// (measured 3.7e-10), the length to rounding.
TEST(UconRoutine, PendulumOfUconsHasTheClosedFormPeriodAndConservesEnergy) {
  double a = 1.0, b = std::sqrt(1.0 - std::pow(std::sin(kTheta0 / 2), 2));
  for (int k = 0; k < 20; ++k) {
    const double m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  const double period = 4.0 * std::sqrt(kL / kG) * std::numbers::pi / (2.0 * a);
  const model::Model m = build(pendulum(uconPendulum(kC)));
  test::BdfRun run(m, 1e-10, 0.01, false);
  run.start();
  const int b0 = 0;
  auto energy = [&] {
    double v2 = 0.0;
    for (int c = 0; c < 3; ++c) v2 += std::pow(run.body(b0, mechanics::StateLayout::kV + c), 2);
    return 0.5 * 2.0 * v2 + 2.0 * kG * run.body(b0, 1);
  };
  const double e0 = energy();
  double previous = run.body(b0, 0), worstEnergy = 0.0, worstLength = 0.0;
  std::vector<double> upward;
  for (int k = 1; k <= 6000 && upward.size() < 3; ++k) {
    const double t = 1e-3 * k;
    run.advanceTo(t);
    const double x = run.body(b0, 0);
    if (previous < 0.0 && x >= 0.0) upward.push_back(t - 1e-3 * x / (x - previous));
    previous = x;
    worstEnergy = std::max(worstEnergy, std::abs(energy() - e0) / std::abs(e0));
    worstLength = std::max(worstLength, std::abs(std::hypot(x, run.body(b0, 1)) - kL));
  }
  ASSERT_EQ(upward.size(), 3u);
  const double measured = 0.5 * (upward[2] - upward[0]);
  EXPECT_NEAR(measured / period, 1.0, 1e-8);
  EXPECT_LE(worstEnergy, 1e-8);
  EXPECT_LE(worstLength, 1e-9);
  std::printf(
      "UCON pendulum: period %.12f s, closed form %.12f s (rel %.2e); energy drift "
      "%.2e; length error %.2e\n",
      measured, period, measured / period - 1.0, worstEnergy, worstLength);
}

// The rows, rates (the acceleration term through XMATRX) and the Newton matrix against central
// differences at random states, for the distance (CM codes) and for the z axes of two parts
// kept perpendicular (axis codes 311..313), C and FORTRAN.
TEST(UconRoutine, RowRatesAndNewtonMatrixMatchCentralDifferences) {
  int checked = 0;
  for (const std::string& lib : {kC, kF77}) {
    const std::string r = ", ROUTINE=" + quoted(lib, "") + "\n";
    const std::string text = pendulum(
        "UCON/1, FUNCTION=USER(2, 2, 0.1, 0.2, 0.3, 1)" + r + "UCON/2, FUNCTION=USER(3, 2, 3)" + r,
        "PART/3, MASS=1, CM=30, IP=1,2,3\n"
        "MARKER/30, PART=3, QP=0,1,0, ZP=1,1,0\n");
    model::Model m = build(text);
    ASSERT_EQ(m.ucons.size(), 2u);
    const mechanics::MultibodySystem s(m);
    std::mt19937 rng(7);
    const Eigen::VectorXd y = testing::randomState(s, rng);
    testing::checkConstraintRows(s, m, y, 0.3);
    testing::checkConstraintRates(s, m, y, 0.3);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(y.size());
    const double worst = testing::checkNewtonMatrix(s, 0.3, y, yp, 21.0, "UCON " + lib);
    std::printf("UCOSUB Newton matrix (%s): largest relative difference %.2e\n",
                lib == kC ? "C" : "FORTRAN", worst);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

std::string errors(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "u.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d));
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  return all;
}

TEST(UconRoutine, BadStatementsAndDeclarationsAreLocatedErrors) {
  const std::string lib = quoted(kC, "");
  std::string all = errors(
      heightModel("UCON/1, FUNCTION=USER(1, 2, 0.3), ROUTINE=" + quoted(kC, "No_ucon") + "\n"));
  EXPECT_NE(all.find("u.adm:13:"), std::string::npos) << all;
  EXPECT_NE(all.find("UCON/1: the user library"), std::string::npos) << all;
  EXPECT_NE(all.find("exports no UCOSUB routine (looked for No_ucon"), std::string::npos) << all;
  all = errors(
      heightModel("UCON/1, FUNCTION=USER(1, 2, 0.3), ROUTINE=" + quoted(kC, "Novar_ucon") + "\n"));
  EXPECT_NE(all.find("u.adm:13:"), std::string::npos) << all;
  EXPECT_NE(all.find("did not call UCOVAR when IFLAG = 3"), std::string::npos) << all;
  all = errors(
      heightModel("UCON/1, FUNCTION=USER(1, 2, 0.3), ROUTINE=" + quoted(kC, "Angle_ucon") + "\n"));
  EXPECT_NE(all.find("code 14 is not supported"), std::string::npos) << all;
  // F = z - 0.3 - 0.1 TIME: the build reads it at TIME = 0 and 1e-3 and refuses it, located.
  all = errors(heightModel(
      "UCON/1, FUNCTION=USER(1, 2, 0.3, 0.1), ROUTINE=" + quoted(kC, "Time_ucon") + "\n"));
  EXPECT_NE(all.find("u.adm:13:"), std::string::npos) << all;
  EXPECT_NE(all.find("a constraint depending on TIME explicitly is not supported yet"),
            std::string::npos)
      << all;
  all = errors(heightModel("UCON/1, FUNCTION=USER(1, 7, 0.3), ROUTINE=" + lib + "\n"));
  EXPECT_NE(all.find("no moving PART has id 7"), std::string::npos) << all;
  all = errors(heightModel("UCON/1, FUNCTION=USER(1, 1, 0.3), ROUTINE=" + lib + "\n"));
  EXPECT_NE(all.find("no moving PART has id 1"), std::string::npos) << all;
  all = errors(heightModel("UCON/1, VARIABLES=1, FUNCTION=USER(1, 2, 0.3), ROUTINE=" + lib + "\n"));
  EXPECT_NE(all.find("VARIABLES is not supported"), std::string::npos) << all;
  all = errors(heightModel("UCON/1, FUNCTION=DX(20,10)\n"));
  EXPECT_NE(all.find("u.adm:13:"), std::string::npos) << all;
  // No library at all: the default library is unset in this process.
  all = errors(heightModel("UCON/1, FUNCTION=USER(1, 2, 0.3)\n"));
  EXPECT_NE(all.find("u.adm:13:"), std::string::npos) << all;
  EXPECT_NE(all.find("UCON/1"), std::string::npos) << all;
}

// Bad user code in UCOSUB: the run stops naming the routine, the element and the time, with
// exit status 2, and the request file up to that time is complete.
void expectContained(const std::string& name, const std::string& what) {
  const fs::path dir = testing::scratch("ucon-bad-" + name);
  testing::write(dir / "b.adm", pendulum(uconPendulum(kC, name, ", 0.5")));
  const testing::Result r = testing::run("run b.adm --end 2 --dtout 0.05", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("UCOSUB (" + name + ") of UCON/1 stopped the run at TIME = 0.5"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
  std::string err;
  const auto req = output::readRequestFile((dir / "b.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = output::lastStepPerTime(req->steps);
  EXPECT_GE(steps.size(), 10u);  // 0, 0.05, ..., 0.45 at least
  EXPECT_LE(steps.back().time, 0.5 + 1e-12);
  for (const auto& s : steps)  // the rows are the run's: the CM on its circle
    EXPECT_NEAR(std::hypot(s.rows[0][0], s.rows[0][1]), kL, 1e-6) << s.time;
}
TEST(UconRoutine, NanFromUcosubStopsTheRun) { expectContained("Nan_ucon", "not a finite number"); }
TEST(UconRoutine, ErrmesStopInUcosubStopsTheRun) {
  expectContained("Stop_ucon", "the rope snapped");
}

// A study through a session with the C library as the default library (`openmss run
// --user-library`): the request rows of every step.
std::vector<output::RequestFileStep> study(const std::string& name, const std::string& adm,
                                           const std::vector<std::string>& acf) {
  const fs::path dir = testing::scratch(name);
  testing::write(dir / "m.adm", adm);
  user::setDefaultLibrary(kC);
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  options.printInformation = false;
  {
    commands::Session session(options);
    EXPECT_TRUE(session.loadModel((dir / "m.adm").string(), "m"));
    language::CommandReader reader("m.acf", 3);
    for (const auto& c : acf) reader.feedLine(c);
    reader.finish();
    for (const auto& c : reader.takeCommands()) EXPECT_TRUE(session.execute(c)) << c.subject();
  }
  user::setDefaultLibrary("");
  std::string why;
  const auto req = output::readRequestFile((dir / "m.req").string(), &why);
  EXPECT_TRUE(req.has_value()) << why;
  return req ? req->steps : std::vector<output::RequestFileStep>{};
}

// The pendulum with its body's rotation held (JPRIM ORIENTATION: otherwise the free rotations
// make statics singular). Statics: it hangs straight down, (0, -1, 0), within the
// equilibrium's tolerance and the .req's 6 significant digits (asserted 1e-6). SI2 dynamics at
// ERROR = 1e-6: the CM stays on its circle to 1e-6 and x matches the I3 run (measured 3e-6,
// both within their ERROR of the solution), asserted at 1e-4.
TEST(UconRoutine, StaticsAndSi2DynamicsWithTheDefaultLibrary) {
  // MAXIT=100: from 1 rad the equilibrium iterations take 26 (ALIMIT's 10 degrees a step), the
  // same count as with GCON DM - 1 and JPRIM INPLANE.
  const std::string held =
      pendulum(uconPendulum(""), "JPRIM/3, ORIENTATION, I=20, J=10\nEQUILIBRIUM/ MAXIT=100\n");
  const auto statics = study("ucon-statics", held, {"SIMULATE/STATICS", "STOP"});
  ASSERT_FALSE(statics.empty());
  EXPECT_NEAR(statics.back().rows[0][0], 0.0, 1e-6);
  EXPECT_NEAR(statics.back().rows[0][1], -kL, 1e-6);
  EXPECT_NEAR(statics.back().rows[0][2], 0.0, 1e-12);
  const auto i3 =
      study("ucon-i3", held,
            {"INTEGRATOR/GSTIFF, I3, ERROR=1e-6", "SIMULATE/DYNAMICS, END=1, STEPS=10", "STOP"});
  const auto si2 =
      study("ucon-si2", held,
            {"INTEGRATOR/GSTIFF, SI2, ERROR=1e-6", "SIMULATE/DYNAMICS, END=1, STEPS=10", "STOP"});
  ASSERT_EQ(i3.size(), 11u);
  ASSERT_EQ(si2.size(), 11u);
  double worst = 0.0;
  for (size_t k = 0; k < si2.size(); ++k) {
    EXPECT_NEAR(std::hypot(si2[k].rows[0][0], si2[k].rows[0][1]), kL, 1e-6) << k;
    worst = std::max(worst, std::abs(si2[k].rows[0][0] - i3[k].rows[0][0]));
  }
  EXPECT_LE(worst, 1e-4);
  std::printf("statics: x = %.3e, y = %.12f; SI2 vs I3: %.2e\n", statics.back().rows[0][0],
              statics.back().rows[0][1], worst);
}

// Kinematics: the orientation held (JPRIM ORIENTATION) and x driven (MOTION X = sin 1 - 0.3 t)
// leave no freedom: y = -sqrt(1 - x^2) on the circle the UCONs keep, asserted at 1e-6 (the
// .req's 6 significant digits).
TEST(UconRoutine, KinematicsFollowTheCircle) {
  const std::string drive = "JPRIM/1, ORIENTATION, I=20, J=10\nMOTION/1, I=20, J=10, X, FUNCTION=" +
                            num(std::sin(kTheta0)) + " - 0.3*TIME\n";
  const auto rows = study("ucon-kin", pendulum(uconPendulum(""), drive),
                          {"SIMULATE/KINEMATICS, END=2, STEPS=10", "STOP"});
  ASSERT_EQ(rows.size(), 11u);
  for (const auto& s : rows) {
    const double x = std::sin(kTheta0) - 0.3 * s.time;
    EXPECT_NEAR(s.rows[0][0], x, 1e-6) << s.time;
    EXPECT_NEAR(s.rows[0][1], -std::sqrt(1.0 - x * x), 1e-6) << s.time;
  }
}

// SAVE/RELOAD: a study saved at t = 1, taken on to 1.6 and reloaded continues bit-identically
// with the uninterrupted one.
TEST(UconRoutine, ReloadContinuesAsIfNeverStopped) {
  const auto plain =
      study("ucon-plain", pendulum(uconPendulum("")),
            {"SIMULATE/DYNAMICS, END=1, STEPS=5", "SIMULATE/DYNAMICS, END=2, STEPS=5", "STOP"});
  const auto reloaded = study("ucon-reload", pendulum(uconPendulum("")),
                              {"SIMULATE/DYNAMICS, END=1, STEPS=5", "SAVE/STATES, FILE=s.sav",
                               "SIMULATE/DYNAMICS, END=1.6, STEPS=3", "RELOAD/STATES, FILE=s.sav",
                               "SIMULATE/DYNAMICS, END=2, STEPS=5", "STOP"});
  ASSERT_EQ(plain.size(), 11u);
  ASSERT_EQ(reloaded.size(), 14u);
  int compared = 0;
  for (size_t k = 0; k < 5; ++k) {
    const auto& a = reloaded[9 + k];
    const auto& b = plain[6 + k];
    EXPECT_EQ(a.time, b.time);
    for (int c = 0; c < 3; ++c, ++compared) EXPECT_EQ(a.rows[0][c], b.rows[0][c]) << k << c;
  }
  EXPECT_EQ(compared, 15);
  EXPECT_GT(std::abs(plain[10].rows[0][0] - plain[5].rows[0][0]), 1e-2);  // it moved
}

// DOF and redundancy: each UCON removes one degree of freedom from the Gruebler count (the
// pendulum: 6 - 2 = 4), and a UCON restating a JPRIM INPLANE is found redundant and removed,
// named, leaving the rank's two degrees of freedom.
TEST(UconRoutine, CountedInTheDofAndFoundRedundant) {
  const fs::path dir = testing::scratch("ucon-dof");
  testing::write(dir / "p.adm", pendulum(uconPendulum(kC)));
  testing::Result r = testing::run("run p.adm --end 0.1", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  std::string msg = testing::slurp(dir / "p.msg");
  EXPECT_NE(msg.find("Gruebler count:       4 degrees of freedom"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Degrees of freedom:   4"), std::string::npos) << msg;
  testing::write(dir / "r.adm",
                 heightModel("JPRIM/1, INPLANE, I=20, J=11\nUCON/1, FUNCTION=USER(1, 2, 0.3), "
                             "ROUTINE=" +
                             quoted(kF77, "") + "\n"));
  r = testing::run("run r.adm --end 0.1", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  msg = testing::slurp(dir / "r.msg");
  EXPECT_NE(msg.find("Gruebler count:       1 degrees of freedom"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Degrees of freedom:   2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("redundant constraint equation removed: UCON/1 equation UCOSUB F = 0"),
            std::string::npos)
      << msg;
}

// Every integrator (HHT, ABAM and DSTIFF on the index-1 or their own forms, WSTIFF SI2) at
// ERROR = 1e-6 against GSTIFF I3: x at t = 1 within 2e-4 (measured 3e-5 at most, ABAM's), the
// CM on its circle to the .req's digits. LINEAR/EIGENSOL at the statics' equilibrium: the one
// mode's frequency is sqrt(g/L) (printed to 10 digits, asserted 1e-9 relative).
TEST(UconRoutine, EveryIntegratorAndTheLinearization) {
  const std::string held =
      pendulum(uconPendulum(""), "JPRIM/3, ORIENTATION, I=20, J=10\nEQUILIBRIUM/ MAXIT=100\n");
  const auto base =
      study("ucon-gstiff", held,
            {"INTEGRATOR/GSTIFF, ERROR=1e-6", "SIMULATE/DYNAMICS, END=1, STEPS=4", "STOP"});
  ASSERT_EQ(base.size(), 5u);
  int runs = 0;
  for (const std::string integrator : {"HHT", "ABAM", "DSTIFF", "WSTIFF, SI2"}) {
    const auto rows = study(
        "ucon-integrator", held,
        {"INTEGRATOR/" + integrator + ", ERROR=1e-6", "SIMULATE/DYNAMICS, END=1, STEPS=4", "STOP"});
    ASSERT_EQ(rows.size(), 5u) << integrator;
    EXPECT_NEAR(rows[4].rows[0][0], base[4].rows[0][0], 2e-4) << integrator;
    EXPECT_NEAR(std::hypot(rows[4].rows[0][0], rows[4].rows[0][1]), kL, 2e-6) << integrator;
    ++runs;
  }
  EXPECT_EQ(runs, 4);
  const fs::path dir = testing::scratch("ucon-linear");
  testing::write(dir / "m.adm", held);
  testing::write(dir / "m.acf", "m.adm\nm\nSIMULATE/STATICS\nLINEAR/EIGENSOL\nSTOP\n");
  const testing::Result r = testing::run("run m.acf --user-library '" + kC + "'", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string msg = testing::slurp(dir / "m.msg");
  const size_t at = msg.find("\n      2   ");
  ASSERT_NE(at, std::string::npos) << msg;
  double re = 1.0, im = 0.0;
  ASSERT_EQ(std::sscanf(msg.c_str() + at, " 2 %lf %lf", &re, &im), 2) << msg;
  EXPECT_EQ(re, 0.0);
  EXPECT_NEAR(im / std::sqrt(kG / kL), 1.0, 1e-9);
  std::printf("UCON pendulum eigenvalue %.10g i, sqrt(g/L) = %.10g\n", im, std::sqrt(kG / kL));
}

// DEACTIVATE/UCON releases the CM (it falls off the circle: |r| = 1.10 at t = 0.4) and
// ACTIVATE/UCON puts it back on (the initial conditions reassemble it: |r| = 1 at t = 0.6 to
// the .req's digits).
TEST(UconRoutine, DeactivateAndActivate) {
  const auto rows = study("ucon-switch", pendulum(uconPendulum("")),
                          {"SIMULATE/DYNAMICS, END=0.2, STEPS=2", "DEACTIVATE/UCON, ID=1",
                           "SIMULATE/DYNAMICS, END=0.4, STEPS=2", "ACTIVATE/UCON, ID=1",
                           "SIMULATE/DYNAMICS, END=0.6, STEPS=2", "STOP"});
  // Rows: 0, 0.1, 0.2 | 0.2, 0.3, 0.4 (free) | 0.4 (reassembled), 0.5, 0.6.
  ASSERT_EQ(rows.size(), 9u);
  auto radius = [&rows](size_t k) { return std::hypot(rows[k].rows[0][0], rows[k].rows[0][1]); };
  EXPECT_NEAR(radius(2), kL, 2e-6);  // t = 0.2, held
  EXPECT_GT(radius(5), kL + 0.05);   // t = 0.4, free
  EXPECT_NEAR(radius(6), kL, 2e-6);  // t = 0.4, put back on the circle
  EXPECT_NEAR(radius(8), kL, 2e-6);  // t = 0.6, held
}

}  // namespace
}  // namespace openmss
