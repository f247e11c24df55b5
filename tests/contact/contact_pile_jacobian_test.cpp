// The Newton matrix of a small pile of spheres (docs/theory.md §6c, "Shared kinematics"): one
// CONTACT per sphere against the floor and one per pair of spheres, as bench/contact_pile.py
// writes them. The sparse matrix's compressed passes evaluate only the contacts near (shared
// broad phase) and, per pass, only those at the parts the pass seeds; the result must equal
// the dense matrix (every element in every direction) and central differences of the residual.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "contact/contact_support.hpp"
#include "mechanics/contact/contact_broad_phase.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::contact_test {
namespace {

// Four spheres (radius 0.05) on the floor 0.099 apart (1e-3 into the floor and into their
// neighbours; the fourth 5e-4 into the floor), a fifth resting on the four, and a sixth far
// above (its contacts are apart: the broad phase leaves them out).
// Spheres (diameter 0.1, 0.1 kg) at `centres` above a ground BOX, a CONTACT with `law` between
// each sphere and the floor and between every two spheres.
std::string sphereDeck(const std::string& title, const std::vector<std::array<double, 3>>& centres,
                       const std::string& law) {
  std::string d = title +
                  "\nPART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\n"
                  "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n";
  const int n = static_cast<int>(centres.size());
  for (int i = 0; i < n; ++i) {
    const int p = 2 + i;
    char line[256];
    std::snprintf(line, sizeof line,
                  "PART/%d, MASS=0.1, CM=%d, IP=1e-4,1e-4,1e-4, QG=%.6f,%.6f,%.6f\n"
                  "MARKER/%d, PART=%d\n"
                  "GRAPHICS/%d, ELLIPSOID, CM=%d, XSCALE=0.1, YSCALE=0.1, ZSCALE=0.1\n",
                  p, 10 * p, centres[i][0], centres[i][1], centres[i][2], 10 * p, p, 10 * p,
                  10 * p);
    d += line;
  }
  d += pileContacts(n, 2, "1", law);
  return d + "ACCGRAV/KGRAV=-9.81\nEND\n";
}

std::string pileDeck() {
  const double z5 = 0.049 + 0.0700;
  return sphereDeck("pile jacobian",
                    {{0, 0, 0.049},
                     {0.099, 0, 0.049},
                     {0, 0.099, 0.049},
                     {0.099, 0.099, 0.0495},
                     {0.0495, 0.0495, z5},
                     {1, 1, 1}},
                    "IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=2e-3, EXPONENT=1.5, "
                    "COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, "
                    "STICTION_TRANSITION_VELOCITY=0.1, FRICTION_TRANSITION_VELOCITY=1\n");
}

// dG/dy (cj = 0, dense) against central differences of the residual, every column.
void expectCentralDifferences(const mechanics::MultibodySystem& s, const Eigen::VectorXd& y,
                              const Eigen::VectorXd& yp, const Eigen::MatrixXd& e) {
  const ColumnMismatch d = centralDifferenceMismatch(s, y, yp, e, 1e-7);
  std::printf(
      "contact pile: max |sparse - central difference| %.3e of max entry %.3e over %d "
      "columns\n",
      d.worst, d.scale, d.columns);
  EXPECT_EQ(d.columns, static_cast<int>(y.size()));
  // Central differences with h = 1e-7 are good to ~1e-7 relative on these smooth branches (as
  // contact_model_test.cpp's single contacts).
  EXPECT_LT(d.worst, 1e-6 * d.scale);
}

TEST(ContactPile, NewtonMatrixMatchesDenseAndCentralDifferences) {
  const model::Model m = build(pileDeck());
  ASSERT_EQ(m.contacts.size(), 21u);
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;  // friction acts
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState();
  // Every sphere moving and turning, each differently (slip on every friction branch).
  for (int b = 0; b < s.layout().bodies; ++b)
    for (int c = 0; c < 3; ++c) {
      y(s.layout().body(b) + StateLayout::kV + c) = 0.3 * std::sin(1.0 + 3 * b + c);
      y(s.layout().body(b) + StateLayout::kW + c) = 2.0 * std::cos(2.0 + 5 * b + c);
    }
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());

