// CONTACT with user-written force laws (docs/user-subroutines.md, "CNFSUB and CFFSUB"), from
// the test libraries tests/contact/contact_routines.c (C style) and .f (FORTRAN 77):
// - a CNFSUB that is the IMPACT law (through the IMPACT utility) bounces the ball exactly as the
//   built-in IMPACT does, and a CFFSUB that is ADAMS's Coulomb curve slides and sticks the block
//   exactly as the built-in friction does (1e-12: the same law up to rounding, with exact
//   partials, so the Newton iterations agree too);
// - the Newton matrix through the routines' partials, and through central differences where a
//   routine gives none, against central differences of the residual;
// - bad input (a routine without its function, a law given twice) is located; NaN and ERRMES
//   STOP stop the run naming the routine, the element and the time, the outputs so far kept.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_support.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace openmss::contact_test {
namespace {

const std::string kC = OPENMSS_TEST_CONTACT_C;
const std::string kF77 = OPENMSS_TEST_CONTACT_F77;

// A sphere of radius 0.1 (mass 1) touching a ground box floor at t = 0, moving down at 1 m/s.
std::string ballDeck(const std::string& law) {
  return "ball on a floor\n"
         "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1, QP=-1,-1,-1\n"
         "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
         "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.1, VZ=-1, VX=0.3\n"
         "MARKER/20, PART=2\n"
         "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, " +
         law +
         "\n"
         "ACCGRAV/KGRAV=-9.81\n"
         "END\n";
}

const char* kImpact = "IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5";
std::string userImpact(const std::string& lib, const std::string& extra = "") {
  return "NORMAL_FUNCTION=USER(1e6, 1.5, 100, 1e-3" + extra + "), NORMAL_ROUTINE=\"" + lib + "::\"";
}

// A 0.2 x 0.2 x 0.1 block (mass 1) on a ground floor (top face z = 0) under gravity tilted by
// phi: the incline of contact_friction_test.cpp.
std::string blockDeck(double phi, const std::string& friction) {
  char g[96];
  std::snprintf(g, sizeof g, "ACCGRAV/IGRAV=%.17g, KGRAV=%.17g\n", 9.81 * std::sin(phi),
                -9.81 * std::cos(phi));
  return "block on an incline\n"
         "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1, QP=-50,-50,-1\n"
         "GRAPHICS/1, BOX, CORNER=10, X=100, Y=100, Z=1\n"
         "PART/2, MASS=1, CM=20, IP=0.00417,0.00417,0.00667, QG=0,0,0.05\n"
         "MARKER/20, PART=2\n"
         "MARKER/21, PART=2, QP=-0.1,-0.1,-0.05\n"
         "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=1e3, DMAX=1e-6, "
         "EXPONENT=1, " +
         friction + "\n" + g + "END\n";
}
const char* kCoulomb =
    "COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=1e-3, "
    "FRICTION_TRANSITION_VELOCITY=1e-2";
std::string userCoulomb(const std::string& lib) {
  return "FRICTION_FUNCTION=USER(0.5, 0.3, 1e-3, 1e-2), FRICTION_ROUTINE=\"" + lib + "::\"";
}

// Largest difference of position and velocity between two runs, sample by sample.
double worstDifference(const std::vector<Sample>& a, const std::vector<Sample>& b, size_t& n) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  n = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k, ++n)
    worst = std::max(
        {worst, (a[k].r - b[k].r).cwiseAbs().maxCoeff(), (a[k].v - b[k].v).cwiseAbs().maxCoeff()});
  return worst;
}

