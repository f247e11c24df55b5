// The .res entities of NFORCE, GCON, TFSISO, LSE, PINPUT and POUTPUT (output/results_layout.cpp;
// docs/output-files.md, "Entities and components") against the values the same run reads back
// through functions in REQUESTs (NFORCE(), ARYVAL(), VARVAL()) and a FORCE request, all in the
// same .res (17 digits), and against the NFORCE's own balance: the reaction on J equals minus
// the sum of the forces on its I markers. COUPLER, CONTACT and FRICTION (a second and third
// data set) against closed forms: the coupled pair's torque, a sphere at rest on a floor
// carrying its weight, a block sliding with dynamic friction.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "output/results_file_reader.hpp"
#include "support/cli_run.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::write;

constexpr const char* kModel =
    "res elements\nUNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\nMARKER/10, PART=1\nMARKER/102, PART=1, QP=5,0,0\n"
    // NFORCE/1: two sliders on z tied to ground marker 10 and to each other.
    "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0,0,1.5\nMARKER/20, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1, QG=0,0,3.2\nMARKER/30, PART=3\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\nJOINT/2, TRANSLATIONAL, I=30, J=10\n"
    "MATRIX/1, SPARSE, ROWS=12, COLUMNS=12, I=3,3,9,9, J=3,9,3,9, VALUES=16,-8,-8,8\n"
    "MATRIX/2, SPARSE, ROWS=12, COLUMNS=1, I=3,9, J=1,1, VALUES=1,2\n"
    "NFORCE/1, IMARKERS=20,30, J=10, KMATRIX=1, LENGTH=2\n"
    // GCON/1: a pendulum of length 2 about ground marker 102.
    "PART/4, MASS=1.5, CM=401, IP=1e-3,1e-3,1e-3\nMARKER/401, PART=4, QP=5,2,0\n"
    "GCON/1, I=102, FUNCTION=DM(401,102)-2\nACCGRAV/ JGRAV=-9.80665\n"
    // TFSISO/1 and LSE/2 driven by the first slider's height; PINPUT and POUTPUT.
    "VARIABLE/1, FUNCTION=DZ(20,10)\nVARIABLE/2, FUNCTION=ARYVAL(3,1)\n"
    "ARRAY/1, U, VARIABLES=1\nARRAY/2, X\nARRAY/3, Y\nARRAY/4, X\nARRAY/5, Y, SIZE=1\n"
    "TFSISO/1, X=2, U=1, Y=3, NUMERATOR=1, 2, DENOMINATOR=4, 6, 2\n"
    "MATRIX/11, FULL=RORDER, ROWS=1, COLUMNS=1, VALUES=-3\n"
    "MATRIX/12, FULL=RORDER, ROWS=1, COLUMNS=1, VALUES=2\n"
    "MATRIX/13, FULL=RORDER, ROWS=1, COLUMNS=1, VALUES=1\n"
    "LSE/2, X=4, U=1, Y=5, A=11, B=12, C=13\n"
    "PINPUT/1, VARIABLES=1\nPOUTPUT/1, VARIABLES=2\n"
    "REQUEST/1, F2=NFORCE(1,10,2,0)\\F3=NFORCE(1,10,3,0)\\F4=NFORCE(1,10,4,0)\\"
    "F6=NFORCE(1,10,6,0)\\F7=NFORCE(1,10,7,0)\\F8=NFORCE(1,10,8,0)\n"
    "REQUEST/2, F2=NFORCE(1,20,4,0)\\F3=NFORCE(1,30,4,0)\n"
    "REQUEST/3, FORCE, I=102, J=401\n"
    "REQUEST/4, F2=ARYVAL(2,1)\\F3=ARYVAL(2,2)\\F4=ARYVAL(4,1)\\F6=VARVAL(1)\\F7=VARVAL(2)\n"
    "RESULTS/XRF\nEND\n";