  // What is being compared: the contacts in touch (4 on the floor, 4 between floor
  // neighbours, 4 under the top sphere) and the near ones (the far sphere's 6 are apart).
  int touching = 0;
  for (const model::Contact& c : m.contacts)
    touching +=
        mechanics::contact::contactLoads<double>(m, s.layout(), c, y.data(), true).points > 0;
  EXPECT_EQ(touching, 12);
  mechanics::contact::ContactBroadPhase broad(m, s.layout());
  // Near: the 8 pairs in touch and 5 spheres against the floor (its bounding sphere, radius 3
  // about the corner, reaches all but the far sphere); the far sphere's 6 contacts are apart.
  EXPECT_EQ(broad.near(y.data()).size(), 13u);

  // The sparse matrix (compressed passes, contacts left out per pass) against the dense one.
  const double cj = 30.0;
  const mechanics::JacobianPattern pattern = mechanics::newtonMatrixPattern(s);
  Eigen::SparseMatrix<double> sparse = pattern.matrix();
  mechanics::SparseJacobianWork work;
  Eigen::MatrixXd dense;
  s.newtonMatrix(0.0, y, yp, cj, dense);
  s.newtonMatrixSparse(0.0, y, yp, cj, pattern, sparse, work);
  const double largest = dense.cwiseAbs().maxCoeff();
  const double difference = (Eigen::MatrixXd(sparse) - dense).cwiseAbs().maxCoeff();
  std::printf("contact pile: max |sparse - dense| %.3e of largest entry %.3e\n", difference,
              largest);
  // Both are exact partials summed in different orders: round-off of the largest entry.
  EXPECT_LE(difference, 1e-12 * largest);
  EXPECT_TRUE(s.rowsOutsidePattern(0.0, y, yp, cj, sparse, work).empty());

  // dG/dy (cj = 0) against central differences of the residual, every column.
  Eigen::SparseMatrix<double> exact = pattern.matrix();
  s.newtonMatrixSparse(0.0, y, yp, 0.0, pattern, exact, work);
  expectCentralDifferences(s, y, yp, Eigen::MatrixXd(exact));
}

