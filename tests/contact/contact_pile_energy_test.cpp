// Energy of an elastic multi-sphere pile (issue 17; docs/theory.md §6c, docs/performance.md
// "Contact pile"): eight spheres thrown about inside a closed box without gravity, every
// CONTACT (sphere-wall and sphere-sphere) undamped IMPACT without friction, so the total
// energy is conserved: the kinetic energy of the spheres plus, for every contact point, the
// IMPACT potential k d^(e+1) / (e+1) of its depth d. The truth is that conservation law,
// evaluated here from the run's positions and velocities with the depths computed in the test
// (sphere-sphere 2R - |c_i - c_j|, sphere-wall R - the distance from the centre to the wall's
// box), independent of the narrow phase. The run is the one the benchmark pile uses: the
// GSTIFF-style BDF on the near-pair pattern under the contact event locator.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/contact_support.hpp"

namespace openmss::contact_test {
namespace {

constexpr double kR = 0.05, kMass = 0.1, kInertia = 1e-4;
constexpr double kK = 1e5, kE = 1.5;
constexpr double kHalf = 0.2;  // the box's inner half-width
constexpr int kSpheres = 8;

// The six walls (0.1 thick) as ground BOX solids: corner and extents.
struct Wall {
  std::array<double, 3> corner, extent;
};
std::vector<Wall> walls() {
  const double a = kHalf, t = 0.1, w = 2 * (a + t);
  return {{{-a - t, -a - t, -a - t}, {w, w, t}},  // floor
          {{-a - t, -a - t, a}, {w, w, t}},       // ceiling
          {{-a - t, -a - t, -a}, {t, w, 2 * a}},  // -x
          {{a, -a - t, -a}, {t, w, 2 * a}},       // +x
          {{-a, -a - t, -a}, {2 * a, t, 2 * a}},  // -y
          {{-a, a, -a}, {2 * a, t, 2 * a}}};      // +y
}

// Centres on a 2 x 2 x 2 grid 0.2 apart (0.1 gaps), velocities of about 1 m/s in directions
// that send them into the walls and each other.
std::string energyDeck() {
  std::string d = "elastic pile\nPART/1, GROUND\n";
  const std::vector<Wall> w = walls();
  for (size_t i = 0; i < w.size(); ++i) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "MARKER/%zu, PART=1, QP=%g,%g,%g\nGRAPHICS/%zu, BOX, CORNER=%zu, X=%g, Y=%g, "
                  "Z=%g\n",
                  10 + i, w[i].corner[0], w[i].corner[1], w[i].corner[2], 1 + i, 10 + i,
                  w[i].extent[0], w[i].extent[1], w[i].extent[2]);
    d += line;
  }
  unsigned state = 2024;
  auto next = [&]() {  // a deterministic LCG in [-1, 1)
    state = 1103515245u * state + 12345u;
    return static_cast<double>((state >> 8) & 0xFFFF) / 32768.0 - 1.0;
  };
  for (int i = 0; i < kSpheres; ++i) {
    const int p = 100 + i;
    const double x = (i & 1 ? 0.1 : -0.1), y = (i & 2 ? 0.1 : -0.1), z = (i & 4 ? 0.1 : -0.1);
    char line[384];
    std::snprintf(line, sizeof line,
                  "PART/%d, MASS=%g, CM=%d, IP=%g,%g,%g, QG=%g,%g,%g, VX=%.6f, VY=%.6f, "
                  "VZ=%.6f\nMARKER/%d, PART=%d\nGRAPHICS/%d, ELLIPSOID, CM=%d, XSCALE=%g, "
                  "YSCALE=%g, ZSCALE=%g\n",
                  p, kMass, 10 * p, kInertia, kInertia, kInertia, x, y, z, next(), next(), next(),
                  10 * p, p, 10 * p, 10 * p, 2 * kR, 2 * kR, 2 * kR);
    d += line;
  }
  const std::string law = "IMPACT, STIFFNESS=1e5, DAMPING=0, DMAX=1e-4, EXPONENT=1.5\n";
  d += pileContacts(kSpheres, 100, "1,2,3,4,5,6", law);
  return d + "END\n";
}