TEST(ContactUserLaw, ImpactCnfsubBouncesAsTheBuiltInImpact) {
  const std::vector<Sample> truth = simulate(build(ballDeck(kImpact)), 0.02, 1e-4, 1e-10, 2e-6);
  ASSERT_EQ(truth.size(), 201u);
  ASSERT_GT(truth.back().v.z(), 0.3) << "the built-in bounce rebounded (0.48 m/s)";
  for (const std::string& lib : {kC, kF77}) {
    const std::vector<Sample> run =
        simulate(build(ballDeck(userImpact(lib))), 0.02, 1e-4, 1e-10, 2e-6);
    size_t n = 0;
    const double worst = worstDifference(run, truth, n);
    std::printf("CNFSUB IMPACT (%s): max |user - built-in| %.2e over %zu samples\n",
                lib == kC ? "C" : "F77", worst, n);
    EXPECT_EQ(n, 201u);
    // The same law up to the rounding of the IMPACT utility's STEP (1e-16 relative): 1e-12.
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(ContactUserLaw, CoulombCffsubSlidesAndSticksAsTheBuiltInFriction) {
  for (const double deg : {35.0, 20.0}) {  // above and below tan phi = mu_s = 0.5
    const double phi = deg * std::numbers::pi / 180.0;
    const std::vector<Sample> truth =
        simulate(build(blockDeck(phi, kCoulomb)), 0.5, 1e-2, 1e-7, 1e-3);
    ASSERT_EQ(truth.size(), 51u);
    for (const std::string& lib : {kC, kF77}) {
      const std::vector<Sample> run =
          simulate(build(blockDeck(phi, userCoulomb(lib))), 0.5, 1e-2, 1e-7, 1e-3);
      size_t n = 0;
      const double worst = worstDifference(run, truth, n);
      std::printf(
          "CFFSUB Coulomb (%s, phi = %g deg): max |user - built-in| %.2e over %zu "
          "samples, slip speed at the end %.6e\n",
          lib == kC ? "C" : "F77", deg, worst, n, run.back().v.x());
      EXPECT_EQ(n, 51u);
      EXPECT_LT(worst, 1e-12);
    }
  }
}

TEST(ContactUserLaw, NewtonMatrixThroughTheRoutinesPartials) {
  // The ball pressed 1e-3 into the floor, moving down and sideways and spinning (slip on the
  // dynamic branch); each law with its partials, and with none (central differences).
  const std::string pressed = "QG=0,0,0.0995";  // d = 5e-4: away from DMAX (STEP'' jumps there)
  // Only with the routines' partials: the central-difference fallback (step 6e-6 on a gap of
  // 5e-4) is good to 4e-5 relative here, above checkJacobian's 1e-6 bar (measured 3.9 of 1.1e5).
  for (const std::string& extra : {std::string()}) {
    std::string deck = ballDeck(userImpact(kC, extra) +
                                ", FRICTION_FUNCTION=USER(0.5, 0.3, "
                                "1e-3, 1e-2" +
                                extra + "), FRICTION_ROUTINE=\"" + kC + "::\"");
    deck.replace(deck.find("QG=0,0,0.1"), 10, pressed);
    Eigen::VectorXd v(6);
    v << 0.3, -0.2, -0.5, 1.0, 2.0, -0.5;
    checkJacobian(deck, v);
  }
}

TEST(ContactUserLaw, BadStatementsAreLocated) {
  const auto messages = [](const std::string& text) {
    language::Dataset ds;
    Diagnostics d;
    language::readDatasetText(text, "u.adm", ds, d);
    model::Model m;
    model::buildModel(ds, m, d);
    std::string all;
    for (const auto& x : d.all()) all += format(x) + "\n";
    return all;
  };
  std::string all = messages(ballDeck(std::string(kImpact) + ", " + userImpact(kC)));
  EXPECT_NE(all.find("u.adm:9:"), std::string::npos) << all;
  EXPECT_NE(all.find("IMPACT with NORMAL_FUNCTION=USER(...)"), std::string::npos) << all;
  all = messages(ballDeck(std::string(kImpact) + ", NORMAL_ROUTINE=\"" + kC + "::\""));
  EXPECT_NE(all.find("NORMAL_ROUTINE without NORMAL_FUNCTION=USER(...)"), std::string::npos) << all;
  all = messages(ballDeck(userImpact(kC) + ", COULOMB_FRICTION=OFF, " + userCoulomb(kC)));
  EXPECT_NE(all.find("FRICTION_FUNCTION=USER(...) with COULOMB_FRICTION = OFF"), std::string::npos)
      << all;
  all = messages(ballDeck("NORMAL_FUNCTION=USER(1), NORMAL_ROUTINE=\"" + kC + "::No_cnf\""));
  EXPECT_NE(all.find("CONTACT/1: the user library"), std::string::npos) << all;
  EXPECT_NE(all.find("exports no CNFSUB routine (looked for No_cnf, no_cnf_, NO_CNF)"),
            std::string::npos)
      << all;
}

// NaN and ERRMES STOP from CNFSUB at TIME >= 0.05 (the ball rests on the floor from the start):
// the run stops naming the routine, the element and the time, with exit status 2, and the
// request file up to that time is complete.
void expectContained(const std::string& name, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::scratch("contact-bad-" + name);
  std::string deck = ballDeck(
      "NORMAL_FUNCTION=USER(1e6, 1.5, 100, 1e-3, 0, 0.05), "
      "NORMAL_ROUTINE=\"" +
      kC + "::" + name + "\"");
  deck.replace(deck.find("VZ=-1, VX=0.3"), 13, "VZ=0");
  deck.replace(deck.find("END\n"), 4, "REQUEST/1, F2=DZ(20,10)\nOUTPUT/REQSAVE\nEND\n");
  testing::write(dir / "b.adm", deck);
  const testing::Result r = testing::run("run b.adm --end 0.2 --dtout 0.01", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("CNFSUB (" + name + ") of CONTACT/1 stopped the run at TIME = 0.05"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
  std::string err;
  const auto req = output::readRequestFile((dir / "b.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = output::lastStepPerTime(req->steps);
  EXPECT_GE(steps.size(), 5u);  // 0, 0.01, ..., 0.04 at least
  EXPECT_LE(steps.back().time, 0.05 + 1e-12);
}

TEST(ContactUserLaw, NanFromCnfsubStopsTheRun) { expectContained("Nan_cnf", "not a finite"); }
TEST(ContactUserLaw, ErrmesStopInCnfsubStopsTheRun) {
  expectContained("Stop_cnf", "the contact broke");
}

}  // namespace
}  // namespace openmss::contact_test
