// ACTIVATE, DEACTIVATE and the redefining commands (docs/commands.md) against closed forms:
// a pendulum held by a MOTION and released, a pendulum on a redundant pair of hinges, a body
// pushed by an SFORCE whose FUNCTION is redefined mid-study, a body falling under an ACCGRAV
// changed between two SIMULATEs; and bad commands that must leave the run as it was.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analysis/request_values.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, write (tests/support)

constexpr double kG = 9.81;

struct Study {
  std::unique_ptr<commands::Session> session;
  Diagnostics readerDiagnostics;
  bool loaded = false;
  std::vector<bool> results;  // one per command
};

// Loads `adm`, reads `acf` lines as a command file (line 3 on) and executes every command,
// calling `after` after each SIMULATE.
template <class After>
Study run(const std::string& name, const std::string& adm, const std::vector<std::string>& acf,
          After&& after) {
  Study r;
  const fs::path dir = scratch(name);
  write(dir / "m.adm", adm);
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  options.printInformation = false;
  r.session = std::make_unique<commands::Session>(options);
  r.loaded = r.session->loadModel((dir / "m.adm").string(), "m");
  if (!r.loaded) return r;
  language::CommandReader reader("m.acf", 3);
  for (const auto& c : acf) reader.feedLine(c);
  reader.finish();
  r.readerDiagnostics = reader.takeDiagnostics();
  for (const auto& c : reader.takeCommands()) {
    r.results.push_back(r.session->execute(c));
    if (c.name == "SIMULATE" && r.results.back()) after(*r.session);
  }
  return r;
}

Study run(const std::string& name, const std::string& adm, const std::vector<std::string>& acf) {
  return run(name, adm, acf, [](const commands::Session&) {});
}

Eigen::Vector3d cmPosition(const commands::Session& s, int body = 0) {
  return s.state()->y.segment<3>(s.system()->layout().body(body));
}

// ---- Pendulum: a rod of mass 1 whose CM is L = 1 from a revolute pivot at the origin ----
// Ic = 0.1 about the CM (z), so I_pivot = 1.1; angle from hanging down, in the XY plane.
constexpr double kTheta0 = 0.8;  // large: the exact (not small-angle) period applies
constexpr double kIc = 0.1;

std::string exact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string pendulum(const std::string& joints, double theta0) {
  const double x = std::sin(theta0), y = -std::cos(theta0);
  return "pendulum\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n"
         "MARKER/12, PART=1, QP=0,0,1\n"
         "PART/2, MASS=1, IP=0.1,0.1,0.1, CM=21\nMARKER/20, PART=2, QP=0,0,0\n"
         "MARKER/22, PART=2, QP=0,0,1\nMARKER/21, PART=2, QP=" +
         exact(x) + "," + exact(y) +
         ",0\nACCGRAV/ JGRAV=-9.81\n"
         "REQUEST/1, FORCE, I=20, J=10\nREQUEST/2, FORCE, I=22, J=12\n" +
         joints + "END\n";
}

double pendulumAngle(const commands::Session& s) {
  const Eigen::Vector3d r = cmPosition(s);
  return std::atan2(r.x(), -r.y());
}

