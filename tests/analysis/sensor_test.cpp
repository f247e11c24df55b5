// SENSOR events in dynamic runs, against the closed form of a falling mass: z(t) = 10 - g t^2/2
// (g = 9.81, no joints), so DZ crosses 5 at tc = sqrt(10/g) with speed g tc. The event time may
// differ from tc by the sensor's ERROR on the function converted to time through that speed,
// ERROR / (g tc); the integration error is kept far below it (ERROR=1e-8 on a motion BDF of
// order >= 2 reproduces exactly). SENVAL, PRINT, RETURN, RESTART, DT and STEPSIZE are checked
// on the request file and the message file.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

constexpr double kG = 9.81;
const double kCrossing = std::sqrt(10.0 / kG);  // DZ(20) = 5
const double kSpeed = kG * kCrossing;

double height(double t) { return 10.0 - 0.5 * kG * t * t; }

std::string fallingMass(const std::string& sensor) {
  return "falling mass\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=1, IP=1,1,1, CM=20, QG=0,0,10\nMARKER/20, PART=2\n"
         "ACCGRAV/ KGRAV=-9.81\n" +
         sensor + "REQUEST/1, F2=DZ(20), F3=VZ(20), F4=SENVAL(1)\nOUTPUT/REQSAVE\nEND\n";
}

// Runs the commands through a Session; returns it for its summary.
struct SensorRun {
  std::unique_ptr<commands::Session> session;
  fs::path dir;
  bool ok = true;
};

SensorRun simulate(const std::string& name, const std::string& sensor,
                   const std::vector<std::string>& commands) {
  SensorRun r;
  r.dir = scratch(name);
  write(r.dir / "f.adm", fallingMass(sensor));
  commands::SessionOptions options;
  options.outputDirectory = r.dir.string();
  options.echoDiagnostics = false;
  r.session = std::make_unique<commands::Session>(options);
  r.ok = r.session->loadModel((r.dir / "f.adm").string(), "f");
  language::CommandReader reader("f.acf", 3);
  for (const auto& c : commands) reader.feedLine(c);
  reader.finish();
  for (const auto& c : reader.takeCommands()) {
    if (!r.ok || r.session->stopped()) break;
    r.ok = r.session->execute(c);
  }
  return r;
}

std::vector<output::RequestFileStep> steps(const SensorRun& r) {
  std::string err;
  auto req = output::readRequestFile((r.dir / "f.req").string(), &err);
  EXPECT_TRUE(req) << err;
  return req ? output::lastStepPerTime(req->steps) : std::vector<output::RequestFileStep>{};
}

// Half a unit in the last of the six printed digits of the request file.
double printed(double v) { return 5e-6 * std::max(1.0, std::abs(v)); }
// The printed time is rounded too: the height read at it may differ by the speed times that.
double heightTolerance(double t, double z) { return printed(z) + kG * t * printed(t) + 1e-6; }

TEST(Sensor, HaltStopsAtTheCrossingTimeWithinTheSensorError) {
  for (const char* how : {"", ", BISECTION"}) {
    for (double error : {1e-3, 1e-6}) {
      const SensorRun r =
          simulate("halt",
                   "SENSOR/1, FUNCTION=DZ(20), VALUE=5, ERROR=" + std::to_string(error) + ", HALT" +
                       how + "\n",
                   {"integrator/gstiff, error=1e-8", "simulate/transient, end=2, dtout=0.1",
                    "simulate/transient, end=3, dtout=0.1"});
      ASSERT_TRUE(r.ok) << r.dir;
      EXPECT_TRUE(r.session->stopped());  // HALT ends the run: the second SIMULATE never runs
      EXPECT_NEAR(r.session->summary().time, kCrossing, error / kSpeed) << how << error;
      const auto s = steps(r);
      ASSERT_FALSE(s.empty());
      // The last output is at the event, where DZ is VALUE (to the print's resolution: the
      // event is located to ERROR/1000 on the function).
      EXPECT_NEAR(s.back().time, kCrossing, 1e-5);
      EXPECT_NEAR(s.back().rows[0][0], 5.0, printed(5.0) + 1e-3 * error);
      EXPECT_NEAR(s[s.size() - 2].time, 1.0, 1e-9);  // the regular output before it
      const std::string msg = slurp(r.dir / "f.msg");
      EXPECT_EQ(msg.find("Begin Simulation"), msg.rfind("Begin Simulation")) << msg;
    }
  }
}

