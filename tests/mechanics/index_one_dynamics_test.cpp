// The index-1 equations of motion for explicit integration (mechanics/index_one_dynamics.hpp)
// against independent solves of the same equations:
// - accelerations and multipliers against solveAccelerations (Eigen's sparse LU of the whole
//   KKT matrix from 8 bodies on, full-pivot LU of the dense KKT matrix below): a different
//   factorisation of a different matrix, so agreement to 1e-10 relative (the KKT condition
//   numbers of these models are <= 1e5, round-off ~1e-16 of it) means the Schur complement,
//   its block Cholesky factor and the back-substitution are right;
// - the projection against the dense mass-weighted least change -M^-1 C^T (C M^-1 C^T)^-1 Phi
//   (COD of the dense C from constraintRow): equal to first order, so the difference of a
//   1e-6 perturbation's correction is O(1e-12) = 1e-6 of its size (tolerance 1e-4 relative);
// - projectAndEvaluate against project() then evaluate() (round-off) and both velocity
//   projections against the dense least change after a position projection;
// - singular matrices are reported, not solved.

#include "mechanics/index_one_dynamics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "language/reader.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::mechanics {

struct IndexOneDynamicsTestAccess {
  static void useRuntimeSizeKernels(IndexOneDynamics& d) { d.useRuntimeSizeKernels(); }
};

