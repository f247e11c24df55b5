// CONTACT normal laws in dynamic runs against independent truth (docs/theory.md §6c):
// - IMPACT: a sphere landing on a box floor; its penetration history, maximum penetration and
//   contact duration against the 1-DOF IMPACT ODE integrated here by classical RK4 with a step
//   1000 times smaller than the run's output step.
// - POISSON: without gravity the rebound speed is RESTITUTION_COEFFICIENT times the approach
//   speed.
// - Energy: a frictionless undamped IMPACT bounce returns the energy it took.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_support.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kRadius = 0.1;

// A sphere of radius 0.1 (mass 1) whose lowest point touches the top face (z = 0) of a ground
// box floor at t = 0, moving down at 1 m/s, with the given CONTACT law and gravity.
std::string ballDeck(const std::string& law, double gravity) {
  return "ball on a floor\n"
         "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1, QP=-1,-1,-1\n"
         "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
         "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.1, VZ=-1\n"
         "MARKER/20, PART=2\n"
         "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
         "CONTACT/1, IGEOM=2, JGEOM=1, " +
         law +
         "\n"
         "ACCGRAV/KGRAV=" +
         std::to_string(-gravity) +
         "\n"
         "END\n";
}

TEST(ContactNormalLaw, ImpactBounceMatchesTheIntegratedImpactOde) {
  const ImpactOde ode{1e6, 1.5, 100.0, 1e-3, 9.81};
  const model::Model m =
      build(ballDeck("IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", ode.g));
  const double dt = 1e-5, end = 0.02;
  const std::vector<Sample> run = simulate(m, end, dt, 1e-10, 2e-6);
  ASSERT_EQ(run.size(), 2001u);
  std::vector<double> t, depth;
  for (const Sample& s : run) {
    t.push_back(s.t);
    depth.push_back(kRadius - s.r.z());
  }
  // Truth: RK4 with h = dt/1000 from d = 0, d' = 1 (the deck's state at t = 0).
  std::vector<double> truth(run.size());
  double x[2] = {0.0, 1.0};
  truth[0] = 0.0;
  const int sub = 1000;
  for (size_t k = 1; k < run.size(); ++k) {
    for (int q = 0; q < sub; ++q) ode.rk4(x, dt / sub);
    truth[k] = x[0];
  }
  const double maxTruth = peak(truth), durationTruth = returnTime(t, truth);
  const double maxRun = peak(depth), durationRun = returnTime(t, depth);
  double worst = 0.0;
  for (size_t k = 0; k < run.size(); ++k) worst = std::max(worst, std::abs(depth[k] - truth[k]));
  RecordProperty("max_penetration", std::to_string(maxRun));
  std::printf(
      "IMPACT bounce: max penetration %.9e (truth %.9e, rel %.2e), duration %.9e "
      "(truth %.9e, rel %.2e), worst |d - truth| %.2e over %zu samples\n",
      maxRun, maxTruth, std::abs(maxRun / maxTruth - 1), durationRun, durationTruth,
      std::abs(durationRun / durationTruth - 1), worst, run.size());
  ASSERT_GT(durationTruth, 0.0);
  // 1e-6 relative (the bar); the history to 1e-6 of the peak at every sample.
  EXPECT_NEAR(maxRun, maxTruth, 1e-6 * maxTruth);
  EXPECT_NEAR(durationRun, durationTruth, 1e-6 * durationTruth);
  EXPECT_LT(worst, 1e-6 * maxTruth);
}

TEST(ContactNormalLaw, PoissonReboundRatioIsTheRestitutionCoefficient) {
  for (const double r : {0.3, 0.6, 0.9}) {
    const model::Model m =
        build(ballDeck("POISSON, PENALTY=1e5, RESTITUTION_COEFFICIENT=" + std::to_string(r), 0.0));
    // Contact lasts about pi sqrt(m/p) (1e-2 s at most); the ball is free well before 0.03 s.
    const std::vector<Sample> run = simulate(m, 0.03, 1e-4, 1e-8, 1e-5);
    ASSERT_EQ(run.size(), 301u);
    const Sample& last = run.back();
    ASSERT_GT(last.r.z(), kRadius) << "separated";
    const double ratio = last.v.z() / 1.0;
    std::printf("POISSON r = %.2f: rebound ratio %.6f\n", r, ratio);
    EXPECT_NEAR(ratio, r, 1e-3);
  }
}

TEST(ContactNormalLaw, UndampedImpactBounceKeepsItsEnergy) {
  const double g = 9.81;
  const model::Model m =
      build(ballDeck("IMPACT, STIFFNESS=1e6, DAMPING=0, DMAX=1e-3, EXPONENT=1.5", g));
  const std::vector<Sample> run = simulate(m, 0.03, 1e-4, 1e-10, 1e-5);
  ASSERT_EQ(run.size(), 301u);
  auto energy = [&](const Sample& s) { return 0.5 * s.v.squaredNorm() + g * s.r.z(); };
  const double before = energy(run.front()), after = energy(run.back());
  ASSERT_GT(run.back().r.z(), kRadius) << "separated";
  ASSERT_GT(run.back().v.z(), 0.0) << "rebounding";
  const double impactEnergy = 0.5 * 1.0 * 1.0;  // kinetic energy at first touch
  std::printf("undamped bounce: energy change %.3e of the impact energy\n",
              (after - before) / impactEnergy);
  EXPECT_LT(std::abs(after - before), 1e-6 * impactEnergy);
}

