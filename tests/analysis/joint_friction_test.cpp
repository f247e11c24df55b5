// FRICTION on joints end to end through the openmss program (docs/theory.md, "Joint
// friction"), against closed forms:
//   (a) a block on an incline held by a TRANSLATIONAL joint: below tan(phi) = mu_s it sticks,
//       its creep settling where the creep spring carries the weight, x = dmax tan(phi)/mu_s,
//       never beyond MAX_STICTION_DEFORMATION; above, it slides with a = g (sin phi - mu_d cos
//       phi) (fitted from the velocity output); launched down a gentle slope it decelerates at
//       g (mu_d cos phi - sin phi) and stops at the closed-form time;
//   (b) a pendulum with pin friction (REVOLUTE, PIN_RADIUS): its amplitude falls linearly, by
//       4 mu Rp / L per cycle (Coulomb damping of the small-angle pendulum);
//   (c) a spinning disc braked by FRICTION_FORCE_PRELOAD alone: constant torque mu_d F Rp,
//       w(t) = w0 - mu_d F Rp t / I until it stops, and stays stopped;
// with the FRICTION(id, index) read-backs checked against the same numbers.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;

const double kG = 9.81;

// The request file of a run of `adm` with `commands`; a failed run fails the test.
std::optional<openmss::output::RequestFileData> runModel(const std::string& name,
                                                         const std::string& adm,
                                                         const std::string& commands) {
  const fs::path dir = scratch(name);
  write(dir / "m.adm", adm);
  write(dir / "m.acf", "m\nm\n" + commands + "stop\n");
  const Result r = run("run m.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  std::string err;
  auto req = openmss::output::readRequestFile((dir / "m.req").string(), &err);
  EXPECT_TRUE(req) << err << r.output;
  fs::remove_all(dir);
  return req;
}

// A 1 kg block at the origin on a slope at `phi` (radians) below the horizontal, gravity -y:
// the joint's z axis points down the slope, x away from it. REQUEST/1 displacement and /2
// velocity of the block along the slope (J axes), /3 FRICTION(1, 3) (force along z_J),
// FRICTION(1, 9) (coefficient along z_J), FRICTION(1, 13) (static coefficient).
std::string incline(double phi, const std::string& friction, double v0) {
  const double c = std::cos(phi), s = std::sin(phi);
  const std::string zp = std::to_string(c) + "," + std::to_string(-s) + ",0";
  const std::string xp = std::to_string(s) + "," + std::to_string(c) + ",0";
  return "incline\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\n"
         "MARKER/10, PART=1, ZP=" +
         zp + ", XP=" + xp +
         "\n"
         "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1, VX=" +
         std::to_string(v0 * c) + ", VY=" + std::to_string(-v0 * s) +
         "\n"
         "MARKER/20, PART=2, ZP=" +
         zp + ", XP=" + xp +
         "\n"
         "JOINT/1, TRANSLATIONAL, I=20, J=10\n" +
         friction +
         "ACCGRAV/ JGRAV=-9.81\n"
         "REQUEST/1, DISPLACEMENT, I=20, J=10, RM=10\nREQUEST/2, VELOCITY, I=20, J=10, RM=10\n"
         "REQUEST/3, F2=FRICTION(1,3)\\F3=FRICTION(1,9)\\F4=FRICTION(1,13)\n"
         "OUTPUT/REQSAVE\nEND\n";
}

TEST(JointFriction, BlockBelowTheStictionAngleSticksWithinTheCreepLimit) {
  const double mus = 0.5, dmax = 1e-3, phi = std::atan(0.4 * mus);
  const auto req =
      runModel("stick",
               incline(phi,
                       "FRICTION/1, JOINT=1, MU_STATIC=0.5, MU_DYNAMIC=0.3, "
                       "STICTION_TRANSITION_VELOCITY=0.1, MAX_STICTION_DEFORMATION=1e-3\n",
                       0.0),
               "integrator/gstiff, error=1e-8\nsimulate/dynamics, end=2, dtout=0.01\n");
  ASSERT_TRUE(req);
  ASSERT_EQ(req->steps.size(), 201u);
  double largest = 0.0;
  for (const auto& step : req->steps) largest = std::max(largest, std::abs(step.rows[0][2]));
  // The creep never exceeds MAX_STICTION_DEFORMATION (underdamped spring: about 1.4 times
  // its rest value at most, 0.56 dmax).
  EXPECT_LT(largest, dmax);
  EXPECT_GT(largest, 0.0);
  // At rest the creep spring mu_s N x / dmax carries m g sin(phi): x = dmax tan(phi) / mu_s,
  // printed with 6 digits (relative 5e-6) after the transient decays (e^-8 by 2 s).
  const auto& last = req->steps.back();
  const double rest = dmax * std::tan(phi) / mus;
  EXPECT_NEAR(last.rows[0][2], rest, 1e-4 * rest);
  EXPECT_NEAR(last.rows[1][2], 0.0, 1e-6);
  // Read-backs: the friction force balances the weight along the slope, the static
  // coefficient is tan(phi) (= |mu| in stiction).
  EXPECT_NEAR(last.rows[2][0], -kG * std::sin(phi), 1e-4);
  EXPECT_NEAR(last.rows[2][2], std::tan(phi), 1e-4);
  std::printf("stick: largest creep %.4e (limit %.1e), rest %.6e (closed form %.6e)\n", largest,
              dmax, last.rows[0][2], rest);
}

TEST(JointFriction, BlockAboveTheStictionAngleSlidesWithDynamicFriction) {
  const double mus = 0.4, mud = 0.25, phi = 30.0 * std::numbers::pi / 180.0;  // tan = 0.577 > mu_s
  const auto req =
      runModel("slide",
               incline(phi,
                       "FRICTION/1, JOINT=1, MU_STATIC=0.4, MU_DYNAMIC=0.25, "
                       "STICTION_TRANSITION_VELOCITY=0.01, MAX_STICTION_DEFORMATION=1e-4\n",
                       0.0),
               "integrator/gstiff, error=1e-8\nsimulate/dynamics, end=1, dtout=0.05\n");
  ASSERT_TRUE(req);
  ASSERT_EQ(req->steps.size(), 21u);
  const double a = kG * (std::sin(phi) - mud * std::cos(phi));
  // Least-squares slope of v(t) over the outputs after the breakaway (v > 1.5 Vs from
  // about 0.01 s): constant acceleration, so the fit is exact up to the 6-digit print.
  double st = 0, sv = 0, stt = 0, stv = 0;
  int n = 0;
  for (const auto& step : req->steps) {
    if (step.time < 0.2) continue;
    const double v = step.rows[1][2];
    st += step.time;
    sv += v;
    stt += step.time * step.time;
    stv += step.time * v;
    ++n;
  }
  ASSERT_EQ(n, 17);
  const double fitted = (n * stv - st * sv) / (n * stt - st * st);
  EXPECT_NEAR(fitted, a, 1e-4 * a);
  (void)mus;
  // Read-backs in the dynamic regime: force -mu_d m g cos(phi), coefficient mu_d, static 0.
  const auto& last = req->steps.back();
  EXPECT_NEAR(last.rows[2][0], -mud * kG * std::cos(phi), 1e-5);
  EXPECT_NEAR(last.rows[2][1], mud, 1e-6);
  EXPECT_EQ(last.rows[2][2], 0.0);
  std::printf("slide: fitted a = %.6f, closed form g(sin - mu_d cos) = %.6f\n", fitted, a);
}

TEST(JointFriction, BlockLaunchedDownAGentleSlopeStopsAtTheClosedFormTime) {
  const double mud = 0.3, phi = 10.0 * std::numbers::pi / 180.0, v0 = 2.0, vs = 1e-3;
  const auto req =
      runModel("stop",
               incline(phi,
                       "FRICTION/1, JOINT=1, MU_STATIC=0.4, MU_DYNAMIC=0.3, "
                       "STICTION_TRANSITION_VELOCITY=1e-3, MAX_STICTION_DEFORMATION=1e-4\n",
                       v0),
               "integrator/gstiff, error=1e-8, hmax=1e-3\nsimulate/dynamics, end=3, dtout=0.01\n");
  ASSERT_TRUE(req);
  const double decel = kG * (mud * std::cos(phi) - std::sin(phi));
  const double stop = v0 / decel;  // 1.57 s
  double firstSlow = -1.0;
  int checked = 0;
  for (const auto& step : req->steps) {
    const double v = step.rows[1][2];
    if (step.time < stop - 0.02) {
      // Dynamic regime: v = v0 - decel t (to the 6-digit print).
      EXPECT_NEAR(v, v0 - decel * step.time, 2e-5) << step.time;
      ++checked;
    }
    if (firstSlow < 0.0 && std::abs(v) < vs) firstSlow = step.time;
    if (step.time > stop + 0.05) {
      EXPECT_LT(std::abs(v), vs) << step.time;
    }
  }
  EXPECT_GT(checked, 150);
  // The joint first reads below Vs at the output after (v0 - Vs) / decel; the band
  // [Vs, 1.5 Vs] takes Vs / (2 decel) = 4e-4 s, under one output step.
  EXPECT_NEAR(firstSlow, stop, 0.011);
  std::printf("stop: v below Vs first at t = %.2f, closed form v0/decel = %.4f\n", firstSlow, stop);
}

// Pendulum: a 1 kg point (Izz 1e-4) on a 1 m arm, revolute at the origin about z, gravity -y,
// released at 0.1 rad; pin friction mu 0.2 on a 0.01 pin.
TEST(JointFriction, PendulumWithPinFrictionDecaysLinearly) {
  const double a0 = 0.1, mu = 0.2, rp = 0.01, len = 1.0;
  const std::string adm =
      "pin friction pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1e-4,1e-4,1e-4\n"
      "MARKER/20, PART=2, QP=" +
      std::to_string(len * std::sin(a0)) + "," + std::to_string(-len * std::cos(a0)) +
      ",0\n"
      "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\n"
      "FRICTION/1, JOINT=1, MU_STATIC=0.2, MU_DYNAMIC=0.2, PIN_RADIUS=0.01, "
      "STICTION_TRANSITION_VELOCITY=1e-5, MAX_STICTION_DEFORMATION=1e-7\n"
      "ACCGRAV/ JGRAV=-9.81\nREQUEST/1, DISPLACEMENT, I=21, J=10\nOUTPUT/REQSAVE\nEND\n";
  const auto req = runModel("pendulum", adm,
                            "integrator/gstiff, error=1e-9, hmax=2e-3\n"
                            "simulate/dynamics, end=10, dtout=0.002\n");
  ASSERT_TRUE(req);
  // The angle from the downward vertical: a0 plus psi of I relative to J (degrees; the markers
  // start aligned, so psi is the rotation since the release).
  std::vector<double> t, a;
  for (const auto& step : req->steps) {
    t.push_back(step.time);
    a.push_back(a0 + step.rows[0][3] * std::numbers::pi / 180.0);
  }
  // Positive peaks, refined by the parabola through the three samples around each.
  std::vector<double> peaks;
  for (size_t k = 1; k + 1 < a.size(); ++k)
    if (a[k] > a[k - 1] && a[k] >= a[k + 1] && a[k] > 0.01) {
      const double d = a[k - 1] - 2 * a[k] + a[k + 1];
      const double shift = d != 0.0 ? 0.5 * (a[k - 1] - a[k + 1]) / d : 0.0;
      peaks.push_back(a[k] - 0.25 * (a[k - 1] - a[k + 1]) * shift);
    }
  // Coulomb damping of I a'' + m g L a = -T sign(a'), T = mu Rp m g: every half cycle loses
  // 2 T / (m g L), a cycle 4 mu Rp / L = 0.008 rad, the same every cycle (linear decay).
  const double perCycle = 4.0 * mu * rp / len;
  ASSERT_GE(peaks.size(), 4u);
  for (size_t k = 0; k + 1 < peaks.size(); ++k) {
    const double drop = peaks[k] - peaks[k + 1];
    // 2%: the rod tension g cos a + L a'^2 differs from g by O(a^2) = 1e-2 of it, and
    // (1 - cos a) from a^2/2 by a^2/12 of it.
    EXPECT_NEAR(drop, perCycle, 0.02 * perCycle) << "cycle " << k;
    std::printf("pendulum: cycle %zu peak %.6f drop %.6f (closed form %.6f)\n", k, peaks[k], drop,
                perCycle);
  }
}

TEST(JointFriction, PreloadAloneBrakesASpinningDiscAtConstantTorque) {
  // Izz = 2, w0 = 10; torque mu_d F Rp = 0.2 * 100 * 0.05 = 1, so w = 10 - t/2 until t = 20.
  const std::string adm =
      "braked disc\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=3, CM=20, IP=1,1,2, WZ=10\nMARKER/20, PART=2\n"
      "JOINT/1, REVOLUTE, I=20, J=10\n"
      "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2, PIN_RADIUS=0.05, "
      "FRICTION_FORCE_PRELOAD=100, INPUTS=PRELOAD, STICTION_TRANSITION_VELOCITY=1e-3, "
      "MAX_STICTION_DEFORMATION=1e-5\n"
      "REQUEST/1, VELOCITY, I=20, J=10\n"
      "REQUEST/2, F2=FRICTION(1,6)\\F3=FRICTION(1,12)\\F4=FRICTION(1,19)\n"
      "OUTPUT/REQSAVE\nEND\n";
  const auto req = runModel("disc", adm,
                            "integrator/gstiff, error=1e-8\n"
                            "simulate/dynamics, end=25, dtout=0.5\n");
  ASSERT_TRUE(req);
  ASSERT_EQ(req->steps.size(), 51u);
  int checked = 0;
  for (const auto& step : req->steps) {
    const double w = step.rows[0][5];  // WZ, rad/s
    if (step.time <= 19.5) {
      EXPECT_NEAR(w, 10.0 - 0.5 * step.time, 1e-5 * 10.0) << step.time;
      if (step.time > 0.0) {
        EXPECT_NEAR(step.rows[1][0], -1.0, 1e-6) << step.time;  // FRICTION(1,6): torque
        EXPECT_NEAR(step.rows[1][1], 0.2, 1e-6) << step.time;   // mu along z (dynamic)
        EXPECT_NEAR(step.rows[1][2], w, 1e-5 * 10.0) << step.time;
      }
      ++checked;
    } else if (step.time >= 20.5) {
      EXPECT_LT(std::abs(w), 1e-3 / 0.05) << step.time;  // below Vs / Rp: stuck
    }
  }
  EXPECT_EQ(checked, 40);
}

}  // namespace

