// SAVE and RELOAD (docs/save-format.md) through the Session, as a command file drives it: SAVE
// at t = 1, RELOAD in a new session (or in the same one after the state moved on), continue to
// t = 2, and the request file is byte for byte the uninterrupted run's (GSTIFF, WSTIFF, DSTIFF,
// HHT, MERSON; a model with DIFF, SENSOR, DELAY and cumulative AZ turns). A corrupt, a
// truncated and a foreign file are each refused with one located error, and the next SIMULATE
// gives what it gives without the failed RELOAD.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using openmss::commands::Session;
using openmss::commands::SessionOptions;
using namespace openmss::testing;  // scratch, slurp, write

// A spinner turned by a motion at 5 rad/s (AZ(20, 10) passes pi, 3 pi, 5 pi by t = 2, so turns
// are counted and saved) and a pendulum of length 1 under gravity released horizontal; a
// DELAY reads the pendulum's past.
const char* kMechanism =
    "save and reload\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=2, 0, 0\n"
    "PART/2, MASS=1, CM=20, IP=1, 1, 1\nMARKER/20, PART=2\n"
    "JOINT/1, REVOLUTE, I=20, J=10\nMOTION/1, JOINT=1, ROTATION, FUNCTION=5*TIME\n"
    "PART/3, MASS=1, CM=30, IP=0.1, 0.1, 0.1\nMARKER/30, PART=3, QP=3, 0, 0\n"
    "MARKER/31, PART=3, QP=2, 0, 0\nJOINT/2, REVOLUTE, I=31, J=11\nACCGRAV/JGRAV=-9.81\n"
    "REQUEST/1, DISPLACEMENT, I=30, J=11\n"
    "REQUEST/2, F2=AZ(20, 10), F3=DELAY(DX(30, 11), 0.3, 0), F4=AZ(30, 11)\n";

// The mechanism with a DIFF fed by a DELAY of itself, a VARIABLE with a DELAY, and a SENSOR
// whose EVALUATE value (SENVAL) a request reads: the pendulum passes DY = -0.5 going down
// before t = 1 and again after t = 1.
std::string fullModel() {
  return std::string(kMechanism) +
         "DIFF/1, FUNCTION=-DELAY(DIF(1), 0.5, 1), IC=1\n"
         "VARIABLE/1, FUNCTION=DELAY(DY(30, 11), 0.2, 0)\n"
         "SENSOR/1, FUNCTION=DY(30, 11), VALUE=-0.5, LE, EVALUATE=VX(30, 11)\n"
         "REQUEST/3, F2=SENVAL(1), F3=DIF(1), F4=VARVAL(1)\nOUTPUT/REQSAVE\nEND\n";
}
std::string mechanism() { return std::string(kMechanism) + "OUTPUT/REQSAVE\nEND\n"; }

struct Study {
  std::unique_ptr<Session> session;
  int errors() const { return static_cast<int>(session->diagnostics().errorCount()); }
};

Study open(const fs::path& dir, const std::string& model, const std::string& prefix) {
  SessionOptions o;
  o.outputDirectory = dir.string();
  o.echoDiagnostics = false;
  Study s{std::make_unique<Session>(o)};
  EXPECT_TRUE(s.session->loadModel((dir / model).string(), prefix));
  return s;
}

// One command, echoed and executed as the command-file runner does.
bool command(Study& s, const std::string& text) {
  openmss::language::CommandReader reader("study.acf", 3);
  reader.feedLine(text);
  reader.finish();
  auto commands = reader.takeCommands();
  EXPECT_EQ(commands.size(), 1u) << text;
  s.session->echoCommand(text);
  return s.session->execute(commands.front());
}

// The request file's header: everything before the first output step (the longest common
// prefix of two files of one model whose first output times differ, cut at a line end).
std::size_t headerLength(const std::string& a, const std::string& b) {
  std::size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  return a.rfind('\n', n - 1) + 1;
}

struct Outputs {
  std::string uninterrupted, first, continued;  // .req texts
  std::string uninterruptedMessages;            // u.msg
};