// The near-pair pattern (docs/theory.md §6c, "Near-pair pattern") at the same state: the far
// sphere's pairs are out of the pattern, and the matrix equals the dense one, the one on the
// full pattern and central differences.
TEST(ContactPile, NearPairPatternLeavesFarPairsOutAndMatchesTheFullPattern) {
  const model::Model m = build(pileDeck());
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState();
  for (int b = 0; b < s.layout().bodies; ++b)
    for (int c = 0; c < 3; ++c) {
      y(s.layout().body(b) + StateLayout::kV + c) = 0.3 * std::sin(1.0 + 3 * b + c);
      y(s.layout().body(b) + StateLayout::kW + c) = 2.0 * std::cos(2.0 + 5 * b + c);
    }
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());
  const double cj = 30.0;
  analysis::MultibodyDae nearDae(s), fullDae(s, false);
  Eigen::SparseMatrix<double> nearJac = *nearDae.pattern(), fullJac = *fullDae.pattern();
  nearDae.newtonMatrixSparse(0.0, y, yp, cj, nearJac);
  fullDae.newtonMatrixSparse(0.0, y, yp, cj, fullJac);
  EXPECT_EQ(nearDae.patternRebuilds(), 1);
  EXPECT_EQ(nearDae.patternRepairs(), 0);
  EXPECT_EQ(fullDae.patternRepairs(), 0);
  // Held: the 13 elements near at factor 1 and whatever is near at 1.25; none of the far
  // sphere's five pairs (the far sphere is part 7, the last; its pairs are the last of each
  // row of pairs: elements 11, 15, 18, 20 and 21 of 1..21, indices 10, 14, 17, 19, 20).
  const std::vector<char>& held = nearDae.jacobianPattern().contacts;
  ASSERT_EQ(held.size(), m.contacts.size());
  int count = 0;
  for (char c : held) count += c != 0;
  mechanics::contact::ContactBroadPhase broad(m, s.layout());
  EXPECT_GE(count, static_cast<int>(broad.near(y.data()).size()));
  for (int e : {10, 14, 17, 19, 20}) EXPECT_EQ(held[e], 0) << "element " << e;
  for (int e : broad.near(y.data())) EXPECT_EQ(held[e], 1) << "element " << e;
  EXPECT_LT(nearJac.nonZeros(), fullJac.nonZeros());
  std::printf("contact pile: near-pair pattern %d of %zu CONTACT elements, %ld of %ld nonzeros\n",
              count, held.size(), static_cast<long>(nearJac.nonZeros()),
              static_cast<long>(fullJac.nonZeros()));

  // The same values: the left-out entries of the full matrix are exact zeros.
  const Eigen::MatrixXd nearDense(nearJac), fullDense(fullJac);
  Eigen::MatrixXd dense;
  s.newtonMatrix(0.0, y, yp, cj, dense);
  const double largest = dense.cwiseAbs().maxCoeff();
  const double toFull = (nearDense - fullDense).cwiseAbs().maxCoeff();
  const double toDense = (nearDense - dense).cwiseAbs().maxCoeff();
  std::printf("contact pile: near pattern: max |near - full| %.3e, |near - dense| %.3e of %.3e\n",
              toFull, toDense, largest);
  EXPECT_LE(toFull, 1e-12 * largest);
  EXPECT_LE(toDense, 1e-12 * largest);
  Eigen::SparseMatrix<double> exact = *nearDae.pattern();
  nearDae.newtonMatrixSparse(0.0, y, yp, 0.0, exact);
  expectCentralDifferences(s, y, yp, Eigen::MatrixXd(exact));
}

// Eight spheres: four resting on the floor 0.13 apart (apart from each other), three dropped
// onto them (frictionless: they push the four apart) and one dropped far away: the near set
// changes as they fall.
std::string dropDeck() {
  return sphereDeck("pile drop",
                    {{0, 0, 0.0495},
                     {0.13, 0, 0.0495},
                     {0, 0.13, 0.0495},
                     {0.13, 0.13, 0.0495},
                     {0.065, 0.066, 0.20},
                     {0.064, -0.001, 0.30},
                     {0.001, 0.064, 0.36},
                     {0.6, 0.6, 0.25}},
                    "IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5\n");
}

struct DropRun {
  std::vector<Eigen::VectorXd> states;  // every 0.01 s
  int rebuilds = 0, repairs = 0;
  long steps = 0;
  std::string solver;  // the linear solver of the last Newton matrix
};

// GSTIFF-style BDF (sparse: 112 states) under the contact event locator, `samples` outputs
// `every` seconds apart (to 0.3 s by default); `supernodal` forces the supernodal LU on
// every pattern (by default this small pile's matrices go to KLU).
DropRun drop(const model::Model& m, bool nearPattern, int samples = 30, double every = 0.01,
             bool supernodal = false) {
  DropRun out;
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  analysis::MultibodyDae dae(s, nearPattern);
  solvers::MultistepSettings settings;
  settings.error = 1e-5;
  settings.hmax = 1e-3;
  settings.hinit = 1e-4;
  solvers::BdfIntegrator method(dae, settings);
  if (supernodal) method.sparseLinearSolver().setSupernodalFlops(0.0);
  analysis::ContactEventIntegrator located(method, s);
  located.start(0.0, y, yp);
  out.states.push_back(y);
  for (int k = 1; k <= samples; ++k) {
    if (!located.advanceTo(k * every)) {
      ADD_FAILURE() << "integration failed at " << k * every << ": " << located.failure().reason;
      break;
    }
    out.states.push_back(located.y());
  }
  out.rebuilds = dae.patternRebuilds();
  out.repairs = dae.patternRepairs();
  out.steps = located.statistics().steps;
  out.solver = method.linearSolverName();
  return out;
}