TEST(ResultsElements, NforceGconStateElementsAndPlantsHoldTheirReadBackValues) {
  const fs::path dir = scratch("res-elements");
  write(dir / "el.adm", kModel);
  const Result r = run("run el.adm --end 0.5 --dtout 0.05 --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  ResultsFileData d;
  std::string err;
  ASSERT_TRUE(readResultsFile((dir / "el.res").string(), d, &err)) << err;
  const auto series = [&](const char* entity, const char* component) {
    const auto id = d.componentId(entity, component);
    EXPECT_TRUE(id.has_value()) << entity << "." << component;
    return id ? d.series(*id) : std::vector<double>{};
  };
  long compared = 0;
  // Two evaluations of one quantity from the same state: equal to 1e-12 of the series' size.
  const auto same = [&](const std::vector<double>& a, const std::vector<double>& b,
                        const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    ASSERT_FALSE(a.empty()) << what;
    double scale = 1.0;
    for (double v : b) scale = std::max(scale, std::fabs(v));
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k], b[k], 1e-12 * scale) << what << " step " << k;
      ++compared;
    }
  };
  const char* forceNames[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};
  const char* requestNames[6] = {"U2", "U3", "U4", "U6", "U7", "U8"};
  for (int c = 0; c < 6; ++c)
    same(series("NFORCE_1", forceNames[c]), series("REQUEST_1", requestNames[c]),
         std::string("NFORCE_1.") + forceNames[c]);
  // The NFORCE is in equilibrium: J takes minus the sum of the I forces (all on the z axis).
  {
    const std::vector<double> f20 = series("REQUEST_2", "U2"), f30 = series("REQUEST_2", "U3");
    std::vector<double> balance(f20.size());
    for (std::size_t k = 0; k < f20.size(); ++k) balance[k] = -(f20[k] + f30[k]);
    same(series("NFORCE_1", "FZ"), balance, "NFORCE_1.FZ balance");
  }
  // The GCON is the only element between 102 and 401: the FORCE request is its reaction on I.
  const char* forceRequest[6] = {"x", "y", "z", "r1", "r2", "r3"};
  for (int c = 0; c < 6; ++c)
    same(series("GCON_1", forceNames[c]), series("REQUEST_3", forceRequest[c]),
         std::string("GCON_1.") + forceNames[c]);
  same(series("TFSISO_1", "X1"), series("REQUEST_4", "U2"), "TFSISO_1.X1");
  same(series("TFSISO_1", "X2"), series("REQUEST_4", "U3"), "TFSISO_1.X2");
  same(series("LSE_2", "X1"), series("REQUEST_4", "U4"), "LSE_2.X1");
  same(series("PINPUT_1", "IN1"), series("REQUEST_4", "U6"), "PINPUT_1.IN1");
  same(series("POUTPUT_1", "OUT1"), series("REQUEST_4", "U7"), "POUTPUT_1.OUT1");
  // 11 output steps: t = 0 (initial conditions), then 0.05 .. 0.5.
  const long steps = static_cast<long>(series("time", "TIME").size());
  EXPECT_EQ(steps, 11);
  EXPECT_EQ(compared, (6 + 1 + 6 + 5) * steps);
  // Not all zero: the comparison has something to compare.
  double gcon = 0.0, lse = 0.0;
  for (double v : series("GCON_1", "FY")) gcon = std::max(gcon, std::fabs(v));
  for (double v : series("LSE_2", "X1")) lse = std::max(lse, std::fabs(v));
  EXPECT_GT(gcon, 1.0);
  EXPECT_GT(lse, 1e-3);
  std::printf("[ .res element entities vs read-backs: %ld values ]\n", compared);
  fs::remove_all(dir);
}

// Closed forms for the entities of COUPLER, CONTACT and FRICTION (docs/output-files.md,
// "Entities and components": the reaction or force on the I marker's part, ground axes).
constexpr double kG = 9.81;

// COUPLER/1 ties two vertical revolute joints, q1 + 2 q2 = 0; SFORCE/5 turns part 5 (Izz = 1)
// with T = 2, part 6 (Izz = 4) follows at -1/2 the angle. Eliminating q2, (I5 + I6/4) q1'' = T,
// so the coupling's torque on part 5 is I5 q1'' - T = -T (I6/4) / (I5 + I6/4) = -1 exactly.
// CONTACT/1: a sphere of radius 0.1 released 1e-3 above its rest depth on a box floor (top at
// z = 0); with ζ ≈ 0.3 at ω ≈ 83 rad/s the bounce decays as e^(-25 t), so at t = 1 s the
// contact force is m g to far below the 1e-6 asserted (at ERROR=1e-8; the default 1e-3 left
// a position error of 1.6e-8, 1.1e-5 of the force through the contact stiffness).
constexpr const char* kCouplerContact =
    "res coupler contact\nUNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\nMARKER/11, PART=1, QP=3,0,0\n"
    "MARKER/12, PART=1, QP=5,0,0\n"
    "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
    "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.098875\nMARKER/20, PART=2\n"
    "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
    "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=50, DMAX=1e-3, EXPONENT=1.5\n"
    "PART/5, MASS=1, CM=50, IP=1,1,1, QG=3,0,0\nMARKER/50, PART=5\n"
    "PART/6, MASS=1, CM=60, IP=4,4,4, QG=5,0,0\nMARKER/60, PART=6\n"
    "JOINT/5, REVOLUTE, I=50, J=11\nJOINT/6, REVOLUTE, I=60, J=12\n"
    "COUPLER/1, JOINTS=5,6, TYPE=R,R, SCALES=2\n"
    "SFORCE/5, ROTATION, ACTIONONLY, I=50, J=11, FUNCTION=2\n"
    "ACCGRAV/ KGRAV=-9.81\nINTEGRATOR/ GSTIFF, ERROR=1e-8\n"
    "REQUEST/1, F2=CONTACT(1,0,2,0)\\F3=CONTACT(1,0,3,0)\\F4=CONTACT(1,0,4,0)\n"
    "RESULTS/XRF\nEND\n";