TEST(Sensor, EvaluateStoresTheValueSenvalReadsAndReturnEndsTheCommand) {
  const SensorRun r =
      simulate("senval", "SENSOR/1, FUNCTION=DZ(20), VALUE=5, LE, RETURN, EVALUATE=VZ(20)\n",
               {"integrator/gstiff, error=1e-8", "simulate/transient, end=2, dtout=0.1",
                "simulate/transient, end=2, dtout=0.1"});
  ASSERT_TRUE(r.ok) << r.dir;
  EXPECT_FALSE(r.session->stopped());
  EXPECT_NEAR(r.session->summary().time, 2.0, 1e-12);  // the second SIMULATE ran to its END
  const auto s = steps(r);
  bool sawEvent = false;
  for (const auto& st : s) {
    const double dz = st.rows[0][0], vz = st.rows[0][1], senval = st.rows[0][2];
    EXPECT_NEAR(dz, height(st.time), heightTolerance(st.time, dz)) << st.time;
    EXPECT_NEAR(vz, -kG * st.time, printed(vz) + kG * printed(st.time)) << st.time;
    if (st.time < kCrossing - 1e-6) {
      EXPECT_EQ(senval, 0.0) << st.time;  // before the first event
    } else {
      // VZ at the event: -g tc, the event time within ERROR (0.001) / speed.
      EXPECT_NEAR(senval, -kSpeed, printed(kSpeed) + kG * 1e-3 / kSpeed) << st.time;
      sawEvent |= std::abs(st.time - kCrossing) < 1e-5;
    }
  }
  EXPECT_TRUE(sawEvent);  // RETURN writes an output at the event
  EXPECT_NEAR(s.back().time, 2.0, 1e-12);
}