// The near set changes mid-run (the droppers come near the resting spheres): the run on the
// near-pair pattern equals the one on the full pattern to round-off amplified by the
// corrector's tolerance, and two runs are bit-identical.
TEST(ContactPile, NearSetChangesMidRunAndTheRunMatchesTheFullPattern) {
  const model::Model m = build(dropDeck());
  const DropRun nearRun = drop(m, true), again = drop(m, true), fullRun = drop(m, false);
  ASSERT_EQ(nearRun.states.size(), 31u);
  ASSERT_EQ(fullRun.states.size(), 31u);
  std::printf("contact drop: %ld steps (full pattern %ld), %d pattern rebuilds, %d repairs\n",
              nearRun.steps, fullRun.steps, nearRun.rebuilds, nearRun.repairs);
  EXPECT_GE(nearRun.rebuilds, 3);  // the first pattern, then each dropper's arrival
  EXPECT_EQ(nearRun.repairs, 0);
  EXPECT_EQ(fullRun.rebuilds, 0);
  // Physics where it is closed-form: the far sphere falls freely until 0.2 s (z = 0.25 - g t²/2,
  // to the run's ERROR 1e-5), and the first dropper did reach the resting spheres (its
  // onset changed the near set: the rebuilds above) and went below its start.
  const mechanics::MultibodySystem sys(m);
  const int far = sys.layout().body(7) + StateLayout::kR + 2;
  const int dropper = sys.layout().body(4) + StateLayout::kR + 2;
  EXPECT_NEAR(nearRun.states[10](far), 0.25 - 0.5 * 9.81 * 0.01, 1e-5);
  EXPECT_NEAR(nearRun.states[15](far), 0.25 - 0.5 * 9.81 * 0.0225, 1e-5);
  EXPECT_LT(nearRun.states.back()(dropper), 0.15);
  double worst = 0.0;
  for (size_t k = 0; k < nearRun.states.size(); ++k) {
    const Eigen::VectorXd& a = nearRun.states[k];
    const Eigen::VectorXd& b = fullRun.states[k];
    for (int i = 0; i < static_cast<int>(a.size()); ++i)
      worst = std::max(worst, std::abs(a(i) - b(i)) / (1.0 + std::abs(b(i))));
    // Determinism: the same decisions and the same bits.
    EXPECT_EQ(0, std::memcmp(a.data(), again.states[k].data(), sizeof(double) * a.size()))
        << "sample " << k;
  }
  std::printf("contact drop: max |near - full| / (1 + |full|) %.3e\n", worst);
  EXPECT_LE(worst, 1e-9);
}

// The same drop with every Newton matrix factorised by the supernodal LU (docs/theory.md §9a,
// "Linear solver"; a 1000-sphere pile takes it by the flop rule, this small one only when
// forced): the run equals the KLU run to the round-off the corrector's tolerance amplifies
// (as the near-pair pattern against the full one above), and two runs give the same bits.
TEST(ContactPile, SupernodalLuRunMatchesTheKluRun) {
  const model::Model m = build(dropDeck());
  const DropRun kluRun = drop(m, true);
  const DropRun superRun = drop(m, true, 30, 0.01, true), again = drop(m, true, 30, 0.01, true);
  EXPECT_EQ(kluRun.solver, "KLU");
  EXPECT_EQ(superRun.solver, "supernodal LU");
  ASSERT_EQ(kluRun.states.size(), 31u);
  ASSERT_EQ(superRun.states.size(), 31u);
  double worst = 0.0;
  for (size_t k = 0; k < kluRun.states.size(); ++k) {
    const Eigen::VectorXd& a = superRun.states[k];
    const Eigen::VectorXd& b = kluRun.states[k];
    for (int i = 0; i < static_cast<int>(a.size()); ++i)
      worst = std::max(worst, std::abs(a(i) - b(i)) / (1.0 + std::abs(b(i))));
    EXPECT_EQ(0, std::memcmp(a.data(), again.states[k].data(), sizeof(double) * a.size()))
        << "sample " << k;
  }
  std::printf(
      "contact drop: %ld steps with the supernodal LU (KLU %ld), max |supernodal - KLU| "
      "/ (1 + |KLU|) %.3e\n",
      superRun.steps, kluRun.steps, worst);
  // The Newton iterates stop at a change of the order of ERROR = 1e-5 times a small factor;
  // the two factorisations' round-off (1e-15 relative) moves the last iterate far less, and
  // the near-vs-full comparison above holds the same runs to the same bound.
  EXPECT_LE(worst, 1e-9);
}

