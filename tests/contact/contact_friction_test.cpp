// CONTACT Coulomb friction in dynamic runs against closed forms (docs/theory.md §6c). The
// incline is a horizontal box floor under gravity tilted by phi (the same mechanics, simpler
// geometry): g = 9.81 (sin phi, 0, -cos phi).
// - A block above tan phi = mu_s slides with a = g (sin phi - mu_d cos phi) once its slip
//   exceeds FRICTION_TRANSITION_VELOCITY.
// - Below it the block sticks: with ADAMS's regularised mu(v) it creeps at the constant speed
//   w vs where mu_s (3w - w^3)/2 = tan phi (the stiction branch of the curve), never faster.
// - A sphere rolls without slip: a = (5/7) g sin phi, v = (5/7) g sin phi t (slip below vs).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_support.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kG = 9.81;
constexpr double kMuStatic = 0.5, kMuDynamic = 0.3, kVs = 1e-3, kVd = 1e-2;

std::string gravity(double phi) {
  char text[96];
  std::snprintf(text, sizeof text, "ACCGRAV/IGRAV=%.17g, KGRAV=%.17g\n", kG * std::sin(phi),
                -kG * std::cos(phi));
  return text;
}

const char* kFriction =
    ", COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=1e-3, "
    "FRICTION_TRANSITION_VELOCITY=1e-2\n";

// A 0.2 x 0.2 x 0.1 block (mass 1) resting on a ground box floor whose top face is z = 0.
std::string blockDeck(double phi) {
  return std::string(
             "block on an incline\n"
             "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
             "PART/1, GROUND\n"
             "MARKER/10, PART=1, QP=-50,-50,-1\n"
             "GRAPHICS/1, BOX, CORNER=10, X=100, Y=100, Z=1\n"
             "PART/2, MASS=1, CM=20, IP=0.00417,0.00417,0.00667, QG=0,0,0.05\n"
             "MARKER/20, PART=2\n"
             "MARKER/21, PART=2, QP=-0.1,-0.1,-0.05\n"
             "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
             "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=1e3, "
             "DMAX=1e-6, EXPONENT=1") +
         kFriction + gravity(phi) + "END\n";
}

