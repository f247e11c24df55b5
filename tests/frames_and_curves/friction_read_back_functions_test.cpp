// FRICTION(id, index) read inside force, VARIABLE and DIFF functions (docs/theory.md §13), on a
// block sliding down a 30 degree slope held by a TRANSLATIONAL joint with FRICTION
// (mu_d = 0.25): VARIABLE/1 = FRICTION(1, 3) (the friction force along z_J), an SFORCE
// (ACTIONONLY, along z_J, down the slope) of 0.5 FRICTION(1, 3), and DIFF/1 integrating the
// friction's power FRICTION(1, 3) VZ(20, 10, 10). Truth:
//   * the block slides with a = g (sin phi - 1.5 mu_d cos phi) (the SFORCE adds half the
//     friction again);
//   * VARIABLE/1 equals the request read-back and -mu_d g cos phi once sliding;
//   * DIF(1), the friction's work, equals (1/1.5) of the change of kinetic plus potential
//     energy (the SFORCE does half the friction's work again): energy bookkeeping independent
//     of the friction law;
//   * the Newton matrix (the SFORCE and VARIABLE rows read the joint's multipliers through the
//     friction's normal force) against central differences.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/bdf_run.hpp"
#include "support/cli_run.hpp"
#include "support/newton_matrix_check.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;

const double kG = 9.81, kMuD = 0.25, kPhi = 30.0 * std::numbers::pi / 180.0;

std::string slidingBlock() {
  const double c = std::cos(kPhi), s = std::sin(kPhi);
  const std::string zp = std::to_string(c) + "," + std::to_string(-s) + ",0";
  const std::string xp = std::to_string(s) + "," + std::to_string(c) + ",0";
  return "friction read-backs\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\n"
         "MARKER/10, PART=1, ZP=" +
         zp + ", XP=" + xp +
         "\n"
         "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
         "MARKER/20, PART=2, ZP=" +
         zp + ", XP=" + xp +
         "\n"
         "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
         "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.25, "
         "STICTION_TRANSITION_VELOCITY=0.01, MAX_STICTION_DEFORMATION=1e-4\n"
         "VARIABLE/1, FUNCTION=FRICTION(1,3)\n"
         "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=0.5*FRICTION(1,3)\n"
         "DIFF/1, FUNCTION=FRICTION(1,3)*VZ(20,10,10), IC=0\n"
         "ACCGRAV/ JGRAV=-9.81\n"
         "REQUEST/1, DISPLACEMENT, I=20, J=10, RM=10\nREQUEST/2, VELOCITY, I=20, J=10, RM=10\n"
         "REQUEST/3, F2=VARVAL(1)\\F3=DIF(1)\\F4=FRICTION(1,3)\n"
         "OUTPUT/REQSAVE\nEND\n";
}

bool command(openmss::commands::Session& s, const std::string& text) {
  openmss::language::CommandReader reader("m.acf", 3);
  reader.feedLine(text);
  reader.finish();
  auto c = reader.takeCommands();
  EXPECT_EQ(c.size(), 1u);
  s.echoCommand(text);
  return s.execute(c.front());
}