// A deterministic uniform number in [0, 1) (a linear congruential generator): the broad-phase
// tests' scattered positions, the same on every platform.
struct Lcg {
  unsigned state;
  double operator()() {
    state = 1103515245u * state + 12345u;
    return (state >> 8) / 16777216.0;
  }
};

// The sort and sweep (contact_sweep.hpp) against the brute-force test of every solid pair of
// every element, on the 8-sphere deck with the spheres scattered (deterministic LCG) from
// touching to apart, at the factors the near-pair pattern uses.
TEST(ContactPile, SweepEqualsBruteForce) {
  const model::Model m = build(dropDeck());
  mechanics::MultibodySystem s(m);
  mechanics::contact::ContactBroadPhase broad(m, s.layout());
  Lcg uniform{12345u};
  int nearTotal = 0, cases = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd y = s.initialState();
    const double spread = 0.05 + 0.5 * uniform();  // from a tight cluster to apart
    for (int b = 0; b < s.layout().bodies; ++b)
      for (int c = 0; c < 3; ++c) y(s.layout().body(b) + StateLayout::kR + c) = spread * uniform();
    for (const double factor :
         {1.0, analysis::MultibodyDae::kEnter, analysis::MultibodyDae::kLeave}) {
      const std::vector<int> swept = broad.nearWithin(y.data(), factor);
      EXPECT_EQ(swept, broad.nearBruteForce(y.data(), factor)) << "trial " << trial;
      nearTotal += static_cast<int>(swept.size());
      ++cases;
    }
    EXPECT_EQ(broad.near(y.data()), broad.nearBruteForce(y.data(), 1.0)) << "trial " << trial;
  }
  // Both sides were exercised: sets from the floor contacts alone to most pairs.
  std::printf("contact sweep: %d cases, %.1f near elements on average of %zu\n", cases,
              double(nearTotal) / cases, m.contacts.size());
  EXPECT_GT(nearTotal, 8 * cases);
  EXPECT_LT(nearTotal, 36 * cases);
}

// The grid of the broad phase (contact_sweep.hpp: from 64 solids, the spheres in cells, the
// box against all) against the brute-force test, on 80 spheres scattered (deterministic LCG)
// from a heap tighter than their diameter to apart, at the near-pair factors; and with one
// sphere thrown 50 m away, where the grid would be too sparse and the sweep answers.
TEST(ContactPile, GridEqualsBruteForce) {
  std::vector<std::array<double, 3>> centres;
  for (int i = 0; i < 80; ++i)
    centres.push_back({0.12 * (i % 5), 0.12 * (i / 5 % 4), 0.12 * (i / 20)});
  const model::Model m = build(
      sphereDeck("grid", centres, "IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5\n"));
  mechanics::MultibodySystem s(m);
  mechanics::contact::ContactBroadPhase broad(m, s.layout());
  Lcg uniform{4321u};
  int nearTotal = 0, cases = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Eigen::VectorXd y = s.initialState();
    const double spread = 0.2 + 1.0 * uniform();  // 80 spheres of 0.1 in 0.2^3 m^3 to 1.2^3
    for (int b = 0; b < s.layout().bodies; ++b)
      for (int c = 0; c < 3; ++c)
        y(s.layout().body(b) + StateLayout::kR + c) = spread * uniform() - 0.3 * (c == 2);
    if (trial % 10 == 9) y(s.layout().body(0) + StateLayout::kR) = 50.0;
    for (const double factor :
         {1.0, analysis::MultibodyDae::kEnter, analysis::MultibodyDae::kLeave}) {
      const std::vector<int> found = broad.nearWithin(y.data(), factor);
      EXPECT_EQ(found, broad.nearBruteForce(y.data(), factor)) << "trial " << trial;
      nearTotal += static_cast<int>(found.size());
      ++cases;
    }
  }
  std::printf("contact grid: %d cases (%ld by the grid), %.1f near elements on average of %zu\n",
              cases, broad.sweep().gridAnswers(), double(nearTotal) / cases, m.contacts.size());
  // Both paths ran: the grid on the heaps, the sweep on the far sphere's trials (4 x 3 cases)
  // and on the loosest spreads (more cells than 8 per sphere).
  EXPECT_GE(broad.sweep().gridAnswers(), cases / 2);
  EXPECT_LE(broad.sweep().gridAnswers(), cases - 12);
  // Sets from a few pairs to hundreds: the grid's cells were exercised, not only the box.
  EXPECT_GT(nearTotal, 150 * cases);
}