TEST(ContactFriction, BlockAboveTheFrictionAngleSlidesWithTheDynamicCoefficient) {
  const double phi = 35.0 * std::numbers::pi / 180.0;
  ASSERT_GT(std::tan(phi), kMuStatic);
  const std::vector<Sample> run = simulate(build(blockDeck(phi)), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  // After 0.5 s the slip is far above vd and the normal transient has died out.
  const Sample& a = run[50];
  const Sample& b = run[100];
  ASSERT_GT(a.v.x(), 100 * kVd);
  const double accel = (b.v.x() - a.v.x()) / (b.t - a.t);
  const double truth = kG * (std::sin(phi) - kMuDynamic * std::cos(phi));
  std::printf("sliding block: a = %.8f, g (sin phi - mu_d cos phi) = %.8f (rel %.2e)\n", accel,
              truth, std::abs(accel / truth - 1));
  EXPECT_NEAR(accel, truth, 1e-4 * truth);
  EXPECT_NEAR(b.v.y(), 0.0, 1e-9);
}

TEST(ContactFriction, BlockBelowTheFrictionAngleSticksAtTheStictionCreepSpeed) {
  const double phi = 20.0 * std::numbers::pi / 180.0;
  const double ratio = std::tan(phi) / kMuStatic;
  ASSERT_LT(ratio, 1.0);
  // Creep: mu_s (3w - w^3)/2 = tan phi, solved by Newton from w = 0.
  double w = 0.0;
  for (int k = 0; k < 50; ++k) w -= (0.5 * (3 * w - w * w * w) - ratio) / (1.5 * (1 - w * w));
  const double creep = w * kVs;
  const std::vector<Sample> run = simulate(build(blockDeck(phi)), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  // The block lands with no normal force and gains some slip before the normal force builds up
  // (under a millisecond): judge the sticking from 0.1 s on.
  double fastest = 0.0;
  for (const Sample& s : run)
    if (s.t >= 0.1) fastest = std::max(fastest, std::abs(s.v.x()));
  const Sample& last = run.back();
  std::printf(
      "sticking block: creep %.8e (closed form %.8e, rel %.2e), fastest %.3e, moved "
      "%.3e m in 1 s\n",
      last.v.x(), creep, std::abs(last.v.x() / creep - 1), fastest, last.r.x());
  EXPECT_LT(fastest, kVs);  // never leaves the stiction branch: it sticks
  EXPECT_NEAR(last.v.x(), creep, 1e-4 * creep);
}

TEST(ContactFriction, SphereRollsWithoutSlipAtFiveSeventhsGSinPhi) {
  const double phi = 20.0 * std::numbers::pi / 180.0;
  const double r = 0.1, mass = 1.0, inertia = 0.4 * mass * r * r;
  char body[160];
  std::snprintf(body, sizeof body, "PART/2, MASS=1, CM=20, IP=%.17g,%.17g,%.17g, QG=0,0,0.1\n",
                inertia, inertia, inertia);
  const std::string deck = std::string(
                               "rolling sphere\n"
                               "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, "
                               "TIME=SECOND\n"
                               "PART/1, GROUND\n"
                               "MARKER/10, PART=1, QP=-50,-50,-1\n"
                               "GRAPHICS/1, BOX, CORNER=10, X=100, Y=100, Z=1\n") +
                           body +
                           "MARKER/20, PART=2\n"
                           "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
                           "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e9, DAMPING=3e3, "
                           "DMAX=1e-6, EXPONENT=1.5" +
                           kFriction + gravity(phi) + "END\n";
  const std::vector<Sample> run = simulate(build(deck), 1.0, 1e-2, 1e-7, 1e-3);
  ASSERT_EQ(run.size(), 101u);
  // The rigid-sphere truth. The contact force acts midway between the surfaces, at r - d/2 from
  // the centre (d the penetration), so the compliant sphere rolls at g sin(phi) / (1 + I/(m
  // (r - d/2)^2)), below the rigid value by about 0.29 d/r: STIFFNESS = 1e9 makes d = (m g
  // cos(phi)/k)^(2/3) = 4.4e-6, 1.3e-5 relative.
  const double rolling = 5.0 / 7.0 * kG * std::sin(phi);
  const Sample& a = run[50];
  const Sample& b = run[100];
  const double accel = (b.v.x() - a.v.x()) / (b.t - a.t);
  // The velocity of the sphere's lowest point, v + w x (-r e_z), along x: v_x - r w_y. With
  // friction F: v' = g sin phi - F/m and r w_y' = (5/2) F/m, so v - (5/7) g sin phi t = (2/7)
  // slip at every instant: both stay below vs once the sphere has landed (from 0.1 s on; it
  // lands with no normal force and slips for under a millisecond).
  double worst = 0.0, slip = 0.0;
  int compared = 0;
  for (const Sample& s : run) {
    if (s.t < 0.1) continue;
    worst = std::max(worst, std::abs(s.v.x() - rolling * s.t));
    slip = std::max(slip, std::abs(s.v.x() - r * s.w.y()));
    ++compared;
  }
  std::printf(
      "rolling sphere: a = %.8f, (5/7) g sin phi = %.8f (rel %.2e); max |v - (5/7) g "
      "sin phi t| = %.3e, max slip %.3e over %d samples\n",
      accel, rolling, std::abs(accel / rolling - 1), worst, slip, compared);
  EXPECT_NEAR(accel, rolling, 1e-4 * rolling);
  // v = (5/7) g sin(phi) t up to the stiction creep (below vs) and the settling transient.
  EXPECT_LT(worst, kVs);
  EXPECT_LT(slip, kVs);  // rolls: the contact point never leaves the stiction branch
  EXPECT_EQ(compared, 91);
}

}  // namespace
}  // namespace openmss::contact_test