// Reference: theta'' = -(m g L / I_pivot) sin theta by classical RK4 with h = 1e-4 s (error
// ~ h^4 ~ 1e-16 per unit time, far below the tolerances below).
double referenceAngle(double theta0, double t) {
  const double k = kG / (1.0 + kIc);
  double q = theta0, w = 0.0;
  const int n = static_cast<int>(std::llround(t / 1e-4));
  const double h = t / n;
  for (int i = 0; i < n; ++i) {
    const double k1q = w, k1w = -k * std::sin(q);
    const double k2q = w + 0.5 * h * k1w, k2w = -k * std::sin(q + 0.5 * h * k1q);
    const double k3q = w + 0.5 * h * k2w, k3w = -k * std::sin(q + 0.5 * h * k2q);
    const double k4q = w + h * k3w, k4w = -k * std::sin(q + h * k3q);
    q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return q;
}

std::vector<std::string> releaseSteps(int n, double dt) {
  std::vector<std::string> c;
  for (int i = 1; i <= n; ++i)
    c.push_back("SIMULATE/DYNAMICS, END=" + std::to_string(i * dt) + ", STEPS=1");
  return c;
}

// Issue 15: a MOTION holds the pendulum at theta0 through a static equilibrium; DEACTIVATE
// frees it and the next SIMULATE swings it as the free pendulum released from rest at theta0.
TEST(ElementCommands, DeactivatedMotionReleasesThePendulumFromTheHeldAngle) {
  std::vector<std::string> acf = {"INTEGRATOR/GSTIFF, ERROR=1e-8", "SIMULATE/STATICS",
                                  "DEACTIVATE/MOTION, ID=1"};
  for (const auto& c : releaseSteps(20, 0.1)) acf.push_back(c);
  int compared = 0;
  double worst = 0.0, energyDrift = 0.0;
  bool heldAtStatics = false;
  const Study r = run(
      "release",
      pendulum("JOINT/1, REVOLUTE, I=20, J=10\nMOTION/1, JOINT=1, FUNCTION=0\n", kTheta0), acf,
      [&](const commands::Session& s) {
        if (s.state()->t == 0.0) {  // the static equilibrium, motion held
          heldAtStatics = std::abs(pendulumAngle(s) - kTheta0) < 1e-9;
          return;
        }
        worst = std::max(worst, std::abs(pendulumAngle(s) - referenceAngle(kTheta0, s.state()->t)));
        // Energy: 1/2 I_pivot w^2 - m g L cos(theta), conserved.
        const int o = s.system()->layout().body(0);
        const double w = s.state()->y(o + 12);  // body z rate (z along ground z)
        const double e = 0.5 * (1.0 + kIc) * w * w - kG * std::cos(pendulumAngle(s));
        energyDrift = std::max(energyDrift, std::abs(e + kG * std::cos(kTheta0)));
        ++compared;
      });
  ASSERT_TRUE(r.loaded);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  EXPECT_TRUE(heldAtStatics);
  EXPECT_EQ(compared, 20);
  EXPECT_EQ(r.session->degreesOfFreedom(), 1);
  // ERROR=1e-8 on the displacements over 2 s (almost a full period, 2.06 s for this rod):
  // the global error stays well under 1e-5 rad; the energy, 1e-5 J of 9.81*(1-cos 0.8) = 3.0 J.
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(energyDrift, 1e-5);
  std::printf("  released pendulum: %d outputs, worst angle error %.3g rad, energy drift %.3g J\n",
              compared, worst, energyDrift);
}

// Issue 15: two coaxial hinges are redundant (10 equations, 5 independent); with one
// deactivated, the reactions equal those of the data set with one hinge, and at the static
// equilibrium the hinge carries the weight m g.
TEST(ElementCommands, DeactivatedRedundantHingeGivesTheOneHingeReactions) {
  const std::string twoHinges = "JOINT/1, REVOLUTE, I=20, J=10\nJOINT/2, REVOLUTE, I=22, J=12\n";
  const std::string oneHinge = "JOINT/1, REVOLUTE, I=20, J=10\n";
  auto reactions = [](const commands::Session& s) {
    std::vector<double> out;
    for (const auto& rq : s.model()->requests) {
      const auto c =
          analysis::requestColumns(*s.system(), rq, s.state()->t, s.state()->y, s.state()->yp);
      out.insert(out.end(), c.begin(), c.end());
    }
    return out;
  };
  std::vector<std::string> acf = {"INTEGRATOR/GSTIFF, ERROR=1e-9", "DEACTIVATE/JOINT, ID=2"};
  for (const auto& c : releaseSteps(10, 0.1)) acf.push_back(c);
  std::vector<std::vector<double>> a, b;
  const Study deactivated = run("redundant", pendulum(twoHinges, 0.5), acf,
                                [&](const commands::Session& s) { a.push_back(reactions(s)); });
  acf.erase(acf.begin() + 1);
  const Study single = run("one-hinge", pendulum(oneHinge, 0.5), acf,
                           [&](const commands::Session& s) { b.push_back(reactions(s)); });
  ASSERT_TRUE(deactivated.loaded && single.loaded);
  ASSERT_EQ(a.size(), 10u);
  ASSERT_EQ(b.size(), a.size());
  int compared = 0;
  for (size_t k = 0; k < a.size(); ++k)
    for (size_t c = 0; c < a[k].size(); ++c, ++compared)
      EXPECT_NEAR(a[k][c], b[k][c], 1e-9 * (1.0 + std::abs(b[k][c]))) << k << " " << c;
  EXPECT_EQ(compared, 160);
  // The swinging hinge carries a load (not a vacuous comparison).
  EXPECT_GT(std::abs(a.back()[0]), 1.0);

  // Statics, hanging: before the deactivation the two hinges share m g; after it one carries it.
  const Study statics = run("redundant-statics", pendulum(twoHinges, 0.0),
                            {"SIMULATE/STATICS", "DEACTIVATE/JOINT, ID=2", "SIMULATE/STATICS"},
                            [&](const commands::Session&) {});
  ASSERT_TRUE(statics.loaded);
  for (bool ok : statics.results) EXPECT_TRUE(ok);
  const auto r = reactions(*statics.session);
  EXPECT_NEAR(r[0], kG, 1e-9);    // |F| of JOINT/1
  EXPECT_NEAR(r[8], 0.0, 1e-12);  // JOINT/2 is gone
  double worst = 0.0;
  for (size_t k = 0; k < a.size(); ++k)
    for (size_t c = 0; c < a[k].size(); ++c) worst = std::max(worst, std::abs(a[k][c] - b[k][c]));
  std::printf(
      "  redundant hinge: %d reaction values, worst difference %.3g N; static |F| - m g "
      "= %.3g N\n",
      compared, worst, r[0] - kG);
}

// A MOTION redefined mid-study (the corpus's MOTION/id, FUNCTION=... commands): the pendulum's
// hinge turns as 0.5 TIME until t = 1, then as 0.5 + 2 (TIME - 1); kinematics gives the angle
// exactly (to the position tolerance) at every output.
TEST(ElementCommands, RedefinedMotionFunctionDrivesTheJointFromTheNextSimulate) {
  std::vector<std::string> acf = {"KINEMATICS/ERROR=1e-12"};
  for (int i = 1; i <= 4; ++i)
    acf.push_back("SIMULATE/KINEMATICS, END=" + std::to_string(0.25 * i) + ", STEPS=1");
  acf.push_back("MOTION/1, FUNCTION=0.5+2*(TIME-1)");
  for (int i = 5; i <= 8; ++i)
    acf.push_back("SIMULATE/KINEMATICS, END=" + std::to_string(0.25 * i) + ", STEPS=1");
  int compared = 0;
  double worst = 0.0;
  const Study r =
      run("motion",
          pendulum("JOINT/1, REVOLUTE, I=20, J=10\nMOTION/1, JOINT=1, FUNCTION=0.5*TIME\n", 0.0),
          acf, [&](const commands::Session& s) {
            const double t = s.state()->t;
            const double q = t <= 1.0 + 1e-12 ? 0.5 * t : 0.5 + 2.0 * (t - 1.0);
            worst = std::max(worst, std::abs(pendulumAngle(s) - q));
            ++compared;
          });
  ASSERT_TRUE(r.loaded);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  EXPECT_EQ(compared, 8);
  EXPECT_LT(worst, 1e-9);  // KINEMATICS/ERROR=1e-12 on unit-length geometry
  std::printf("  redefined MOTION: %d outputs, worst angle error %.3g rad\n", compared, worst);
}

// ---- A free body of mass 2 (no gravity unless ACCGRAV says) ----
std::string freeBody(const std::string& extra) {
  return "free body\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n"
         "PART/2, MASS=2, IP=1,1,1, CM=20\nMARKER/20, PART=2, QP=0,0,0\n" +
         extra + "END\n";
}

// Issue 15: F = 3 N along ground z for 0 <= t <= 1, then the SFORCE is redefined to
// F = -2 TIME. With m = 2: z(1) = 0.75, v(1) = 1.5; afterwards a = -t, so
// v(t) = 1.5 - (t^2 - 1)/2 and z(t) = 0.75 + 1.5 (t - 1) - ((t^3 - 1)/3 - (t - 1))/2.
TEST(ElementCommands, RedefinedSForceFunctionMidStudy) {
  std::vector<std::string> acf = {"INTEGRATOR/GSTIFF, ERROR=1e-9"};
  for (int i = 1; i <= 4; ++i)
    acf.push_back("SIMULATE/DYNAMICS, END=" + std::to_string(0.25 * i) + ", STEPS=1");
  acf.push_back("SFORCE/1, FUNCTION=-2*TIME, LIST");
  for (int i = 5; i <= 8; ++i)
    acf.push_back("SIMULATE/DYNAMICS, END=" + std::to_string(0.25 * i) + ", STEPS=1");
  int compared = 0;
  double worst = 0.0;
  const Study r =
      run("sforce", freeBody("SFORCE/1, TRANSLATION, ACTIONONLY, I=20, J=10, FUNCTION=3\n"), acf,
          [&](const commands::Session& s) {
            const double t = s.state()->t;
            const double z = t <= 1.0 + 1e-12
                                 ? 0.75 * t * t
                                 : 0.75 + 1.5 * (t - 1) - ((t * t * t - 1) / 3 - (t - 1)) / 2;
            worst = std::max(worst, std::abs(cmPosition(s).z() - z));
            ++compared;
          });
  ASSERT_TRUE(r.loaded);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  EXPECT_EQ(compared, 8);
  // Polynomial motion integrated at ERROR=1e-9: the BDF's error is at the tolerance's level.
  EXPECT_LT(worst, 1e-6);
  std::printf("  redefined SFORCE: %d outputs, worst z error %.3g m\n", compared, worst);
}

// VARIABLE and PART redefined together: F = VARVAL(1) = 3 N on m = 2 for 0 <= t <= 1, then
// VARIABLE/1, FUNCTION=-2*TIME and PART/2, MASS=1: a = -2 t, so v(t) = 1.5 - (t^2 - 1) and
// z(t) = 0.75 + 1.5 (t - 1) - ((t^3 - 1)/3 - (t - 1)).
TEST(ElementCommands, RedefinedVariableAndPartMassMidStudy) {
  std::vector<std::string> acf = {
      "INTEGRATOR/GSTIFF, ERROR=1e-9", "SIMULATE/DYNAMICS, END=1, STEPS=4",
      "VARIABLE/1, FUNCTION=-2*TIME", "PART/2, MASS=1, LIST", "SIMULATE/DYNAMICS, END=2, STEPS=4"};
  const Study r =
      run("variable-mass",
          freeBody("VARIABLE/1, FUNCTION=3\n"
                   "SFORCE/1, TRANSLATION, ACTIONONLY, I=20, J=10, FUNCTION=VARVAL(1)\n"),
          acf);
  ASSERT_TRUE(r.loaded);
  ASSERT_EQ(r.results.size(), 5u);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  const double expected = 0.75 + 1.5 - (7.0 / 3.0 - 1.0);
  EXPECT_NEAR(cmPosition(*r.session).z(), expected, 1e-6);
  EXPECT_DOUBLE_EQ(r.session->model()->parts[1].mass, 1.0);
  std::printf("  redefined VARIABLE and MASS: z(2) error %.3g m\n",
              cmPosition(*r.session).z() - expected);
}

// PART/id, CM= moves the body frame: the carried state is that of the new CM marker, a point
// of the same moving body. A free symmetric body (no gravity) translating at VX = 1 and
// spinning at WZ = 2 turns by 1 rad in 0.5 s; the marker d = (1, 0, 0) from the old CM is then
// at (0.5 + cos 1, sin 1, 0) with velocity v + w x d = (1 - 2 sin 1, 2 cos 1, 0).
TEST(ElementCommands, RedefinedCentreOfMassCarriesTheMotionOfTheBody) {
  const Study r = run("cm",
                      "cm\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
                      "PART/2, MASS=2, IP=1,1,1, CM=20, VX=1, WZ=2\nMARKER/20, PART=2\n"
                      "MARKER/22, PART=2, QP=1,0,0\nEND\n",
                      {"INTEGRATOR/GSTIFF, ERROR=1e-10", "SIMULATE/DYNAMICS, END=0.5, STEPS=1",
                       "PART/2, CM=22", "SIMULATE/INITIAL_CONDITIONS"});
  ASSERT_TRUE(r.loaded);
  ASSERT_EQ(r.results.size(), 4u);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  const auto& y = r.session->state()->y;
  const int o = r.session->system()->layout().body(0);
  const Eigen::Vector3d at(0.5 + std::cos(1.0), std::sin(1.0), 0.0);
  const Eigen::Vector3d v(1.0 - 2.0 * std::sin(1.0), 2.0 * std::cos(1.0), 0.0);
  // The rotation is integrated at ERROR=1e-10 for 0.5 s: errors of order 1e-8.
  EXPECT_LT((y.segment<3>(o) - at).norm(), 1e-6);
  EXPECT_LT((y.segment<3>(o + 7) - v).norm(), 1e-6);
  EXPECT_NEAR(y(o + 12), 2.0, 1e-9);  // the spin is the body's, unchanged
  std::printf("  redefined CM: position error %.3g m, velocity error %.3g m/s\n",
              (y.segment<3>(o) - at).norm(), (y.segment<3>(o + 7) - v).norm());
}

// Issue 15: ACCGRAV added by command (the data set has none), then changed: g1 = 9.81 down z
// for 1 s, then g2 = 1.62: z(2) = -g1/2 - g1 - g2/2.
TEST(ElementCommands, AccgravChangedBetweenTwoSimulates) {
  const Study r = run(
      "accgrav", freeBody(""),
      {"INTEGRATOR/GSTIFF, ERROR=1e-9", "ACCGRAV/ KGRAV=-9.81", "SIMULATE/DYNAMICS, END=1, STEPS=4",
       "ACCGRAV/ KGRAV=-1.62, LIST", "SIMULATE/DYNAMICS, END=2, STEPS=4"});
  ASSERT_TRUE(r.loaded);
  ASSERT_EQ(r.results.size(), 5u);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  const double expected = -9.81 / 2 - 9.81 - 1.62 / 2;
  EXPECT_NEAR(cmPosition(*r.session).z(), expected, 1e-6);
  std::printf("  ACCGRAV changed: z(2) error %.3g m\n", cmPosition(*r.session).z() - expected);
  EXPECT_NEAR(r.session->model()->gravity.z(), -1.62, 0.0);
}

// Issue 15: a bad command gives one located error and changes nothing: the next SIMULATE
// gives, bit for bit, the state of the run without it.
TEST(ElementCommands, BadCommandsGiveOneLocatedErrorAndChangeNothing) {
  const std::string adm = pendulum(
      "JOINT/1, REVOLUTE, I=20, J=10\nSFORCE/1, ROTATION, I=20, J=10, FUNCTION=-0.5\n", 0.3);
  const std::vector<std::string> base = {"SIMULATE/DYNAMICS, END=0.5, STEPS=5"};
  const Study reference = run("bad-reference", adm, base);
  ASSERT_TRUE(reference.loaded);
  const std::vector<std::string> bad = {
      "DEACTIVATE/JOINT, ID=99",         // no such joint
      "DEACTIVATE/SFORCE, RANGE=50,60",  // none in the range
      "SFORCE/7, FUNCTION=1",            // no such SFORCE
      "JOINT/1, I=22",                   // not changeable by command
      "SFORCE/1, FUNCTION=1+",           // does not parse
      "DEACTIVATE/JOINT",                // nothing named
      "CONTROL/ ROUTINE=consub",         // no FUNCTION=USER(...) for CONSUB
  };
  int checked = 0;
  for (const auto& b : bad) {
    const Study r = run("bad", adm, {b, base[0]});
    ASSERT_TRUE(r.loaded);
    ASSERT_EQ(r.results.size(), 2u) << b;
    EXPECT_FALSE(r.results[0]) << b;
    EXPECT_TRUE(r.results[1]) << b;
    const auto& d = r.session->diagnostics();
    ASSERT_EQ(d.errorCount(), 1) << b;
    for (const auto& e : d.all())
      if (e.severity == Severity::Error) {
        EXPECT_EQ(e.where.file, "m.acf") << b;
        EXPECT_EQ(e.where.line, 3) << b;
      }
    EXPECT_EQ(r.session->state()->y, reference.session->state()->y) << b;
    ++checked;
  }
  EXPECT_EQ(checked, 7);
  // An argument the command does not have: the reader's one located error.
  const Study r = run("bad-argument", adm, {"SFORCE/1, STIFFNESS=3", base[0]});
  EXPECT_EQ(r.readerDiagnostics.errorCount(), 1);
  EXPECT_EQ(r.readerDiagnostics.all().at(0).where.line, 3);
}

// ACTIVATE undoes DEACTIVATE: the run equals, bit for bit, the run with neither.
TEST(ElementCommands, ActivateUndoesDeactivate) {
  const std::string adm = pendulum(
      "JOINT/1, REVOLUTE, I=20, J=10\nSFORCE/1, ROTATION, I=20, J=10, FUNCTION=-0.5\n", 0.3);
  const Study plain = run("plain", adm, {"SIMULATE/DYNAMICS, END=0.5, STEPS=5"});
  const Study toggled = run(
      "toggled", adm,
      {"DEACTIVATE/SFORCE, ID=1", "ACTIVATE/SFORCE, ID=1", "SIMULATE/DYNAMICS, END=0.5, STEPS=5"});
  ASSERT_TRUE(plain.loaded && toggled.loaded);
  for (bool ok : toggled.results) EXPECT_TRUE(ok);
  EXPECT_EQ(plain.session->state()->y, toggled.session->state()->y);
  // And a deactivated SFORCE changes the motion (the comparison above can fail).
  const Study off =
      run("off", adm, {"DEACTIVATE/SFORCE, ID=1", "SIMULATE/DYNAMICS, END=0.5, STEPS=5"});
  EXPECT_GT((off.session->state()->y - plain.session->state()->y).norm(), 1e-3);
}

}  // namespace