TEST(ContactNormalLaw, OnsetEventsAreLocatedAndTheLooseBounceStaysAccurate) {
  // The ball starts 0.01 above the floor moving down at 1 m/s, so the first touch falls inside
  // a step. Truth: free fall to the touch (closed form), then the IMPACT ODE by RK4 as above.
  const ImpactOde ode{1e6, 1.5, 100.0, 1e-3, 9.81};
  std::string deck = ballDeck("IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", ode.g);
  deck.replace(deck.find("QG=0,0,0.1"), 10, "QG=0,0,0.11");
  const model::Model m = build(deck);
  const double touch = (-1.0 + std::sqrt(1.0 + 2.0 * ode.g * 0.01)) / ode.g;
  const double dt = 1e-4, end = 0.04;  // touch at 0.00995, release near 0.024
  std::vector<double> t, truth;
  double x[2] = {0.0, 1.0 + ode.g * touch};
  for (int k = 0; k <= 400; ++k) {
    const double tk = k * dt;
    t.push_back(tk);
    if (tk <= touch) {
      truth.push_back(-(0.01 - tk - 0.5 * ode.g * tk * tk));  // negative: the gap
      continue;
    }
    const double from = std::max(touch, (k - 1) * dt);
    for (int q = 0; q < 1000; ++q) ode.rk4(x, (tk - from) / 1000);
    truth.push_back(x[0]);
  }
  const double maxTruth = peak(truth);
  double errors[2];
  size_t onsets = 0;
  for (int withEvents = 0; withEvents < 2; ++withEvents) {
    std::vector<analysis::ContactEvent> events;
    // ERROR 1e-4 and HMAX 1e-3 (the contact lasts about 4e-3 s): a loose run.
    const std::vector<Sample> run =
        simulate(m, end, dt, 1e-4, 1e-3, withEvents ? &events : nullptr);
    ASSERT_EQ(run.size(), t.size());
    std::vector<double> depth;
    for (const Sample& s : run) depth.push_back(kRadius - s.r.z());
    errors[withEvents] = std::abs(peak(depth) / maxTruth - 1);
    if (withEvents) {
      onsets = events.size();
      ASSERT_GE(events.size(), 2u);
      EXPECT_TRUE(events[0].onset);
      EXPECT_EQ(events[0].contactId, 1);
      EXPECT_FALSE(events[1].onset);
      // The onset time to the bisection's bracket (1e-10 of a step) plus the integration error.
      std::printf("contact onset at %.12f (free-fall truth %.12f, diff %.2e), separation at %.9f\n",
                  events[0].time, touch, events[0].time - touch, events[1].time);
      EXPECT_NEAR(events[0].time, touch, 1e-6);
    }
  }
  std::printf(
      "loose bounce (ERROR 1e-4): max penetration rel error %.3e without events, %.3e "
      "with onset restarts (%zu events)\n",
      errors[0], errors[1], onsets);
  // Measured: the restart at onset does not improve the peak at this tolerance (2.47e-4 with,
  // 2.37e-4 without; docs/theory.md §6c): both stay within the run's ERROR-level accuracy.
  EXPECT_LT(errors[0], 1e-3);
  EXPECT_LT(errors[1], 1e-3);
}

// Two balls touch the floor 1e-7 s apart (a cluster, as a layer of the benchmark pile lands):
// the step that finds the first onset is cut back to it, and the restart's first step, which
// holds the second, is cut back to its last onset (docs/theory.md §6c, "Events"). Both onsets
// are located against the free-fall closed form all the same.
TEST(ContactNormalLaw, ClusteredOnsetsAreEachLocated) {
  const double g = 9.81;
  std::string deck = ballDeck("IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5", g);
  deck.replace(deck.find("QG=0,0,0.1"), 10, "QG=0,0,0.11");
  // The second ball 0.5 m away along x, 1e-7 m higher (it touches about 1e-7 s later).
  deck.replace(deck.find("ACCGRAV"), 0,
               "PART/3, MASS=1, CM=30, IP=0.004,0.004,0.004, QG=0.5,0,0.1100001, VZ=-1\n"
               "MARKER/30, PART=3\n"
               "GRAPHICS/3, ELLIPSOID, CM=30, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
               "CONTACT/2, IGEOM=3, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, "
               "EXPONENT=1.5\n");
  const model::Model m = build(deck);
  auto touch = [&](double h) { return (-1.0 + std::sqrt(1.0 + 2.0 * g * h)) / g; };
  std::vector<analysis::ContactEvent> events;
  simulate(m, 0.012, 1e-4, 1e-4, 1e-3, &events);
  std::vector<analysis::ContactEvent> onsets;
  for (const auto& e : events)
    if (e.onset) onsets.push_back(e);
  ASSERT_EQ(onsets.size(), 2u);
  EXPECT_EQ(onsets[0].contactId, 1);
  EXPECT_EQ(onsets[1].contactId, 2);
  const double truth[2] = {touch(0.01), touch(0.0100001)};
  std::printf("clustered onsets at %.12f and %.12f (truth %.12f and %.12f)\n", onsets[0].time,
              onsets[1].time, truth[0], truth[1]);
  // As the single onset above (1.1e-7 s there, outputs every 1e-4 s as here): the bracket plus
  // the integration error (with outputs every 1e-3 s both are 1e-5 s late: ERROR 1e-4's level).
  EXPECT_NEAR(onsets[0].time, truth[0], 1e-6);
  EXPECT_NEAR(onsets[1].time, truth[1], 1e-6);
  EXPECT_LT(onsets[0].time, onsets[1].time);
}

}  // namespace
}  // namespace openmss::contact_test
