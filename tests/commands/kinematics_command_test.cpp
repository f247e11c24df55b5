// The KINEMATICS statement and command (docs/language.md, "KINEMATICS") on a crank-rocker
// four-bar driven by a MOTION, against the closed form of the loop: ground pivots A = (0,0)
// and D = (3,0), crank AB = 1, coupler BC = 3, rocker DC = 2 (Grashof: 1 + 3 <= 3 + 2, the
// crank turns fully). For crank angle q = TIME, B = (cos q, sin q) and C is the intersection of
// the circles about B (radius 3) and D (radius 2) on the branch of the data set (y > 0 at
// q = 0); the transmission angle stays within acos(0.75)..acos(-0.25), so the branch never
// changes. The parts' centres of mass sit at the links' midpoints.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, write (tests/support)

std::string fourBar(const std::string& extra) {
  return "four-bar crank-rocker\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\n"
         "MARKER/10, PART=1, QP=0,0,0\nMARKER/11, PART=1, QP=3,0,0\n"
         "PART/2, MASS=1, IP=1,1,1, CM=20\nMARKER/20, PART=2, QP=0.5,0,0\n"
         "MARKER/21, PART=2, QP=0,0,0\nMARKER/22, PART=2, QP=1,0,0\n"
         "PART/3, MASS=1, IP=1,1,1, CM=30\nMARKER/30, PART=3, QP=2.125,0.9921567416492215,0\n"
         "MARKER/31, PART=3, QP=1,0,0\nMARKER/32, PART=3, QP=3.25,1.984313483298443,0\n"
         "PART/4, MASS=1, IP=1,1,1, CM=40\nMARKER/40, PART=4, QP=3.125,0.9921567416492215,0\n"
         "MARKER/41, PART=4, QP=3,0,0\nMARKER/42, PART=4, QP=3.25,1.984313483298443,0\n"
         "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=22, J=31\n"
         "JOINT/3, REVOLUTE, I=32, J=42\nJOINT/4, REVOLUTE, I=41, J=11\n"
         "MOTION/1, JOINT=1, FUNCTION=TIME\nACCGRAV/ JGRAV=-9.81\n" +
         extra + "END\n";
}

// Closed form: the coupler-rocker pin C at crank angle q.
Eigen::Vector2d pinC(double q) {
  const Eigen::Vector2d b(std::cos(q), std::sin(q)), d(3.0, 0.0);
  const Eigen::Vector2d u = (d - b).normalized();
  const double l = (d - b).norm();
  const double along = (9.0 - 4.0 + l * l) / (2.0 * l);
  const double h = std::sqrt(9.0 - along * along);
  return b + along * u + h * Eigen::Vector2d(-u.y(), u.x());
}

struct KinematicRun {
  std::unique_ptr<commands::Session> session;
  Diagnostics readerDiagnostics;
  bool loaded = false, ok = true;
  double worst = 0.0;  // largest CM position error against the closed form over the outputs
  int compared = 0;    // outputs compared
};

// Loads the four-bar (with `extra` statements), executes `settings`, then 30 kinematic steps
// of 0.1 s (one output each, so that the state of every output is compared).
KinematicRun kinematics(const std::string& name, const std::string& extra,
                        const std::vector<std::string>& settings) {
  KinematicRun r;
  const fs::path dir = scratch(name);
  write(dir / "f.adm", fourBar(extra));
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  r.session = std::make_unique<commands::Session>(options);
  r.loaded = r.session->loadModel((dir / "f.adm").string(), "f");
  if (!r.loaded) return r;
  language::CommandReader reader("f.acf", 3);
  for (const auto& c : settings) reader.feedLine(c);
  for (int i = 1; i <= 30; ++i)
    reader.feedLine("SIMULATE/KINEMATICS, END=" + std::to_string(0.1 * i) + ", STEPS=1");
  reader.finish();
  r.readerDiagnostics = reader.takeDiagnostics();
  const auto* sys = r.session->system();
  for (const auto& c : reader.takeCommands()) {
    r.ok = r.session->execute(c);
    if (!r.ok) return r;
    if (c.name != "SIMULATE") continue;
    const auto& s = *r.session->state();
    const double q = s.t;
    const Eigen::Vector2d b(std::cos(q), std::sin(q)), cc = pinC(q), d(3.0, 0.0);
    const Eigen::Vector2d expected[3] = {0.5 * b, 0.5 * (b + cc), 0.5 * (cc + d)};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d at = s.y.segment<3>(sys->layout().body(k) + 0);
      r.worst = std::max({r.worst, (at.head<2>() - expected[k]).norm(), std::abs(at.z())});
    }
    ++r.compared;
  }
  return r;
}

// Test 1 of issue 20 item 3: the command sets the tolerances before SIMULATE/KINEMATICS.
TEST(KinematicsCommand, TightTolerancesGiveTheClosedFormFourBar) {
  const KinematicRun r =
      kinematics("kin_tight", "", {"KINEMATICS/ERROR=1e-10, AERROR=1e-10, LIST"});
  ASSERT_TRUE(r.loaded && r.ok);
  EXPECT_EQ(r.compared, 30);
  EXPECT_DOUBLE_EQ(r.session->model()->kinematics.error, 1e-10);
  EXPECT_DOUBLE_EQ(r.session->model()->kinematics.accelerationError, 1e-10);
  // |Phi| <= 1e-10 on unit-size links; Newton's last step makes it far smaller.
  EXPECT_LT(r.worst, 1e-9);
}