TEST(FrictionReadBackFunctions, SlidingBlockAgainstClosedFormAndEnergy) {
  const fs::path dir = scratch("friction-read-back");
  write(dir / "m.adm", slidingBlock());
  {
    openmss::commands::SessionOptions o;
    o.outputDirectory = dir.string();
    o.echoDiagnostics = false;
    openmss::commands::Session s(o);
    ASSERT_TRUE(s.loadModel((dir / "m.adm").string(), "m"));
    ASSERT_TRUE(command(s, "INTEGRATOR/GSTIFF, ERROR=1e-8"));
    ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=1, DTOUT=0.05"));
    ASSERT_TRUE(command(s, "STOP"));
    EXPECT_EQ(s.diagnostics().errorCount(), 0);
  }
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "m.req").string(), &err);
  ASSERT_TRUE(req) << err;
  ASSERT_EQ(req->steps.size(), 21u);
  const double friction = -kMuD * kG * std::cos(kPhi);
  const double a = kG * (std::sin(kPhi) - 1.5 * kMuD * std::cos(kPhi));
  double st = 0, sv = 0, stt = 0, stv = 0, worstWork = 0.0;
  int n = 0, compared = 0;
  for (const auto& step : req->steps) {
    const double s = step.rows[0][2], v = step.rows[1][2];
    const double variable = step.rows[2][0], work = step.rows[2][1], readBack = step.rows[2][2];
    // The VARIABLE is the request's own read-back (both printed with 6 digits).
    EXPECT_NEAR(variable, readBack, 1e-5 * std::abs(friction)) << step.time;
    // The friction's work from its power: (1/1.5) of the mechanical energy's change; the
    // integrator's ERROR=1e-8 and the 6-digit print bound the difference well below 1e-4.
    const double energy = 0.5 * v * v - kG * std::sin(kPhi) * s;
    EXPECT_NEAR(work, energy / 1.5, 1e-4) << step.time;
    worstWork = std::max(worstWork, std::abs(work - energy / 1.5));
    ++compared;
    if (step.time < 0.2) continue;  // after the breakaway (v > 1.5 Vs within 0.01 s)
    EXPECT_NEAR(variable, friction, 1e-5) << step.time;
    st += step.time;
    sv += v;
    stt += step.time * step.time;
    stv += step.time * v;
    ++n;
  }
  EXPECT_EQ(compared, 21);
  ASSERT_GT(n, 10);
  const double slope = (n * stv - st * sv) / (n * stt - st * st);
  EXPECT_NEAR(slope, a, 1e-4 * a);
  std::printf(
      "FRICTION read-backs in functions: a = %.6f (closed form %.6f), |work - dE/1.5| "
      "<= %.2e over %d outputs\n",
      slope, a, worstWork, compared);
  fs::remove_all(dir);
}

// The Newton matrix against central differences in every column, the joint's multipliers
// included (the SFORCE and VARIABLE rows read them through the friction's normal force). Until
// the normal force's magnitudes were rounded (docs/theory.md §13, "Normal force"), the torque
// multipliers, round-off at this state, got slopes +-1 there that the residual does not have.
TEST(FrictionReadBackFunctions, NewtonMatrixMatchesCentralDifferencesInEveryColumn) {
  const openmss::model::Model m = openmss::test::buildModelFromText(slidingBlock(), "friction.adm");
  openmss::test::BdfRun run(m, 1e-7, 0.01, true);
  run.start();
  run.advanceTo(0.4);  // sliding at about 0.7 m/s: the smooth sliding branch
  const auto& s = run.system();
  const auto& l = s.layout();
  Eigen::VectorXd y = run.y(), yp = run.yp();
  for (int c = 0; c < yp.size(); ++c) yp(c) += 0.01 * std::cos(1.0 + c);
  const double cj = 23.0;
  const int n = l.size();
  Eigen::MatrixXd jac;
  s.newtonMatrix(0.4, y, yp, cj, jac);
  double worst = 0.0;
  int compared = 0;
  int multiplierColumns = 0;
  for (int c = 0; c < n; ++c) {  // every column
    if (c >= l.lambda(0) && c < l.lambda(0) + s.constraints().size()) ++multiplierColumns;
    // Central differences with h = 1e-6 max(1, |y_c|): good to about 1e-8 relative.
    const double h = 1e-6 * std::max(1.0, std::abs(y(c)));
    Eigen::VectorXd yA = y, yB = y, pA = yp, pB = yp;
    yA(c) += h;
    yB(c) -= h;
    if (l.differential(c)) {
      pA(c) += cj * h;
      pB(c) -= cj * h;
    }
    Eigen::VectorXd gA(n), gB(n);
    s.residual(0.4, yA.data(), pA.data(), gA.data());
    s.residual(0.4, yB.data(), pB.data(), gB.data());
    const Eigen::VectorXd fd = (gA - gB) / (2 * h);
    for (int r = 0; r < n; ++r) {
      EXPECT_NEAR(jac(r, c), fd(r), 1e-6 * (1.0 + std::abs(fd(r))))
          << "row " << r << " column " << c;
      worst = std::max(worst, std::abs(jac(r, c) - fd(r)) / (1.0 + std::abs(fd(r))));
      ++compared;
    }
  }
  // Every row against every column: 1 body (14), 5 joint multipliers, DIFF and VARIABLE.
  EXPECT_EQ(multiplierColumns, 5);
  EXPECT_GE(compared, 21 * 21);
  std::printf(
      "FRICTION read-back Newton matrix, all columns: largest relative difference %.2e over %d "
      "entries (%d multiplier columns)\n",
      worst, compared, multiplierColumns);
}

}  // namespace
