// PTCV and CVCV through the whole run driver (docs/theory.md §5d, §5e): the committed curve
// parameters (the searches' warm start) in the run state, and the located stop when a point
// runs off the end of an OPEN curve (ADAMS stops the run there too).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/run_state.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace openmss {
namespace {

namespace fs = std::filesystem;
using testing::scratch;
using testing::slurp;
using testing::write;

bool command(commands::Session& s, const std::string& text) {
  language::CommandReader reader("c.acf", 3);
  reader.feedLine(text);
  reader.finish();
  auto c = reader.takeCommands();
  EXPECT_EQ(c.size(), 1u);
  s.echoCommand(text);
  return s.execute(c.front());
}

// A bead sliding down an OPEN straight-line curve (ORDER=2 through 4 points from (-3, 1.5, -1)
// to (3, -1.5, 1), length 7) under gravity, from (0.6, -0.3, 0.2) at 0.35 along the line. Its
// arc length s(t) = 0.35 t + (a/2) t^2 with a = g 1.5/3.5 reaches the end (2.8 on) at
// t = 1.0739 s; ADAMS stops there.
const char* kBeadOffTheEnd =
    "bead off the end\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "MARKER/11, PART=1, FLOATING\n"
    "PART/2, MASS=2, CM=20, IP=0.1,0.2,0.3, QG=0.6,-0.3,0.2, VX=0.3, VY=-0.15, VZ=0.1\n"
    "MARKER/20, PART=2\nACCGRAV/ JGRAV=-9.81\n"
    "MATRIX/1, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=-3,1.5,-1, -1,0.5,-0.33333333333333333, "
    "1,-0.5,0.33333333333333333, 3,-1.5,1\n"
    "CURVE/1, OPEN, MATRIX=1, CURVE_POINTS, ORDER=2\n"
    "PTCV/7, I=20, JFLOAT=11, CURVE=1, RM=10\nOUTPUT/REQSAVE\n"
    "REQUEST/1, DISPLACEMENT, I=20, J=10\nEND\n";

TEST(CurveRunState, PointRunningOffAnOpenCurveStopsTheRunNamingTheElementAndTime) {
  const fs::path dir = scratch("ptcv-off-end");
  write(dir / "b.adm", kBeadOffTheEnd);
  commands::SessionOptions o;
  o.outputDirectory = dir.string();
  o.echoDiagnostics = false;
  commands::Session s(o);
  const bool loaded = s.loadModel((dir / "b.adm").string(), "b");
  for (const auto& d : s.diagnostics().all()) std::printf("%s\n", format(d).c_str());
  ASSERT_TRUE(loaded);
  ASSERT_TRUE(command(s, "INTEGRATOR/GSTIFF, ERROR=1e-7, HMAX=0.01"));
  EXPECT_FALSE(command(s, "SIMULATE/DYNAMICS, END=3, STEPS=30"));
  const double a = 9.81 * 1.5 / 3.5;
  const double tEnd = (-0.35 + std::sqrt(0.35 * 0.35 + 2.0 * a * 2.8)) / a;
  int found = 0;
  for (const auto& d : s.diagnostics().all()) {
    if (d.severity != Severity::Error) continue;
    const std::string text = format(d);
    const std::string key = "PTCV/7: marker I ran off the end of OPEN CURVE/1 at time ";
    const std::size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << text;
    EXPECT_NE(text.find("Lengthen the curve"), std::string::npos) << text;
    // The first accepted step past the end: within one HMAX (0.01) after the closed form.
    const double t = std::stod(text.substr(at + key.size(), 13));
    EXPECT_GE(t, tEnd - 1e-4) << text;
    EXPECT_LE(t, tEnd + 0.01 + 1e-4) << text;
    std::printf("run-off stop at t = %.6f (closed form %.6f)\n", t, tEnd);
    ++found;
  }
  EXPECT_EQ(found, 1);
  // The outputs up to the stop were written: 10 of the 30 steps (t = 0 .. 1.0).
  std::string err;
  const auto req = output::readRequestFile((dir / "b.req").string(), &err);
  ASSERT_TRUE(req) << err;
  EXPECT_EQ(output::lastStepPerTime(req->steps).size(), 11u);
}

// A bead on a closed circular wire (radius 0.8, 64 points) through the run driver: the
// committed curve parameter follows the bead (alpha = -1 + theta/pi from the bottom, the
// curve's uniform parameter), and the run is timed (printed) with the warm start in use.
std::string beadOnCircle() {
  std::ostringstream s;
  s.precision(17);
  const double r = 0.8, start = std::numbers::pi / 3.0;
  s << "bead\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
       "MARKER/11, PART=1, FLOATING\nPART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3, QG="
    << r * std::sin(start) << "," << -r * std::cos(start) << ",0\nMARKER/20, PART=2\n"
    << "MATRIX/1, FULL=RORDER, ROWS=65, COLUMNS=3, VALUES=";
  for (int k = 0; k <= 64; ++k) {
    const double a = 2.0 * std::numbers::pi * (k % 64) / 64;
    s << (k ? ", " : "") << r * std::sin(a) << ", " << -r * std::cos(a) << ", 0";
  }
  s << "\nCURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\nPTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\n"
       "ACCGRAV/ JGRAV=-9.81\nREQUEST/1, DISPLACEMENT, I=20, J=10\nEND\n";
  return s.str();
}

TEST(CurveRunState, CommittedParameterFollowsTheBead) {
  const fs::path dir = scratch("ptcv-warm");
  write(dir / "b.adm", beadOnCircle());
  commands::SessionOptions o;
  o.outputDirectory = dir.string();
  o.echoDiagnostics = false;
  commands::Session s(o);
  ASSERT_TRUE(s.loadModel((dir / "b.adm").string(), "b"));
  ASSERT_TRUE(command(s, "INTEGRATOR/GSTIFF, ERROR=1e-9, HMAX=0.005"));
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=2, STEPS=20"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& p = s.state()->expressions->curveParameters();
  ASSERT_EQ(p.size(), 1u);
  const auto& l = s.system()->layout();
  const double x = s.state()->y(l.body(0) + 0), y = s.state()->y(l.body(0) + 1);
  const double theta = std::atan2(x, -y);  // from the bottom, counter-clockwise
  // The curve passes its points at uniform alpha; between them the cubic's parameter departs
  // from the arc's by well under 1e-3 (the points are 0.1 rad apart).
  EXPECT_NEAR(std::remainder(p[0] - (-1.0 + theta / std::numbers::pi), 2.0), 0.0, 1e-3)
      << "alpha " << p[0] << " theta " << theta;
  std::printf(
      "bead on a circle, 2 s through the run driver: %.2f s; committed alpha %.6f at "
      "theta %.6f\n",
      seconds, p[0], theta);
}

// PTCV and CVCV keep their curve parameters in the run state (the searches' warm start): a
// bead on a closed circular wire (PTCV) and a cam (a unit circle 0.3 off its pivot, turned by a
// MOTION) against a roller (a unit circle) on a translational joint (CVCV) continue
// bit-identically after SAVE and RELOAD in a new session (docs/save-format.md, format 2).
std::string curveModel() {
  std::ostringstream s;
  s.precision(17);
  s << "curves\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
       "MARKER/11, PART=1, FLOATING\nMARKER/13, PART=1, QP=5,0,0\n"
       "MARKER/14, PART=1, QP=5,0,0, ZP=5,1,0, XP=6,0,0\n"
       "MATRIX/1, FULL=RORDER, ROWS=33, COLUMNS=3, VALUES=";
  for (int k = 0; k <= 32; ++k) {
    const double a = 2.0 * std::numbers::pi * (k % 32) / 32;
    s << (k ? ", " : "") << std::cos(a) << ", " << std::sin(a) << ", 0";
  }
  s << "\nCURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
       "PART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3, QG=1,0,0\nMARKER/20, PART=2\n"
       "PTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\n"
       "PART/3, MASS=1, CM=30, IP=1,1,1, QG=5,0,0\nMARKER/30, PART=3\n"
       "MARKER/31, PART=3, QP=0.3,0,0\nMARKER/32, PART=3, FLOATING\n"
       "JOINT/3, REVOLUTE, I=30, J=13\nMOTION/3, JOINT=3, ROTATION, FUNCTION=3*TIME\n"
       "PART/4, MASS=1, CM=40, IP=1,1,1, QG=5,"
    << std::sqrt(4.0 - 0.09)
    << ",0\nMARKER/40, PART=4, ZP=0,1,0, XP=1,0,0\nMARKER/41, PART=4\n"
       "MARKER/42, PART=4, FLOATING\nJOINT/4, TRANSLATIONAL, I=40, J=14\n"
       "CVCV/1, ICURVE=1, IRM=31, IFLOAT=32, JCURVE=1, JRM=41, JFLOAT=42\n"
       "ACCGRAV/JGRAV=-9.81\n"
       "REQUEST/1, DISPLACEMENT, I=20, J=10\nREQUEST/2, FORCE, I=41, J=31\n"
       "OUTPUT/REQSAVE\nEND\n";
  return s.str();
}

TEST(CurveRunState, SaveAndReloadContinueBitIdentically) {
  const fs::path dir = scratch("curves-save");
  write(dir / "m.adm", curveModel());
  auto session = [&](const std::string& prefix, const std::vector<std::string>& lines) {
    commands::SessionOptions o;
    o.outputDirectory = dir.string();
    o.echoDiagnostics = false;
    commands::Session s(o);
    EXPECT_TRUE(s.loadModel((dir / "m.adm").string(), prefix));
    for (const std::string& c : lines) EXPECT_TRUE(command(s, c)) << c;
    EXPECT_EQ(s.diagnostics().errorCount(), 0);
    if (prefix == "a") {
      const auto& p = s.state()->expressions->curveParameters();
      EXPECT_EQ(p.size(), 3u);  // PTCV alpha, CVCV alpha and beta: committed, finite
      for (double v : p) EXPECT_TRUE(std::isfinite(v));
    }
    return slurp(dir / (prefix + ".req"));
  };
  const std::string g = "INTEGRATOR/GSTIFF, ERROR=1e-6";
  const std::string u = session(
      "u", {g, "SIMULATE/DYNAMICS, END=1, STEPS=10", "SIMULATE/DYNAMICS, END=2, STEPS=10", "STOP"});
  const std::string a =
      session("a", {g, "SIMULATE/DYNAMICS, END=1, STEPS=10", "SAVE/STATES, FILE=at1.sav", "STOP"});
  const std::string b = session(
      "b", {g, "RELOAD/STATES, FILE=at1.sav", "SIMULATE/DYNAMICS, END=2, STEPS=10", "STOP"});
  EXPECT_NE(slurp(dir / "at1.sav").find("vector curve-parameters 3"), std::string::npos);
  // b's header is a's; its steps continue a's: u == a + (b after the common header).
  std::size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  const std::size_t header = a.rfind('\n', n - 1) + 1;
  ASSERT_GT(b.size() - header, 10u);  // something was compared
  EXPECT_LT(a.size(), u.size());
  EXPECT_EQ(u, a + b.substr(header));
}

}  // namespace
}  // namespace openmss