namespace {

using L = StateLayout;

model::Model buildText(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "index_one.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

model::Model buildFile(const std::string& path) {
  language::Dataset ds;
  Diagnostics d;
  EXPECT_TRUE(language::readDatasetFile(path, ds, d));
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  return m;
}

// A pendulum chain of revolute joints, links of length 0.1 along x (as the benchmark's):
// planar (axes along z) or spatial (axes alternate between z and y). `units` lets a chain be
// written in grams and millimetres (UCF != 1).
std::string chain(int links, bool spatial, bool grams = false, bool duplicateFirstJoint = false) {
  std::ostringstream s;
  const double len = grams ? 100.0 : 0.1;
  const double mass = grams ? 1000.0 : 1.0;
  const double inertia = grams ? 1e6 : 1e-3;
  s << "chain\n"
    << (grams ? "UNITS/FORCE=NEWTON, MASS=GRAM, LENGTH=MILLIMETER, TIME=SECOND\n"
              : "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n")
    << "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n";
  auto turned = [&](int i) { return spatial && i % 2 == 1; };
  for (int i = 0; i < links; ++i) {
    const int p = 100 + i;
    const double x0 = i * len, x1 = (i + 1) * len;
    s << "PART/" << p << ", MASS=" << mass * (1.0 + 0.01 * i) << ", CM=" << p * 10
      << ", IP=" << inertia << "," << 1.2 * inertia << "," << 0.9 * inertia << "\n"
      << "MARKER/" << p * 10 << ", PART=" << p << ", QP=" << x0 + 0.5 * len << ",0,0\n"
      << "MARKER/" << p * 10 + 1 << ", PART=" << p << ", QP=" << x0 << ",0,0"
      << (turned(i) ? ", REULER=0D,90D,0D" : "") << "\n"
      << "MARKER/" << p * 10 + 2 << ", PART=" << p << ", QP=" << x1 << ",0,0"
      << (turned(i + 1) ? ", REULER=0D,90D,0D" : "") << "\n"
      << "JOINT/" << i + 1 << ", REVOLUTE, I=" << p * 10 + 1
      << ", J=" << (i == 0 ? 10 : (p - 1) * 10 + 2) << "\n";
  }
  // The same hinge twice (same markers): five dependent rows when they are not removed.
  if (duplicateFirstJoint) s << "JOINT/9999, REVOLUTE, I=1001, J=10\n";
  s << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// Joints of several kinds, two MOTIONs, spring-dampers, an SFORCE and a VARIABLE that an
// SFORCE reads (the VARIABLE must be solved before the applied forces).
std::string mixedModel() {
  std::ostringstream s;
  s << "mixed\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
       "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\nMARKER/11, PART=1, QP=0,0,0\n";
  const char* joints[] = {"REVOLUTE",  "SPHERICAL", "TRANSLATIONAL", "CYLINDRICAL",
                          "UNIVERSAL", "REVOLUTE",  "PLANAR",        "TRANSLATIONAL"};
  for (int i = 0; i < 8; ++i) {
    const int p = i + 2;
    s << "PART/" << p << ", MASS=" << 1.0 + 0.1 * i << ", CM=" << 10 * p << ", IP=0.05,0.1,0.12\n"
      << "MARKER/" << 10 * p << ", PART=" << p << ", QP=" << i + 0.5 << ",0,0\n"
      << "MARKER/" << 10 * p + 1 << ", PART=" << p << ", QP=" << i << ",0,0"
      << (std::string(joints[i]) == "UNIVERSAL" ? ", REULER=0D,90D,0D" : "") << "\n"
      << "MARKER/" << 10 * p + 2 << ", PART=" << p << ", QP=" << i + 1 << ",0,0\n";
    s << "JOINT/" << p << ", " << joints[i] << ", I=" << 10 * p + 1
      << ", J=" << (i == 0 ? 10 : 10 * (p - 1) + 2) << "\n";
    if (i >= 2)
      s << "SPRINGDAMPER/" << p << ", TRANSLATIONAL, I=" << 10 * p << ", J=" << 10 * (p - 2)
        << ", K=50, C=0.5, LENGTH=2\n";
  }
  s << "MOTION/1, JOINT=2, FUNCTION=0.3*SIN(2*TIME)\n"
    << "MOTION/2, JOINT=9, FUNCTION=0.1*TIME\n"
    << "SFORCE/1, TRANSLATION, I=72, J=10, FUNCTION=-10*(DM(72,10)-3)-0.2*VR(72,10)\n"
    << "VARIABLE/1, FUNCTION=DX(52,10)*DY(52,10) + 0.5*VX(52,10)\n"
    << "SFORCE/2, ROTATION, I=91, J=82, FUNCTION=-3*VARVAL(1)\n"
    << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// A mass on a vertical translational joint with an added-mass force that reads its
// acceleration (tests/analysis/acceleration_reaction_functions_test.cpp).
std::string addedMassModel() {
  return "added mass\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,0.5\nMARKER/20, PART=2\n"
         "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
         "SFORCE/1, TRANSLATIONAL, ACTIONONLY, I=20, J=10, FUNCTION=-8*DZ(20,10) - 2*ACCZ(20)\n"
         "END\n";
}

// A consistent state with non-trivial velocities: assembled, then every body given an angular
// velocity and the velocities projected by the set-up solve.
struct Prepared {
  explicit Prepared(const model::Model& model, bool removeRedundant = true, double t0 = 0.3)
      : m(model), system(m), t(t0) {
    y = system.initialState();
    if (removeRedundant) removeRedundantConstraints(system, y);
    assemblePositions(system, t, y, 1e-12, 25);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int b = 0; b < system.layout().bodies; ++b)
      for (int c = 0; c < 3; ++c) y(system.layout().body(b) + L::kW + c) = u(rng);
    solveVelocities(system, t, y);
  }
  const model::Model& m;
  MultibodySystem system;
  double t;
  Eigen::VectorXd y;
};

// max |a - b| / max |b| over the body rates and the multipliers.
void expectSameDynamics(Prepared& run, double tolerance, bool runtimeSizes = false) {
  const StateLayout& l = run.system.layout();
  Eigen::VectorXd yRef = run.y, ypRef;
  ASSERT_TRUE(solveAccelerations(run.system, run.t, yRef, ypRef));
  IndexOneDynamics dynamics(run.system);
  if (runtimeSizes) IndexOneDynamicsTestAccess::useRuntimeSizeKernels(dynamics);
  Eigen::VectorXd y = run.y, yp;
  ASSERT_TRUE(dynamics.evaluate(run.t, y, yp));
  ASSERT_EQ(yp.size(), ypRef.size());
  const double rateScale = ypRef.cwiseAbs().maxCoeff();
  EXPECT_LE((yp - ypRef).cwiseAbs().maxCoeff(), tolerance * rateScale);
  const int nl = l.constraintEquations;
  if (nl > 0) {
    const Eigen::VectorXd lambda = y.segment(l.lambda(0), nl);
    const Eigen::VectorXd lambdaRef = yRef.segment(l.lambda(0), nl);
    EXPECT_LE((lambda - lambdaRef).cwiseAbs().maxCoeff(),
              tolerance * std::max(1e-300, lambdaRef.cwiseAbs().maxCoeff()));
  }
  // The rest of y as the reference leaves it (mu = 0, VARIABLE values solved).
  EXPECT_LE((y.head(l.lambda(0)) - yRef.head(l.lambda(0))).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(dynamics.factorizations(), 1);
}

TEST(IndexOneDynamics, MatchesTheKktSolveOnPlanarAndSpatialChains) {
  for (int links : {5, 50})
    for (bool spatial : {false, true}) {
      SCOPED_TRACE(std::to_string(links) + (spatial ? " spatial" : " planar"));
      const model::Model m = buildText(chain(links, spatial));
      Prepared run(m);
      expectSameDynamics(run, 1e-10);
    }
}

TEST(IndexOneDynamics, KernelsWithTheBlockSizeAtRunTimeAgree) {
  // The path blocks of more than 6 equations take, on models whose blocks have 1-6.
  for (const std::string& text : {chain(50, true), mixedModel()}) {
    const model::Model m = buildText(text);
    Prepared run(m);
    expectSameDynamics(run, 1e-10, true);
  }
}

TEST(IndexOneDynamics, ScalesTheMassMatrixByUcfAsTheResidualDoes) {
  // Grams and millimetres: masses are divided by UCF = 1e6 in the equations.
  const model::Model m = buildText(chain(6, true, true));
  Prepared run(m);
  expectSameDynamics(run, 1e-10);
}

TEST(IndexOneDynamics, MatchesOnThePistonAndTheFourBar) {
  for (const char* path : {"/examples/piston/piston.adm", "/examples/fourbar/fourbar.adm"}) {
    SCOPED_TRACE(path);
    const model::Model m = buildFile(std::string(OPENMSS_SOURCE_DIR) + path);
    Prepared run(m);
    expectSameDynamics(run, 1e-10);
  }
}

TEST(IndexOneDynamics, MatchesWithMotionsForcesAndAVariable) {
  const model::Model m = buildText(mixedModel());
  ASSERT_FALSE(readsAccelerationsOrReactions(m));
  Prepared run(m, true, 0.7);
  // The VARIABLE starts off its value: evaluate() must solve it before the forces.
  run.y(run.system.layout().userAlg(0)) = 123.0;
  expectSameDynamics(run, 1e-10);
}

TEST(IndexOneDynamics, FunctionsOfAccelerationsTakeTheCoupledSolve) {
  const model::Model m = buildText(addedMassModel());
  ASSERT_TRUE(readsAccelerationsOrReactions(m));
  Prepared run(m);
  expectSameDynamics(run, 1e-12);
  // (m + ma) z'' = -k z: z'' = -8 * 0.5 / 4 = -1.
  IndexOneDynamics dynamics(run.system);
  Eigen::VectorXd y = run.y, yp;
  ASSERT_TRUE(dynamics.evaluate(run.t, y, yp));
  EXPECT_NEAR(yp(L::kV + 2), -1.0, 1e-10);
}

TEST(IndexOneDynamics, NormalisesEulerParameters) {
  const model::Model m = buildText(chain(5, true));
  Prepared run(m);
  Eigen::VectorXd y = run.y, yp;
  const StateLayout& l = run.system.layout();
  for (int b = 0; b < l.bodies; ++b) y.segment<4>(l.body(b) + L::kE) *= 1.001;
  IndexOneDynamics dynamics(run.system);
  ASSERT_TRUE(dynamics.evaluate(run.t, y, yp));
  for (int b = 0; b < l.bodies; ++b)
    EXPECT_NEAR(y.segment<4>(l.body(b) + L::kE).norm(), 1.0, 1e-15);
  expectSameDynamics(run, 1e-10);
}

TEST(IndexOneDynamics, DependentRowsAreDroppedAsTheRedundancyAnalysisDrops) {
  // A hinge given twice (its redundant rows not removed): C has dependent rows and S is
  // singular. The factorisation drops the dependent rows (docs/theory.md §9d, "Singular S"),
  // so the accelerations equal those of the same model with the redundant equations removed
  // by the set-up analysis (before issue 20 evaluate() failed here).
  const model::Model m = buildText(chain(5, false, false, true));
  Prepared run(m, false);
  IndexOneDynamics dynamics(run.system);
  Eigen::VectorXd y = run.y, yp;
  ASSERT_TRUE(dynamics.evaluate(run.t, y, yp));
  Prepared fixed(m, true);
  expectSameDynamics(fixed, 1e-10);
  IndexOneDynamics reduced(fixed.system);
  Eigen::VectorXd yFixed = fixed.y, ypFixed;
  ASSERT_TRUE(reduced.evaluate(fixed.t, yFixed, ypFixed));
  const StateLayout& l = run.system.layout();
  ASSERT_GT(l.bodies, 0);
  for (int b = 0; b < l.bodies; ++b) {
    // The same state (both prepared from the same data set; round-off of their assembly)...
    const int o = l.body(b);
    EXPECT_LT((y.segment<13>(o) - yFixed.segment<13>(o)).cwiseAbs().maxCoeff(), 1e-12) << b;
    // ... and the same accelerations, to 1e-9 of values of the size of g (round-off of S).
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(yp(o + L::kV + i), ypFixed(o + L::kV + i), 1e-9) << b << " " << i;
  }
}

// The change of every body (translation, body-axes rotation vector) from y0 to y.
Eigen::VectorXd bodyChange(const StateLayout& l, const Eigen::VectorXd& y0,
                           const Eigen::VectorXd& y) {
  Eigen::VectorXd d(6 * l.bodies);
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    d.segment<3>(6 * b) = y.segment<3>(o + L::kR) - y0.segment<3>(o + L::kR);
    const Eigen::Quaterniond e0(y0(o + L::kE), y0(o + L::kE + 1), y0(o + L::kE + 2),
                                y0(o + L::kE + 3));
    const Eigen::Quaterniond e1(y(o + L::kE), y(o + L::kE + 1), y(o + L::kE + 2), y(o + L::kE + 3));
    const Eigen::AngleAxisd turn(e0.conjugate() * e1);
    d.segment<3>(6 * b + 3) = turn.angle() * turn.axis();
  }
  return d;
}

// Perturbs every body's position and orientation by about `size` and its velocities by 0.1.
void perturb(const StateLayout& l, double size, unsigned seed, Eigen::VectorXd& y) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd delta(6 * l.bodies);
  for (Eigen::Index i = 0; i < delta.size(); ++i) delta(i) = size * u(rng);
  applyBodyCorrection(l, delta, y);
  for (int b = 0; b < l.bodies; ++b)
    for (int c = 0; c < 3; ++c) {
      y(l.body(b) + L::kV + c) += 0.1 * u(rng);
      y(l.body(b) + L::kW + c) += 0.1 * u(rng);
    }
}

TEST(IndexOneDynamics, ProjectionReachesBothManifolds) {
  for (const std::string& text : {chain(50, true), chain(50, false), mixedModel()}) {
    const model::Model m = buildText(text);
    Prepared run(m);
    const StateLayout& l = run.system.layout();
    IndexOneDynamics dynamics(run.system);
    Eigen::VectorXd y = run.y, yp;
    perturb(l, 1e-3, 11, y);
    ASSERT_GT(dynamics.positionViolation(run.t, y), 1e-5);
    ASSERT_TRUE(dynamics.project(run.t, y, 1e-10));
    EXPECT_LE(dynamics.positionViolation(run.t, y), 1e-10);
    EXPECT_LE(dynamics.velocityViolation(run.t, y), 1e-12);
    for (int b = 0; b < l.bodies; ++b)
      EXPECT_NEAR(y.segment<4>(l.body(b) + L::kE).norm(), 1.0, 1e-14);
    // A projection that has nothing to do costs no factorisation and changes nothing.
    const long before = dynamics.factorizations();
    const Eigen::VectorXd settled = y;
    ASSERT_TRUE(dynamics.project(run.t, y, 1e-10));
    EXPECT_LE((y - settled).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LE(dynamics.factorizations() - before, 1);
  }
}

TEST(IndexOneDynamics, ProjectionIsTheMassWeightedLeastChange) {
  for (const std::string& text : {chain(5, true), mixedModel()}) {
    const model::Model m = buildText(text);
    Prepared run(m);
    const StateLayout& l = run.system.layout();
    Eigen::VectorXd y = run.y;
    perturb(l, 1e-6, 3, y);
    // Dense reference at the perturbed state: delta = -M^-1 C^T (C M^-1 C^T)^-1 Phi.
    std::vector<int> rows;
    const Eigen::MatrixXd c = activeConstraintJacobian(run.system, y.data(), &rows);
    Eigen::VectorXd phi(static_cast<Eigen::Index>(rows.size()));
    for (size_t r = 0; r < rows.size(); ++r)
      phi(static_cast<Eigen::Index>(r)) = run.system.constraintValue(rows[r], run.t, y.data());
    Eigen::MatrixXd mass;
    run.system.massMatrix(mass);
    const Eigen::MatrixXd minvCt = mass.ldlt().solve(c.transpose());
    const Eigen::VectorXd expected =
        -minvCt * (c * minvCt).completeOrthogonalDecomposition().solve(phi);
    const Eigen::VectorXd y0 = y;
    for (bool fused : {false, true}) {
      SCOPED_TRACE(fused ? "projectAndEvaluate" : "project");
      IndexOneDynamics dynamics(run.system);
      Eigen::VectorXd moved = y0, yp;
      if (fused) {
        bool projected = false;
        ASSERT_TRUE(dynamics.projectAndEvaluate(run.t, moved, yp, 1e-14, &projected));
        EXPECT_TRUE(projected);
      } else {
        ASSERT_TRUE(dynamics.project(run.t, moved, 1e-14));
      }
      const Eigen::VectorXd change = bodyChange(l, y0, moved);
      ASSERT_GT(expected.cwiseAbs().maxCoeff(), 1e-8);
      EXPECT_LE((change - expected).cwiseAbs().maxCoeff(), 1e-4 * expected.cwiseAbs().maxCoeff());
    }
  }
}

TEST(IndexOneDynamics, VelocityProjectionIsTheMassWeightedLeastChange) {
  const model::Model m = buildText(mixedModel());
  Prepared run(m);
  const StateLayout& l = run.system.layout();
  Eigen::VectorXd y = run.y;
  perturb(l, 0.0, 5, y);  // velocities only
  std::vector<int> rows;
  const Eigen::MatrixXd c = activeConstraintJacobian(run.system, y.data(), &rows);
  Eigen::VectorXd u(6 * l.bodies), nu(static_cast<Eigen::Index>(rows.size()));
  for (int b = 0; b < l.bodies; ++b) {
    u.segment<3>(6 * b) = y.segment<3>(l.body(b) + L::kV);
    u.segment<3>(6 * b + 3) = y.segment<3>(l.body(b) + L::kW);
  }
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& eq = run.system.constraints().equations()[static_cast<size_t>(rows[r])];
    nu(static_cast<Eigen::Index>(r)) =
        eq.motion >= 0 ? run.system.motionJet(rows[r], run.t).d1 : 0.0;
  }
  Eigen::MatrixXd mass;
  run.system.massMatrix(mass);
  const Eigen::MatrixXd minvCt = mass.ldlt().solve(c.transpose());
  const Eigen::VectorXd expected =
      u - minvCt * (c * minvCt).completeOrthogonalDecomposition().solve(c * u - nu);
  for (bool fused : {false, true}) {
    SCOPED_TRACE(fused ? "projectAndEvaluate" : "project");
    IndexOneDynamics dynamics(run.system);
    Eigen::VectorXd moved = y, yp;
    if (fused) {
      ASSERT_TRUE(dynamics.projectAndEvaluate(run.t, moved, yp, 1e-10));
    } else {
      ASSERT_TRUE(dynamics.project(run.t, moved, 1e-10));
    }
    for (int b = 0; b < l.bodies; ++b) {
      EXPECT_LE(
          (moved.segment<3>(l.body(b) + L::kV) - expected.segment<3>(6 * b)).cwiseAbs().maxCoeff(),
          1e-12);
      EXPECT_LE((moved.segment<3>(l.body(b) + L::kW) - expected.segment<3>(6 * b + 3))
                    .cwiseAbs()
                    .maxCoeff(),
                1e-12);
    }
  }
}

// max |a - b| over [from, from + count) relative to max |b| there (1 when b is zero).
double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::Index from,
                          Eigen::Index count) {
  const double scale = std::max(1.0, b.segment(from, count).cwiseAbs().maxCoeff());
  return (a.segment(from, count) - b.segment(from, count)).cwiseAbs().maxCoeff() / scale;
}

// projectAndEvaluate against project() then evaluate() on a second instance with the same
// history (one evaluation at the consistent state, whose factorisation both position
// projections start from, as after an integrator's last stage). The positions take the same
// iteration; both velocity projections solve with S at the projected positions, and the
// accelerations use the same C and S (formed twice by the separate calls, once here) with
// gamma at the same velocities: everything agrees to round-off, which cond(S) <= 1e4 on these
// models amplifies to ~1e-12 at most (seen: 4.7e-15 on y').
// Returns the largest relative difference of y' (the accelerations) seen.
double expectFusedEqualsProjectThenEvaluate(Prepared& run, double positionShift, double tolerance,
                                            bool expectProjected) {
  const StateLayout& l = run.system.layout();
  IndexOneDynamics separate(run.system), fused(run.system);
  Eigen::VectorXd y = run.y, ypSeparate, ypFused;
  EXPECT_TRUE(separate.evaluate(run.t, y, ypSeparate));
  y = run.y;
  EXPECT_TRUE(fused.evaluate(run.t, y, ypFused));
  perturb(l, positionShift, 17, y);
  Eigen::VectorXd ySeparate = y, yFused = y;
  const long separateBefore = separate.factorizations(), fusedBefore = fused.factorizations();
  EXPECT_EQ(separate.project(run.t, ySeparate, tolerance), expectProjected);
  EXPECT_TRUE(separate.evaluate(run.t, ySeparate, ypSeparate));
  bool projected = !expectProjected;
  EXPECT_TRUE(fused.projectAndEvaluate(run.t, yFused, ypFused, tolerance, &projected));
  EXPECT_EQ(projected, expectProjected);
  // Both velocity projections against the dense least change at the projected positions:
  // u - M^-1 C^T (C M^-1 C^T)^-1 (C u - nu), u the perturbed velocities (COD of the dense
  // matrices: another method). Round-off of these solves is ~1e-16 times cond(S) <= 1e4.
  {
    std::vector<int> rows;
    const Eigen::MatrixXd c = activeConstraintJacobian(run.system, yFused.data(), &rows);
    Eigen::VectorXd u(6 * l.bodies), nu(static_cast<Eigen::Index>(rows.size()));
    for (int b = 0; b < l.bodies; ++b) {
      u.segment<3>(6 * b) = y.segment<3>(l.body(b) + L::kV);
      u.segment<3>(6 * b + 3) = y.segment<3>(l.body(b) + L::kW);
    }
    for (size_t r = 0; r < rows.size(); ++r) {
      const auto& eq = run.system.constraints().equations()[static_cast<size_t>(rows[r])];
      nu(static_cast<Eigen::Index>(r)) =
          eq.motion >= 0 ? run.system.motionJet(rows[r], run.t).d1 : 0.0;
    }
    Eigen::MatrixXd mass;
    run.system.massMatrix(mass);
    const Eigen::MatrixXd minvCt = mass.ldlt().solve(c.transpose());
    const Eigen::VectorXd expected =
        u - minvCt * (c * minvCt).completeOrthogonalDecomposition().solve(c * u - nu);
    Eigen::VectorXd uSeparate(6 * l.bodies), uFused(6 * l.bodies);
    for (int b = 0; b < l.bodies; ++b) {
      uSeparate.segment<6>(6 * b) = ySeparate.segment<6>(l.body(b) + L::kV);
      uFused.segment<6>(6 * b) = yFused.segment<6>(l.body(b) + L::kV);
    }
    const double size = std::max(1.0, expected.cwiseAbs().maxCoeff());
    if (expectProjected) {
      EXPECT_LE((uSeparate - expected).cwiseAbs().maxCoeff(), 1e-10 * size);
      EXPECT_LE((uFused - expected).cwiseAbs().maxCoeff(), 1e-10 * size);
    }
  }
  // Positions: the same operations (Euler parameters normalised once more by both).
  const Eigen::Index positions = StateLayout::kV;
  double worstPosition = 0.0, worstVelocity = 0.0;
  for (int b = 0; b < l.bodies; ++b) {
    worstPosition =
        std::max(worstPosition, relativeDifference(yFused, ySeparate, l.body(b), positions));
    worstVelocity = std::max(worstVelocity,
                             relativeDifference(yFused, ySeparate, l.body(b) + StateLayout::kV, 6));
  }
  EXPECT_LE(worstPosition, 1e-14);
  EXPECT_LE(worstVelocity, 1e-12);
  const double accelerations = relativeDifference(ypFused, ypSeparate, 0, ypSeparate.size());
  EXPECT_LE(accelerations, 1e-12);
  if (l.constraintEquations > 0) {
    EXPECT_LE(relativeDifference(yFused, ySeparate, l.lambda(0), l.constraintEquations), 1e-12);
  }
  if (l.userAlgebraic > 0) {
    EXPECT_LE(relativeDifference(yFused, ySeparate, l.userAlg(0), l.userAlgebraic), 1e-12);
  }
  // One factorisation serves the velocities and the accelerations.
  if (expectProjected && !readsAccelerationsOrReactions(run.m)) {
    EXPECT_EQ(fused.factorizations() - fusedBefore, 1);
  }
  EXPECT_GE(separate.factorizations() - separateBefore, fused.factorizations() - fusedBefore);
  return accelerations;
}

TEST(IndexOneDynamics, ProjectAndEvaluateEqualsProjectThenEvaluate) {
  double worst = 0.0;
  for (const std::string& text : {chain(50, true), chain(50, false), mixedModel()}) {
    const model::Model m = buildText(text);
    Prepared run(m);
    for (double shift : {0.0, 1e-7, 1e-4}) {
      SCOPED_TRACE(text.substr(0, 40) + " shift " + std::to_string(shift));
      worst = std::max(worst, expectFusedEqualsProjectThenEvaluate(run, shift, 1e-11, true));
    }
  }
  std::ostringstream s;
  s << std::scientific << worst;
  RecordProperty("largest_acceleration_difference", s.str());
}

TEST(IndexOneDynamics, ProjectAndEvaluateFallsBackAsProjectThenEvaluate) {
  // Functions of accelerations (no Schur complement to share): the two calls themselves.
  {
    const model::Model m = buildText(addedMassModel());
    Prepared run(m);
    expectFusedEqualsProjectThenEvaluate(run, 1e-4, 1e-11, true);
  }
  // Positions that cannot reach the tolerance (0: not even round-off does): evaluated where the
  // iteration stopped, and reported not projected.
  {
    const model::Model m = buildText(chain(5, true));
    Prepared run(m);
    expectFusedEqualsProjectThenEvaluate(run, 1e-4, 0.0, false);
  }
}

// Kinetic plus potential energy of the bodies (SI units: UCF = 1).
double energy(const MultibodySystem& system, const Eigen::VectorXd& y) {
  const StateLayout& l = system.layout();
  const Eigen::Vector3d gravity = system.model().gravity;
  double e = 0.0;
  for (int b = 0; b < l.bodies; ++b) {
    const int o = l.body(b);
    const Eigen::Vector3d v = y.segment<3>(o + L::kV), w = y.segment<3>(o + L::kW);
    e += 0.5 * system.bodyMass(b) * v.squaredNorm() + 0.5 * w.dot(system.bodyInertia(b) * w) -
         system.bodyMass(b) * gravity.dot(y.segment<3>(o + L::kR));
  }
  return e;
}

// A conservative spatial chain (gravity, no damping) integrated by fixed-step RK4 on
// evaluate() with a projection after every step: energy is conserved up to the method's
// O(h^4) error. h = 1e-3 over 0.5 s; the drift is measured against m g L of the chain.
// `fused`: the projection and the next first stage by projectAndEvaluate.
void expectRungeKuttaConservesEnergy(bool fused) {
  const model::Model m = buildText(chain(5, true));
  Prepared run(m, true, 0.0);
  IndexOneDynamics dynamics(run.system);
  const StateLayout& l = run.system.layout();
  Eigen::VectorXd y = run.y, yp, k1, k2, k3, k4, stage;
  ASSERT_TRUE(dynamics.project(0.0, y, 1e-13));
  const double e0 = energy(run.system, y);
  const double h = 1e-3;
  const int bodyEntries = l.userStates();
  auto step = [&](const Eigen::VectorXd& from, const Eigen::VectorXd& rate, double a) {
    stage = from;
    stage.head(bodyEntries) += a * h * rate.head(bodyEntries);
  };
  double t = 0.0, worst = 0.0;
  if (fused) {
    stage = y;
    ASSERT_TRUE(dynamics.evaluate(t, stage, k1));
  }
  for (int n = 0; n < 500; ++n) {
    if (!fused) {
      stage = y;
      ASSERT_TRUE(dynamics.evaluate(t, stage, k1));
    }
    step(y, k1, 0.5);
    ASSERT_TRUE(dynamics.evaluate(t + 0.5 * h, stage, k2));
    step(y, k2, 0.5);
    ASSERT_TRUE(dynamics.evaluate(t + 0.5 * h, stage, k3));
    step(y, k3, 1.0);
    ASSERT_TRUE(dynamics.evaluate(t + h, stage, k4));
    y.head(bodyEntries) += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4).head(bodyEntries);
    t += h;
    if (fused) {
      bool projected = false;
      ASSERT_TRUE(dynamics.projectAndEvaluate(t, y, k1, 1e-12, &projected));
      ASSERT_TRUE(projected);
    } else {
      ASSERT_TRUE(dynamics.project(t, y, 1e-12));
    }
    worst = std::max(worst, std::abs(energy(run.system, y) - e0));
  }
  const double scale = 5.0 * 9.80665 * 0.5;  // m g L: 5 links of ~1 kg, 0.5 m long
  std::ostringstream drift;
  drift << std::scientific << worst / scale;
  ::testing::Test::RecordProperty(fused ? "relative_energy_drift_fused" : "relative_energy_drift",
                                  drift.str());
  EXPECT_LE(worst, 1e-8 * scale);
  // It moved: the chain fell from the horizontal.
  EXPECT_LT(y(l.body(4) + L::kR + 1), -0.01);
}

TEST(IndexOneDynamics, ClassicalRungeKuttaConservesTheChainsEnergy) {
  expectRungeKuttaConservesEnergy(false);
}

TEST(IndexOneDynamics, ClassicalRungeKuttaWithProjectAndEvaluateConservesTheChainsEnergy) {
  expectRungeKuttaConservesEnergy(true);
}

}  // namespace
}  // namespace openmss::mechanics