// Physics on the near-pair pattern: eight spheres stacked on the floor along z (centres on one
// vertical line, so every force is vertical; DAMPING 100), 0.02 apart at the start (not near: the
// near set changes at each landing), come to rest with the static penetrations of IMPACT's k d^1.5:
// the contact under sphere k carries (8 - k) m g, so d_k = ((8 - k) m g / k)^(2/3) and the centres
// are z_0 = R - d_0, z_k = z_(k-1) + 2 R - d_k (closed form).
TEST(ContactPile, StackOnTheNearPairPatternRestsAtTheStaticPenetrations) {
  std::string d =
      "pile stack\nPART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\n"
      "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n";
  for (int i = 0; i < 8; ++i) {
    const int p = 2 + i;
    char line[256];
    std::snprintf(line, sizeof line,
                  "PART/%d, MASS=0.1, CM=%d, IP=1e-4,1e-4,1e-4, QG=0,0,%.6f\n"
                  "MARKER/%d, PART=%d\n"
                  "GRAPHICS/%d, ELLIPSOID, CM=%d, XSCALE=0.1, YSCALE=0.1, ZSCALE=0.1\n",
                  p, 10 * p, 0.05 + 0.12 * i, 10 * p, p, 10 * p, 10 * p);
    d += line;
  }
  const std::string law = "IMPACT, STIFFNESS=1e5, DAMPING=100, DMAX=1e-4, EXPONENT=1.5\n";
  int id = 1;
  for (int i = 0; i < 8; ++i)
    d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (2 + i)) +
         ", JGEOM=1, " + law;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (2 + i)) +
           ", JGEOM=" + std::to_string(10 * (2 + j)) + ", " + law;
  const model::Model m = build(d + "ACCGRAV/KGRAV=-9.81\nEND\n");
  const DropRun run = drop(m, true, 20, 0.1);  // to 2 s
  ASSERT_EQ(run.states.size(), 21u);
  EXPECT_GE(run.rebuilds, 3);
  EXPECT_EQ(run.repairs, 0);
  const mechanics::MultibodySystem sys(m);
  double z = 0.0, worst = 0.0;
  for (int k = 0; k < 8; ++k) {
    const double load = (8 - k) * 0.1 * 9.81;
    const double penetration = std::pow(load / 1e5, 1.0 / 1.5);
    z += (k == 0 ? 0.05 : 0.1) - penetration;
    const double zk = run.states.back()(sys.layout().body(k) + StateLayout::kR + 2);
    worst = std::max(worst, std::abs(zk - z));
  }
  std::printf("contact stack: %ld steps, %d rebuilds, max |z - closed form| %.3e m\n", run.steps,
              run.rebuilds, worst);
  // The penetrations are 0.5 to 1.8 mm. DAMPING = 100 damps the stack's slowest mode (about
  // 40 rad/s) at some 0.4 of critical, so by 2 s it has decayed by far more than 1e-9
  // (measured: 1.2e-15 m, velocities below 1e-13 m/s): the equilibrium is met to round-off.
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace openmss::contact_test