double potential(double depth) { return depth > 0 ? kK * std::pow(depth, kE + 1) / (kE + 1) : 0.0; }

// Kinetic energy of every body plus the IMPACT potential of every contact point.
double energy(const mechanics::MultibodySystem& s, const Eigen::VectorXd& y, int* touching) {
  std::vector<Eigen::Vector3d> c;
  double e = 0.0;
  for (int b = 0; b < kSpheres; ++b) {
    const int o = s.layout().body(b);
    c.push_back(y.segment<3>(o + StateLayout::kR));
    e += 0.5 * kMass * y.segment<3>(o + StateLayout::kV).squaredNorm() +
         0.5 * kInertia * y.segment<3>(o + StateLayout::kW).squaredNorm();
  }
  *touching = 0;
  for (int i = 0; i < kSpheres; ++i) {
    for (int j = i + 1; j < kSpheres; ++j) {
      const double d = 2 * kR - (c[i] - c[j]).norm();
      *touching += d > 0;
      e += potential(d);
    }
    for (const Wall& w : walls()) {
      Eigen::Vector3d q;  // the wall's point nearest the centre (the centre stays outside)
      for (int k = 0; k < 3; ++k)
        q[k] = std::clamp(c[i][k], w.corner[k], w.corner[k] + w.extent[k]);
      const double d = kR - (c[i] - q).norm();
      *touching += d > 0;
      e += potential(d);
    }
  }
  return e;
}

struct EnergyRun {
  double initial = 0.0, worst = 0.0;  // the energy at t = 0 and its largest change
  int touchingSamples = 0;            // samples with a contact point in force
  long steps = 0;
};

EnergyRun run(const model::Model& m, double error) {
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState state(m);
  state.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&state);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  analysis::MultibodyDae dae(s, true);
  solvers::MultistepSettings settings;
  settings.error = error;
  settings.hmax = 1e-3;
  settings.hinit = 1e-4;
  solvers::BdfIntegrator method(dae, settings);
  analysis::ContactEventIntegrator located(method, s);
  located.start(0.0, y, yp);
  EnergyRun out;
  int touching = 0;
  out.initial = energy(s, y, &touching);
  for (int k = 1; k <= 400; ++k) {  // 0.4 s, every 1 ms
    if (!located.advanceTo(k * 1e-3)) {
      ADD_FAILURE() << "integration failed at " << k * 1e-3 << ": " << located.failure().reason;
      break;
    }
    out.worst = std::max(out.worst, std::abs(energy(s, located.y(), &touching) - out.initial));
    out.touchingSamples += touching > 0;
  }
  out.steps = located.statistics().steps;
  return out;
}

TEST(ContactPile, UndampedElasticPileInAClosedBoxConservesEnergy) {
  const model::Model m = build(energyDeck());
  ASSERT_EQ(m.contacts.size(), static_cast<size_t>(kSpheres + kSpheres * (kSpheres - 1) / 2));
  const EnergyRun tight = run(m, 1e-10), loose = run(m, 1e-7);
  std::printf(
      "elastic pile: energy %.6f J; largest change %.3e of it at ERROR 1e-10 (%ld steps), "
      "%.3e at 1e-7 (%ld steps); %d of 400 samples in contact\n",
      tight.initial, tight.worst / tight.initial, tight.steps, loose.worst / loose.initial,
      loose.steps, tight.touchingSamples);
  // The run did collide: contacts were in force at many samples (each impact lasts ~2 ms).
  EXPECT_GE(tight.touchingSamples, 20);
  // Conservation to 5e-5 of the energy at ERROR 1e-10. What is lost is the BDF's numerical
  // damping of the impacts, not a modelling error: it falls with ERROR (measured 2026-11-28,
  // largest change over the run: 1.5e-3 of the energy at 1e-7, 6.7e-5 at 1e-9, 1.15e-5 at
  // 1e-10; a potential that did not match the force would stay as ERROR falls). 5e-5 leaves 4x
  // for round-off across platforms; the looser run must lose more (the measure is not blind).
  EXPECT_LT(tight.worst, 5e-5 * tight.initial);
  EXPECT_GT(loose.worst, tight.worst);
}

}  // namespace
}  // namespace openmss::contact_test