TEST(Sensor, PrintWritesAnOutputAtTheEventAndTheRunGoesOn) {
  const SensorRun r =
      simulate("print",
               "SENSOR/1, FUNCTION=DZ(20), VALUE=5, GE, PRINT\n"
               "SENSOR/2, FUNCTION=DZ(20), VALUE=5, LE, PRINT\n",
               {"integrator/gstiff, error=1e-8", "simulate/transient, end=2, dtout=0.1"});
  ASSERT_TRUE(r.ok) << r.dir;
  const auto s = steps(r);
  // 21 regular outputs and one at the event (SENSOR/1 holds from the start: it never acts).
  ASSERT_EQ(s.size(), 22u);
  int atEvent = 0;
  for (const auto& st : s) {
    EXPECT_NEAR(st.rows[0][0], height(st.time), heightTolerance(st.time, st.rows[0][0])) << st.time;
    atEvent += std::abs(st.time - kCrossing) < 1e-5;
  }
  EXPECT_EQ(atEvent, 1);
  const std::string msg = slurp(r.dir / "f.msg");
  EXPECT_NE(msg.find("SENSOR/2 event at time 1.0096"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("SENSOR/1 event"), std::string::npos) << msg;
}

TEST(Sensor, RestartWithDtChangesTheOutputGridFromTheEvent) {
  const SensorRun r =
      simulate("dt", "SENSOR/1, FUNCTION=DZ(20), VALUE=5, RESTART, DT=0.03\n",
               {"integrator/gstiff, error=1e-8", "simulate/transient, end=1.5, dtout=0.1"});
  ASSERT_TRUE(r.ok) << r.dir;
  const auto s = steps(r);
  std::vector<double> after;
  for (const auto& st : s) {
    EXPECT_NEAR(st.rows[0][0], height(st.time), heightTolerance(st.time, st.rows[0][0])) << st.time;
    if (st.time > kCrossing + 1e-6) after.push_back(st.time);
  }
  // Outputs at tc + 0.03 k while before END, then END (the restart kept the solution exact).
  ASSERT_GE(after.size(), 2u);
  for (size_t k = 0; k + 1 < after.size(); ++k)
    EXPECT_NEAR(after[k], kCrossing + 0.03 * static_cast<double>(k + 1), 1e-5) << k;
  EXPECT_NEAR(after.back(), 1.5, 1e-12);
  EXPECT_EQ(after.size(), static_cast<size_t>(std::ceil((1.5 - kCrossing) / 0.03)));
}

TEST(Sensor, StepsizeSetsTheFirstStepAfterTheEvent) {
  const SensorRun r =
      simulate("stepsize", "SENSOR/1, FUNCTION=DZ(20), VALUE=5, STEPSIZE=1.25e-4\nDEBUG/EPRINT\n",
               {"integrator/gstiff, error=1e-8", "simulate/transient, end=1.2, dtout=0.1"});
  ASSERT_TRUE(r.ok) << r.dir;
  const auto s = steps(r);
  EXPECT_NEAR(s.back().rows[0][0], height(1.2), printed(height(1.2)) + 1e-6);
  // DEBUG/EPRINT prints each step's start time and size: one starts at the event with 1.25E-04.
  const std::string msg = slurp(r.dir / "f.msg");
  EXPECT_NE(msg.find("time 1.00963" /* the event */), std::string::npos);
  EXPECT_NE(msg.find("step size 1.250000E-04"), std::string::npos);
}

// The SI2 formulation and INTERPOLATE=ON wrap the BDF method (the SI2 state, the interpolation
// to output times); STEPSIZE must still reach the method, not fall back to HINIT.
TEST(Sensor, StepsizeReachesTheMethodUnderSi2AndInterpolation) {
  for (const char* options : {", si2", ", interpolate=on"}) {
    const SensorRun r =
        simulate(std::string("stepsize-wrapped") + (options[2] == 's' ? "-si2" : "-interp"),
                 "SENSOR/1, FUNCTION=DZ(20), VALUE=5, STEPSIZE=1.25e-4\nDEBUG/EPRINT\n",
                 {std::string("integrator/gstiff, error=1e-8") + options,
                  "simulate/transient, end=1.2, dtout=0.1"});
    ASSERT_TRUE(r.ok) << r.dir << options;
    const auto s = steps(r);
    EXPECT_NEAR(s.back().rows[0][0], height(1.2), printed(height(1.2)) + 1e-6) << options;
    const std::string msg = slurp(r.dir / "f.msg");
    EXPECT_NE(msg.find("step size 1.250000E-04"), std::string::npos) << options << "\n" << msg;
    EXPECT_EQ(msg.find("STEPSIZE had"), std::string::npos) << options << "\n" << msg;
  }
}

TEST(Sensor, TheMessageFileSaysWhichSensorHaltedTheRunAndWhen) {
  const fs::path dir = scratch("sensor-cli");
  write(dir / "f.adm", fallingMass("SENSOR/1, FUNCTION=DZ(20), VALUE=5, HALT\n"));
  write(dir / "f.acf",
        "f\nf\nintegrator/gstiff, error=1e-8\nsimulate/transient, end=2, dtout=0.1\n"
        "simulate/transient, end=3, dtout=0.1\nstop\n");
  const Result r = run("run f.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string msg = slurp(dir / "f.msg");
  EXPECT_NE(msg.find("   SENSOR/1 event at time 1.009638E+00: FUNCTION = 5.0000"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("(EQ VALUE = 5.000000E+00, ERROR = 1.000000E-03); actions: HALT"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("   The simulation is halted by SENSOR/1 at time 1.009638E+00"),
            std::string::npos)
      << msg;
  EXPECT_EQ(msg.find("Begin Simulation"), msg.rfind("Begin Simulation")) << msg;
  fs::remove_all(dir);
}

TEST(Sensor, KinematicAnalysesRefuseSensors) {
  const SensorRun r = simulate("kin",
                               "JOINT/1, TRANSLATIONAL, I=20, J=10\nMOTION/1, JOINT=1, "
                               "FUNCTION=-TIME\nSENSOR/1, FUNCTION=DZ(20), VALUE=5, HALT\n",
                               {"simulate/kinematics, end=1, steps=2"});
  EXPECT_FALSE(r.ok);
  bool named = false;
  for (const auto& d : r.session->diagnostics().all())
    named |=
        d.message.find("SENSOR events are detected in dynamic analyses only") != std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
