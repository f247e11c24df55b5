// COUPLER whole turns (docs/theory.md §5b) are counted from the angle committed at the last
// accepted state, never from the last evaluation: a Newton trial or a rejected step far from
// the solution does not move the count, and a run through many turns, with steps rejected at a
// jump of the driving torque, follows the closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>

#include "analysis/run_state.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"
#include "support/random_state.hpp"

namespace openmss {
namespace {

namespace fs = std::filesystem;
using testing::scratch;
using testing::slurp;
using testing::write;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Part 2 turns on JOINT/1 about ground z at the origin, part 3 on JOINT/2 about ground z at
// x = 3; COUPLER/1 holds q1 - 2 q2 = 0 (SCALES=-2: r1 = 1, r2 = -2), so q2 = q1 / 2.
const char* kCoupled =
    "coupler turns\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=3, 0, 0\n"
    "PART/2, MASS=1, CM=20, IP=1, 1, 1\nMARKER/20, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1, 1, 1\nMARKER/30, PART=3, QP=3, 0, 0\n"
    "JOINT/1, REVOLUTE, I=20, J=10\nJOINT/2, REVOLUTE, I=30, J=11\n"
    "COUPLER/1, JOINTS=1, 2, TYPE=R, R, SCALES=-2\n";

// A trial evaluation 10 rad away (a Newton iterate of a step that is then rejected) leaves the
// count alone: the equation at the true state 2.5 rad on is zero, and committing that state
// gives the cumulative angles 2.5 and 1.25. (When the count followed every evaluation, the
// trial moved it by a turn and the equation read 2 pi off.)
TEST(CouplerTurns, TrialEvaluationsDoNotMoveTheCommittedTurnCount) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(std::string(kCoupled) + "END\n", "c.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  mechanics::MultibodySystem s(m);
  analysis::RunState run(s);
  int coupler = -1;
  for (int k = 0; k < s.constraints().size(); ++k)
    if (s.constraints().equations()[k].coupler >= 0) coupler = k;
  ASSERT_GE(coupler, 0);
  const auto& l = s.layout();
  const Eigen::Vector3d z(0, 0, 1);
  auto state = [&](double q1, double q2) {
    return testing::turned(testing::turned(run.y, l.body(0), z, q1), l.body(1), z, q2);
  };
  const Eigen::VectorXd y0 = run.y;
  EXPECT_NEAR(s.constraintValue(coupler, 0.0, y0.data()), 0.0, 1e-14);
  // The rejected trial: q1 = 10 rad (principal value 10 - 4 pi), q2 still 0.
  const Eigen::VectorXd trial = state(10.0, 0.0);
  EXPECT_NEAR(s.constraintValue(coupler, 0.0, trial.data()), 10.0 - 2 * kTwoPi, 1e-12);
  // The accepted state: q1 = 2.5, q2 = 1.25 satisfy q1 - 2 q2 = 0.
  const Eigen::VectorXd accepted = state(2.5, 1.25);
  EXPECT_NEAR(s.constraintValue(coupler, 0.0, accepted.data()), 0.0, 1e-12);
  run.expressions->commitCoupledAngles(s, accepted);
  ASSERT_EQ(run.expressions->coupledAngles().size(), 2u);
  EXPECT_NEAR(run.expressions->coupledAngles()[0], 2.5, 1e-12);
  EXPECT_NEAR(run.expressions->coupledAngles()[1], 1.25, 1e-12);
  // Turned on by 3 rad per step, each step committed: 15 steps = 45 rad = 7.2 turns.
  for (int k = 1; k <= 15; ++k) {
    const double q1 = 2.5 + 3.0 * k;
    const Eigen::VectorXd y = state(q1, q1 / 2);
    EXPECT_NEAR(s.constraintValue(coupler, 0.0, y.data()), 0.0, 1e-11) << q1;
    run.expressions->commitCoupledAngles(s, y);
  }
  EXPECT_NEAR(run.expressions->coupledAngles()[0], 47.5, 1e-10);
  EXPECT_NEAR(run.expressions->coupledAngles()[1], 23.75, 1e-10);
}

bool command(commands::Session& s, const std::string& text) {
  language::CommandReader reader("c.acf", 3);
  reader.feedLine(text);
  reader.finish();
  auto c = reader.takeCommands();
  EXPECT_EQ(c.size(), 1u);
  s.echoCommand(text);
  return s.execute(c.front());
}

// A torque of 25 on JOINT/1 until t = 1, then 75: with the coupled inertia Izz2 + Izz3 / 4 =
// 1.25 the driver accelerates at 20 rad/s^2, then 60. q1 = 10 t^2 for t <= 1, then
// 10 + 20 (t - 1) + 30 (t - 1)^2: 60 rad (9.5 turns) at t = 2. The jump of the torque makes
// the integrator reject steps there; HMAX = 0.02 keeps each accepted step below pi (80 rad/s
// at the end) as the whole-turn count needs (docs/theory.md §5b).
TEST(CouplerTurns, ManyTurnsWithRejectedStepsFollowTheClosedForm) {
  const fs::path dir = scratch("coupler-turns");
  write(dir / "c.adm", std::string(kCoupled) +
                           "SFORCE/1, ROTATIONAL, I=20, J=10, FUNCTION=IF(TIME-1: 25, 75, 75)\n"
                           "REQUEST/1, F2=AZ(20, 10), F3=AZ(30, 11)\nOUTPUT/REQSAVE\nEND\n");
  commands::SessionOptions o;
  o.outputDirectory = dir.string();
  o.echoDiagnostics = false;
  commands::Session s(o);
  ASSERT_TRUE(s.loadModel((dir / "c.adm").string(), "c"));
  ASSERT_TRUE(command(s, "INTEGRATOR/GSTIFF, ERROR=1e-7, HMAX=0.02"));
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=2, STEPS=20"));
  ASSERT_TRUE(command(s, "STOP"));
  const std::string msg = slurp(dir / "c.msg");
  const std::string key = "steps, ";
  const std::size_t at = msg.find("Integrator statistics: ");
  ASSERT_NE(at, std::string::npos) << msg;
  const long rejected = std::stol(msg.substr(msg.find(key, at) + key.size()));
  EXPECT_GT(rejected, 0) << msg.substr(at, 120);
  // The requests at every output against the closed form (AZ cumulative, 6 digits in the
  // .req); ERROR = 1e-7 leaves about 2e-4 rad on q1 = 60 at t = 2, inside 1e-3 rad, while a
  // turn miscounted by the coupler would put AZ(30, 11) pi away from q1 / 2.
  std::string err;
  const auto req = output::readRequestFile((dir / "c.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = output::lastStepPerTime(req->steps);
  ASSERT_EQ(steps.size(), 21u);
  for (const auto& step : steps) {
    const double t = step.time;
    const double q1 = t <= 1.0 ? 10.0 * t * t : 10.0 + 20.0 * (t - 1) + 30.0 * (t - 1) * (t - 1);
    EXPECT_NEAR(step.rows[0][0], q1, 1e-3 + 1e-5 * q1) << "AZ(20, 10) at t = " << t;
    EXPECT_NEAR(step.rows[0][1], q1 / 2, 1e-3 + 1e-5 * q1) << "AZ(30, 11) at t = " << t;
  }
  // The committed angles (at the integrator's last accepted step, at most HMAX past t = 2,
  // 1.6 rad on q1) are in the closed form's turns and satisfy the coupler.
  const auto& angles = s.state()->expressions->coupledAngles();
  ASSERT_EQ(angles.size(), 2u);
  EXPECT_NEAR(angles[0], 2.0 * angles[1], 1e-6);
  EXPECT_EQ(std::floor(angles[0] / kTwoPi), 9.0);
  EXPECT_EQ(std::floor(angles[1] / kTwoPi), 4.0);
}

}  // namespace
}  // namespace openmss