// A looser ERROR is not ignored: fewer Newton iterations and a result further from the closed
// form (|Phi| may stay up to 1e-3 after the first-order prediction and one correction).
TEST(KinematicsCommand, LooserErrorTakesFewerIterationsAndIsLessAccurate) {
  const KinematicRun tight = kinematics("kin_tight2", "", {"KINEMATICS/ERROR=1e-10"});
  const KinematicRun loose = kinematics("kin_loose", "", {"KINEMATICS/ERROR=1e-3"});
  ASSERT_TRUE(tight.ok && loose.ok);
  EXPECT_EQ(loose.compared, 30);
  EXPECT_LT(loose.session->summary().kinematicIterations,
            tight.session->summary().kinematicIterations);
  EXPECT_GT(loose.worst, 1e-8);
  EXPECT_LT(loose.worst, 1e-2);
}

// The statement form in the data set is read and applied, and DEFAULT restores the defaults.
TEST(KinematicsStatement, IsReadAndApplied) {
  const KinematicRun r = kinematics("kin_stmt", "KINEMATICS/ ERROR=1e-3, MAXIT=7, HMAX=0.05\n", {});
  ASSERT_TRUE(r.loaded && r.ok);
  const auto& k = r.session->model()->kinematics;
  EXPECT_DOUBLE_EQ(k.error, 1e-3);
  EXPECT_EQ(k.maxit, 7);
  ASSERT_TRUE(k.hmax.has_value());
  EXPECT_DOUBLE_EQ(*k.hmax, 0.05);
  EXPECT_GT(r.worst, 1e-9);  // ERROR=1e-3 applied: not the default 1e-12's accuracy
  EXPECT_LT(r.worst, 1e-2);
  const KinematicRun d =
      kinematics("kin_stmt_default", "KINEMATICS/ ERROR=1e-3\n", {"KINEMATICS/DEFAULT"});
  ASSERT_TRUE(d.ok);
  EXPECT_DOUBLE_EQ(d.session->model()->kinematics.error, 1e-12);
  EXPECT_LT(d.worst, 1e-9);
}

// MAXIT=1 cannot close a 0.1 rad step to 1e-12: the run stops with a located message.
TEST(KinematicsCommand, MaxitIsApplied) {
  const KinematicRun r = kinematics("kin_maxit", "", {"KINEMATICS/MAXIT=1"});
  ASSERT_TRUE(r.loaded);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.compared, 0);
}

// Bad input: one located error each, and the settings stay as they were.
TEST(KinematicsCommand, BadArgumentsAreOneLocatedErrorEach) {
  {
    const KinematicRun r = kinematics("kin_neg", "", {"KINEMATICS/ERROR=-1e-6"});
    EXPECT_FALSE(r.ok);
    const auto& all = r.session->diagnostics().all();
    ASSERT_EQ(r.session->diagnostics().errorCount(), 1);
    int located = 0;
    for (const auto& d : all)
      if (d.severity == Severity::Error) {
        EXPECT_EQ(d.where.file, "f.acf");
        EXPECT_EQ(d.where.line, 3);
        EXPECT_NE(d.message.find("ERROR"), std::string::npos) << d.message;
        ++located;
      }
    EXPECT_EQ(located, 1);
    EXPECT_DOUBLE_EQ(r.session->model()->kinematics.error, 1e-12);
  }
  {
    const KinematicRun r = kinematics("kin_typo", "", {"KINEMATICS/EROR=1e-6"});
    ASSERT_EQ(r.readerDiagnostics.errorCount(), 1);
    EXPECT_EQ(r.readerDiagnostics.all().front().where.line, 3);
    EXPECT_NE(r.readerDiagnostics.all().front().message.find("EROR"), std::string::npos)
        << r.readerDiagnostics.all().front().message;
  }
  {
    const KinematicRun r = kinematics("kin_stmt_neg", "KINEMATICS/ ERROR=-1\n", {});
    EXPECT_FALSE(r.loaded);
    ASSERT_EQ(r.session->diagnostics().errorCount(), 1);
    for (const auto& d : r.session->diagnostics().all())
      if (d.severity == Severity::Error) {
        EXPECT_EQ(d.where.line, 24);
      }
  }
}

// AMAXIT and APATTERN have no effect on a direct linear solve: one warning each, no error.
TEST(KinematicsCommand, AccelerationIterationControlsWarn) {
  const KinematicRun r = kinematics("kin_amaxit", "", {"KINEMATICS/AMAXIT=5, APATTERN=T:F"});
  ASSERT_TRUE(r.ok);
  int warnings = 0;
  for (const auto& d : r.session->diagnostics().all())
    if (d.severity == Severity::Warning && d.message.find("has no effect") != std::string::npos)
      ++warnings;
  EXPECT_EQ(warnings, 2);
  EXPECT_EQ(r.compared, 30);
}

}  // namespace