// u: SIMULATE to 1, then to 2. a: SIMULATE to 1, SAVE/<kind>. b: a new session (loading
// `bModel`), RELOAD/<kind>, SIMULATE to 2.
Outputs saveAndContinue(const std::string& name, const std::string& model,
                        const std::string& integrator, const std::string& kind,
                        const std::string& bModel = "m.adm") {
  const fs::path dir = scratch("save-" + name);
  write(dir / "m.adm", model);
  write(dir / "other.adm", mechanism());
  Outputs o;
  {
    Study u = open(dir, "m.adm", "u");
    if (!integrator.empty()) {
      EXPECT_TRUE(command(u, integrator));
    }
    EXPECT_TRUE(command(u, "SIMULATE/DYNAMICS, END=1, STEPS=10"));
    EXPECT_TRUE(command(u, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
    EXPECT_TRUE(command(u, "STOP"));
    EXPECT_EQ(u.errors(), 0);
    o.uninterrupted = slurp(dir / "u.req");
    o.uninterruptedMessages = slurp(dir / "u.msg");
  }
  {
    Study a = open(dir, "m.adm", "a");
    if (!integrator.empty()) {
      EXPECT_TRUE(command(a, integrator));
    }
    EXPECT_TRUE(command(a, "SIMULATE/DYNAMICS, END=1, STEPS=10"));
    EXPECT_TRUE(command(a, "SAVE/" + kind + ", FILE=at1.sav"));
    EXPECT_TRUE(command(a, "STOP"));
    EXPECT_EQ(a.errors(), 0);
    o.first = slurp(dir / "a.req");
  }
  {
    Study b = open(dir, bModel, "b");
    // RELOAD/SYSTEM brings the integrator command back itself.
    if (!integrator.empty() && kind == "STATES") {
      EXPECT_TRUE(command(b, integrator));
    }
    EXPECT_TRUE(command(b, "RELOAD/" + kind + ", FILE=at1.sav"));
    EXPECT_DOUBLE_EQ(b.session->state()->t, 1.0);
    EXPECT_TRUE(command(b, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
    EXPECT_TRUE(command(b, "STOP"));
    EXPECT_EQ(b.errors(), 0);
    o.continued = slurp(dir / "b.req");
  }
  return o;
}

// The uninterrupted file is the first half followed by the continuation's steps, byte for byte.
void expectBitIdentical(const Outputs& o, const std::string& what) {
  ASSERT_FALSE(o.first.empty()) << what;
  ASSERT_FALSE(o.continued.empty()) << what;
  const std::size_t header = headerLength(o.first, o.continued);
  ASSERT_GT(header, 0u) << what;
  const std::string tail = o.continued.substr(header);
  // Something was compared: the continuation holds the 10 output steps after t = 1, and the
  // first file is a strict prefix of the uninterrupted one.
  ASSERT_GT(tail.size(), 10u) << what;
  EXPECT_LT(o.first.size(), o.uninterrupted.size()) << what;
  EXPECT_EQ(o.uninterrupted, o.first + tail) << what;
}

TEST(SaveReload, StatesContinueBitIdenticallyForEveryIntegrator) {
  int compared = 0;
  for (const char* integrator : {"INTEGRATOR/GSTIFF, ERROR=1e-6", "INTEGRATOR/WSTIFF, ERROR=1e-6",
                                 "INTEGRATOR/DSTIFF, ERROR=1e-6", "INTEGRATOR/HHT, ERROR=1e-6",
                                 "INTEGRATOR/MERSON, ERROR=1e-6"}) {
    expectBitIdentical(saveAndContinue("states", mechanism(), integrator, "STATES"), integrator);
    ++compared;
  }
  EXPECT_EQ(compared, 5);
}

TEST(SaveReload, DiffSensorDelayAndTurnsContinueBitIdentically) {
  const Outputs o = saveAndContinue("full", fullModel(), "", "STATES");
  expectBitIdentical(o, "STATES");
  // The sensor fired before t = 1 and again after (about 0.35 s and 1.59 s, the pendulum
  // passing 30 degrees below horizontal going down): the saved SENVAL and the event after the
  // reload were both in the compared part.
  std::vector<double> events;
  const std::string key = "SENSOR/1 event at time ";
  for (std::size_t at = o.uninterruptedMessages.find(key); at != std::string::npos;
       at = o.uninterruptedMessages.find(key, at + 1))
    events.push_back(std::stod(o.uninterruptedMessages.substr(at + key.size(), 14)));
  ASSERT_EQ(events.size(), 2u) << o.uninterruptedMessages;
  EXPECT_LT(events[0], 1.0);
  EXPECT_GT(events[1], 1.0);
}

TEST(SaveReload, SystemBringsTheModelAndItsCommandsBack) {
  // The new session loads another model (no DIFF, SENSOR, VARIABLE) and no INTEGRATOR
  // command: RELOAD/SYSTEM replaces both with the saved ones.
  expectBitIdentical(saveAndContinue("system", fullModel(), "INTEGRATOR/WSTIFF, ERROR=1e-7",
                                     "SYSTEM", "other.adm"),
                     "SYSTEM");
}

// In one session: SAVE at 1, run on to 2, RELOAD with OUTPUT_PREFIX, run to 2 again: the new
// file's steps are the uninterrupted run's.
TEST(SaveReload, ReloadInTheSameSessionTurnsTheStateBackAndStartsNewOutputFiles) {
  const fs::path dir = scratch("save-same");
  write(dir / "m.adm", fullModel());
  Study s = open(dir, "m.adm", "s");
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=1, STEPS=10"));
  ASSERT_TRUE(command(s, "SAVE/STATES, FILE=at1.sav"));
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
  const std::string uninterrupted = slurp(dir / "s.req");
  ASSERT_TRUE(command(s, "RELOAD/STATES, FILE=at1.sav, OUTPUT_PREFIX=again"));
  EXPECT_DOUBLE_EQ(s.session->state()->t, 1.0);
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
  ASSERT_TRUE(command(s, "STOP"));
  EXPECT_EQ(s.errors(), 0);
  const std::string again = slurp(dir / "again.req");
  const std::size_t header = headerLength(uninterrupted, again);
  ASSERT_GT(again.size(), header + 10);
  // The continuation's steps are the last part of the uninterrupted file.
  const std::string tail = again.substr(header);
  ASSERT_LT(tail.size(), uninterrupted.size());
  EXPECT_EQ(uninterrupted.substr(uninterrupted.size() - tail.size()), tail);
  EXPECT_TRUE(fs::exists(dir / "again.msg"));
}

// A bad file: RELOAD fails with one error naming the file and line, and the state is as it
// was: the next SIMULATE writes what the uninterrupted run writes.
void expectRefused(const std::string& name, const std::string& damage,
                   const std::string& expectedMessage) {
  const fs::path dir = scratch("save-bad-" + name);
  write(dir / "m.adm", fullModel());
  std::string uninterrupted;
  {
    Study u = open(dir, "m.adm", "u");
    EXPECT_TRUE(command(u, "SIMULATE/DYNAMICS, END=1, STEPS=10"));
    EXPECT_TRUE(command(u, "SAVE/STATES, FILE=good.sav"));
    EXPECT_TRUE(command(u, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
    EXPECT_TRUE(command(u, "STOP"));
    uninterrupted = slurp(dir / "u.req");
  }
  std::string text = slurp(dir / "good.sav");
  ASSERT_GT(text.size(), 200u);
  if (damage == "corrupt") {
    // One digit of a state value changed (line 20 is inside y).
    std::size_t line = 0, at = 0;
    while (line < 19) at = text.find('\n', at) + 1, ++line;
    const std::size_t digit = text.find_first_of("123456789", at);
    text[digit] = text[digit] == '1' ? '2' : '1';
  } else if (damage == "truncated") {
    text.resize(text.size() / 2);
  } else if (damage == "foreign") {
    // A well-formed file of another model: the first session's save of the mechanism alone.
    write(dir / "other.adm", mechanism());
    Study o = open(dir, "other.adm", "o");
    EXPECT_TRUE(command(o, "SAVE/STATES, FILE=bad.sav"));
    text = slurp(dir / "bad.sav");
  }
  write(dir / "bad.sav", text);
  Study s = open(dir, "m.adm", "s");
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=1, STEPS=10"));
  ASSERT_EQ(s.errors(), 0);
  EXPECT_FALSE(command(s, "RELOAD/STATES, FILE=bad.sav"));
  ASSERT_EQ(s.errors(), 1) << name;
  const openmss::Diagnostic& d = s.session->diagnostics().all().back();
  EXPECT_EQ(d.where.line, 3) << name;  // the RELOAD command's line
  EXPECT_NE(d.message.find("bad.sav"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find(expectedMessage), std::string::npos) << d.message;
  EXPECT_DOUBLE_EQ(s.session->state()->t, 1.0);
  ASSERT_TRUE(command(s, "SIMULATE/DYNAMICS, END=2, STEPS=10"));
  ASSERT_TRUE(command(s, "STOP"));
  const std::string after = slurp(dir / "s.req");
  ASSERT_GT(after.size(), 1000u);
  EXPECT_EQ(after, uninterrupted) << name;
}

TEST(SaveReload, CorruptFileIsRefusedAndNothingChanges) {
  expectRefused("corrupt", "corrupt", "checksum mismatch");
}
TEST(SaveReload, TruncatedFileIsRefusedAndNothingChanges) {
  expectRefused("truncated", "truncated", "truncated");
}
TEST(SaveReload, StatesOfAnotherModelAreRefusedAndNothingChanges) {
  expectRefused("foreign", "foreign", "another model");
}

}  // namespace