// FRICTION/1 on a translational joint sliding along ground z, gravity along -x: the joint
// carries N = m g = 19.62 and the block slides at v = 3 - 2.4525 t > 1.5 Vs for t <= 0.5, so
// the friction force on the block is -MU_DYNAMIC N = -4.905 along z (docs/theory.md §13).
constexpr const char* kFriction =
    "res friction\nUNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, VZ=3\nMARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "FRICTION/1, JOINT=1, MU_STATIC=0.4, MU_DYNAMIC=0.25, "
    "STICTION_TRANSITION_VELOCITY=0.01, MAX_STICTION_DEFORMATION=1e-4\n"
    "ACCGRAV/ IGRAV=-9.81\n"
    "REQUEST/1, F2=FRICTION(1,1)\\F3=FRICTION(1,2)\\F4=FRICTION(1,3)\n"
    "RESULTS/XRF\nEND\n";

ResultsFileData runAndRead(const fs::path& dir, const std::string& name, const char* text,
                           const std::string& options) {
  write(dir / (name + ".adm"), text);
  const Result r = run("run " + name + ".adm " + options + " --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  ResultsFileData d;
  std::string err;
  EXPECT_TRUE(readResultsFile((dir / (name + ".res")).string(), d, &err)) << err;
  return d;
}

std::vector<double> seriesOf(const ResultsFileData& d, const char* entity, const char* comp) {
  const auto id = d.componentId(entity, comp);
  EXPECT_TRUE(id.has_value()) << entity << "." << comp;
  return id ? d.series(*id) : std::vector<double>{};
}

TEST(ResultsElements, CouplerContactAndFrictionHoldTheirClosedForms) {
  const fs::path dir = scratch("res-elements-closed");
  long compared = 0;
  const auto near = [&](double a, double b, double tol, const std::string& what) {
    EXPECT_NEAR(a, b, tol) << what;
    ++compared;
  };
  const char* names[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};
  {
    const ResultsFileData d = runAndRead(dir, "cc", kCouplerContact, "--end 1 --dtout 0.1");
    const std::size_t steps = seriesOf(d, "time", "TIME").size();
    ASSERT_EQ(steps, 11u);
    // The coupling torque is constant (-1 about z), its other components zero. The deck runs
    // at ERROR=1e-8: the multiplier carries the integrator's error on q'' (the default 1e-3
    // left 1.8e-8), so 1e-9 on a 1 N m torque.
    for (int c = 0; c < 6; ++c) {
      const std::vector<double> v = seriesOf(d, "COUPLER_1", names[c]);
      ASSERT_EQ(v.size(), steps);
      for (std::size_t k = 1; k < steps; ++k)
        near(v[k], c == 5 ? -1.0 : 0.0, 1e-9, std::string("COUPLER_1.") + names[c]);
    }
    // The contact force entity equals the CONTACT() read-back (same state, 1e-12) and, at rest,
    // the weight m g (1e-6 relative: the transient has decayed by e^-25).
    const char* req[3] = {"U2", "U3", "U4"};
    for (int c = 0; c < 3; ++c) {
      const std::vector<double> v = seriesOf(d, "CONTACT_1", names[c]);
      const std::vector<double> r = seriesOf(d, "REQUEST_1", req[c]);
      ASSERT_EQ(v.size(), steps);
      ASSERT_EQ(r.size(), steps);
      for (std::size_t k = 0; k < steps; ++k)
        near(v[k], r[k], 1e-12 * kG, std::string("CONTACT_1.") + names[c] + " vs read-back");
      near(v.back(), c == 2 ? kG : 0.0, 1e-6 * kG, std::string("CONTACT_1.") + names[c]);
    }
  }
  {
    const ResultsFileData d = runAndRead(dir, "fr", kFriction, "--end 0.5 --dtout 0.05");
    const std::size_t steps = seriesOf(d, "time", "TIME").size();
    ASSERT_EQ(steps, 11u);
    const std::vector<double> fz = seriesOf(d, "FRICTION_1", "FZ");
    const std::vector<double> along = seriesOf(d, "REQUEST_1", "U4");
    ASSERT_EQ(fz.size(), steps);
    ASSERT_EQ(along.size(), steps);
    // From the first integrator output on (t >= 0.05) the block slides: the force is the
    // dynamic law to the corrector's accuracy on N (1e-6 relative), and |FRICTION(1,3)| is
    // the same force in the J axes (parallel to ground).
    for (std::size_t k = 1; k < steps; ++k) {
      near(fz[k], -0.25 * 2 * kG, 1e-6 * 2 * kG, "FRICTION_1.FZ");
      near(std::fabs(along[k]), std::fabs(fz[k]), 1e-12 * 2 * kG, "FRICTION_1.FZ vs read-back");
    }
    for (int c : {0, 1, 3, 4, 5})
      for (double v : seriesOf(d, "FRICTION_1", names[c]))
        near(v, 0.0, 1e-9, std::string("FRICTION_1.") + names[c]);
  }
  // 6 x 10 coupler, 3 x (11 + 1) contact, 2 x 10 + 5 x 11 friction values.
  EXPECT_EQ(compared, 60 + 36 + 20 + 55);
  std::printf("[ .res COUPLER, CONTACT, FRICTION entities vs closed forms: %ld values ]\n",
              compared);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss::output