// A HOOKE pendulum with the default transition velocity and stiction deformation: the slip
// turns round at every swing. docs/theory.md §13 records that the friction can jump at a
// reversal while the creep sits at its limit (a case that stopped a run is described there);
// this swing, on every integrator step through its reversals, reaches END, and since friction
// only takes energy out, no swing rises above the one before it (to 1e-3 of the 0.3 m swing).
TEST(JointFriction, HookePendulumWithDefaultStictionRunsThroughSlipReversals) {
  const double a0 = 0.3;
  const std::string adm =
      "hooke pendulum with friction\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\n"
      "MARKER/10, PART=1, ZP=1,0,0, XP=0,1,0\n"
      "PART/2, MASS=1, CM=20, IP=1e-2,1e-2,1e-2\n"
      "MARKER/20, PART=2, QP=" +
      std::to_string(std::sin(a0)) + "," + std::to_string(-std::cos(a0)) +
      ",0\n"
      "MARKER/21, PART=2\nJOINT/1, HOOKE, I=21, J=10\n"
      "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2, PIN_RADIUS=0.05\n"
      "ACCGRAV/ JGRAV=-9.81\nREQUEST/1, DISPLACEMENT, I=20, J=10\nOUTPUT/REQSAVE\nEND\n";
  const auto req = runModel("hooke", adm, "simulate/dynamics, end=5, dtout=0.005\n");
  ASSERT_TRUE(req);
  ASSERT_FALSE(req->steps.empty());
  EXPECT_NEAR(req->steps.back().time, 5.0, 1e-9);
  // Swing peaks of x (the bob's horizontal position): non-increasing up to the run's error.
  std::vector<double> x;
  for (const auto& step : req->steps) x.push_back(step.rows[0][1]);
  std::vector<double> peaks;
  for (size_t k = 1; k + 1 < x.size(); ++k)
    if (x[k] > x[k - 1] && x[k] >= x[k + 1]) peaks.push_back(x[k]);
  ASSERT_GE(peaks.size(), 2u);
  for (size_t k = 0; k + 1 < peaks.size(); ++k)
    EXPECT_LE(peaks[k + 1], peaks[k] + 1e-3) << "swing " << k;
}
