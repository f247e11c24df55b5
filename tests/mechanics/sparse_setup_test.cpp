// The sparse set-up solves (docs/theory.md §7) against the dense ones they replace for large
// models: the sparse rows of C against the dense rows (bit for bit: one code path), the
// redundant equations and rank from the sparse QR against the dense Gram-Schmidt (door hinge,
// four-bar, the validation models, every corpus model that builds, a chain with redundant
// loops), and positions, velocities, accelerations and multipliers from the saddle-point
// solves against the dense QR / COD / full-pivot LU (piston, four-bar, validation models,
// generated chains). Tolerances: both sides solve the same well-conditioned linear problems
// in double precision, so they agree to a few hundred ulps of the largest entry; 1e-9
// relative leaves room for the condition numbers (<= 1e5) of these models.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "mechanics/saddle_point_solver.hpp"
#include "mechanics/sparse_constraint_jacobian.hpp"
#include "model/model_builder.hpp"
#include "support/validation_data.hpp"

namespace openmss::mechanics {
namespace {

namespace fs = std::filesystem;
using L = StateLayout;

const fs::path kJoints = openmss::testing::adamsJointsDir();
const fs::path kCorpus = openmss::testing::corpusDir();

// Reads and builds a data set; false when it has errors (corpus models may use statements
// the solver does not support yet).
bool buildFile(const fs::path& path, model::Model& m) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetFile(path.string(), ds, d);
  return model::buildModel(ds, m, d) && !d.hasErrors();
}

model::Model buildText(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "generated.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// An N-link pendulum chain of revolute joints, links of length 0.1 along ground x. Planar:
// every axis along z. Spatial: the axes alternate between z and y, so the chain swings out of
// its plane. `redundantHinges`: every fourth joint gets a coaxial twin 0.05 further along its
// axis (five redundant equations each, as the door's second hinge).
std::string chain(int links, bool spatial, bool redundantHinges = false) {
  std::ostringstream s;
  s << (spatial ? "spatial" : "planar") << " chain\n"
    << "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
    << "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n";
  const double len = 0.1;
  auto turned = [&](int i) { return spatial && i % 2 == 1; };  // axis of joint i along y
  for (int i = 0; i < links; ++i) {
    const int p = 100 + i;
    const double x0 = i * len, x1 = (i + 1) * len;
    s << "PART/" << p << ", MASS=1, CM=" << p * 10 << ", IP=0.001,0.0012,0.0009\n"
      << "MARKER/" << p * 10 << ", PART=" << p << ", QP=" << x0 + 0.5 * len << ",0,0\n"
      << "MARKER/" << p * 10 + 1 << ", PART=" << p << ", QP=" << x0 << ",0,0"
      << (turned(i) ? ", REULER=0D,90D,0D" : "") << "\n"
      << "MARKER/" << p * 10 + 2 << ", PART=" << p << ", QP=" << x1 << ",0,0"
      << (turned(i + 1) ? ", REULER=0D,90D,0D" : "") << "\n"
      << "JOINT/" << i + 1 << ", REVOLUTE, I=" << p * 10 + 1
      << ", J=" << (i == 0 ? 10 : (p - 1) * 10 + 2) << "\n";
    if (redundantHinges && i % 4 == 3) {
      // A second hinge on the same axis, 0.05 further along it: five redundant equations.
      const char* onAxis = turned(i) ? ",0.05,0, REULER=0D,90D,0D" : ",0,0.05";
      s << "MARKER/" << p * 10 + 3 << ", PART=" << p << ", QP=" << x0 << onAxis << "\n"
        << "MARKER/" << (p - 1) * 10 + 4 << ", PART=" << p - 1 << ", QP=" << x0 << onAxis
        << "\n"
        << "JOINT/" << 1000 + i << ", REVOLUTE, I=" << p * 10 + 3 << ", J=" << (p - 1) * 10 + 4
        << "\n";
    }
  }
  s << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// A state near the data set's one: positions perturbed (so that the assembly has work to do),
// velocities set.
Eigen::VectorXd perturbed(const MultibodySystem& s) {
  Eigen::VectorXd y = s.initialState();
  for (int b = 0; b < s.layout().bodies; ++b) {
    const int o = s.layout().body(b);
    for (int c = 0; c < 3; ++c) y(o + L::kR + c) += 1e-3 * std::sin(1.3 * b + c);
    Eigen::Vector4d e = y.segment<4>(o + L::kE);
    for (int c = 0; c < 4; ++c) e(c) += 2e-3 * std::cos(0.7 * b + c);
    y.segment<4>(o + L::kE) = e.normalized();
    for (int c = 0; c < 3; ++c) {
      y(o + L::kV + c) = 0.3 * std::sin(b + 2.0 * c);
      y(o + L::kW + c) = 0.5 * std::cos(b - c);
    }
  }
  return y;
}

double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

// Both paths on one model: the same removed equations, then positions (from a perturbed
// state), velocities and accelerations with multipliers agree.
void expectSameResults(const model::Model& m, const std::string& name) {
  MultibodySystem dense(m), sparse(m);
  // Redundancy at the data set's configuration (as the session finds it), then the assembly
  // from a perturbed state.
  const RedundancyReport rd =
      removeRedundantConstraints(dense, dense.initialState(), LinearAlgebra::Dense);
  const RedundancyReport rs =
      removeRedundantConstraints(sparse, sparse.initialState(), LinearAlgebra::Sparse);
  const Eigen::VectorXd y0 = perturbed(dense);
  EXPECT_EQ(rd.rank, rs.rank) << name;
  EXPECT_EQ(rd.removed, rs.removed) << name;
  Eigen::VectorXd yd = y0, ys = y0, ypd, yps;
  AssemblyOptions o;
  o.tolerance = 1e-12;
  o.linearAlgebra = LinearAlgebra::Dense;
  const AssemblyResult ad = assemblePositions(dense, 0.0, yd, o);
  o.linearAlgebra = LinearAlgebra::Sparse;
  const AssemblyResult as = assemblePositions(sparse, 0.0, ys, o);
  EXPECT_EQ(ad.converged, as.converged) << name;
  EXPECT_EQ(ad.iterations, as.iterations) << name;
  EXPECT_LT(relativeDifference(ys, yd), 1e-9) << name;
  solveVelocities(dense, 0.0, yd, true, LinearAlgebra::Dense);
  solveVelocities(sparse, 0.0, ys, true, LinearAlgebra::Sparse);
  EXPECT_LT(relativeDifference(ys, yd), 1e-9) << name;
  const bool okd = solveAccelerations(dense, 0.0, yd, ypd, LinearAlgebra::Dense);
  const bool oks = solveAccelerations(sparse, 0.0, ys, yps, LinearAlgebra::Sparse);
  ASSERT_EQ(okd, oks) << name;
  if (!okd) return;
  EXPECT_LT(relativeDifference(yps, ypd), 1e-9) << name << " accelerations";
  EXPECT_LT(relativeDifference(ys, yd), 1e-9) << name << " multipliers";
}

TEST(SparseSetup, RowEntriesAreTheDenseRow) {
  for (const std::string& text : {chain(7, true, true), chain(5, false)}) {
    const model::Model m = buildText(text);
    const MultibodySystem s(m);
    const Eigen::VectorXd y = perturbed(s);
    const int n = 6 * s.layout().bodies;
    std::vector<double> row(n), scattered(n);
    std::vector<int> cols;
    std::vector<double> vals;
    for (int k = 0; k < s.constraints().size(); ++k) {
      s.constraintRow(k, y.data(), row.data());
      s.constraintRowEntries(k, y.data(), cols, vals);
      const int markers = s.constraints().equations()[k].markerCount();
      EXPECT_LE(static_cast<int>(cols.size()), 6 * markers);
      std::fill(scattered.begin(), scattered.end(), 0.0);
      for (size_t i = 0; i < cols.size(); ++i) {
        if (i > 0) {
          EXPECT_LT(cols[i - 1], cols[i]);
        }
        scattered[cols[i]] = vals[i];
      }
      EXPECT_EQ(scattered, row) << k;
    }
  }
}

TEST(SparseSetup, DoorHingeRankAndRemovedEquationsAgree) {
  const model::Model m = buildText(
      "door\nPART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0.5\nMARKER/11, PART=1, QP=0,0,1.5\n"
      "PART/2, MASS=10, CM=20, IP=1,2,3\nMARKER/20, PART=2, QP=0.5,0,1\n"
      "MARKER/21, PART=2, QP=0,0,0.5\nMARKER/22, PART=2, QP=0,0,1.5\n"
      "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=22, J=11\nACCGRAV/KGRAV=-9.81\nEND\n");
  MultibodySystem s(m);
  const RedundancyReport r = removeRedundantConstraints(s, s.initialState(), LinearAlgebra::Sparse);
  EXPECT_EQ(6 - r.rank, 1);
  EXPECT_EQ(r.removed, (std::vector<int>{5, 6, 7, 8, 9}));  // JOINT/2, all five
  expectSameResults(m, "door");
}

TEST(SparseSetup, ExamplesAgreeWithTheDensePath) {
  for (const char* file : {"/examples/piston/piston.adm", "/examples/fourbar/fourbar.adm"}) {
    model::Model m;
    ASSERT_TRUE(buildFile(fs::path(OPENMSS_SOURCE_DIR + std::string(file)), m)) << file;
    expectSameResults(m, file);
  }
}

TEST(SparseSetup, ValidationModelsKeepTheirDegreesOfFreedom) {
  const std::pair<const char*, int> expected[] = {
      {"Revolute_Case01", 1},  {"Revolute_Case02", 1},  {"Spherical_Case01", 3},
      {"Spherical_Case02", 3}, {"Universal_Case01", 2}, {"Universal_Case02", 2},
      {"Prismatic_Case01", 1}, {"Prismatic_Case02", 1}, {"Cylindrical_Case01", 2}};
  for (const auto& [name, dof] : expected) {
    model::Model m;
    ASSERT_TRUE(buildFile(kJoints / name / ("test_" + std::string(name) + ".adm"), m)) << name;
    MultibodySystem s(m);
    const RedundancyReport r =
        removeRedundantConstraints(s, s.initialState(), LinearAlgebra::Sparse);
    EXPECT_EQ(6 * m.bodyCount() - r.rank, dof) << name;
    expectSameResults(m, name);
  }
}

TEST(SparseSetup, CorpusRanksAgree) {
  if (!fs::exists(kCorpus)) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    if (entry.path().extension() != ".adm") continue;
    // A corpus model with statements not supported yet (RESULTS, GRAPHICS, ...) still builds
    // its parts and joints: its rank is compared whenever the builder produced a model.
    language::Dataset ds;
    Diagnostics d;
    language::readDatasetFile(entry.path().string(), ds, d);
    model::Model m;
    if (!model::buildModel(ds, m, d)) continue;
    MultibodySystem dense(m), sparse(m);
    const Eigen::VectorXd y = dense.initialState();
    const RedundancyReport rd = removeRedundantConstraints(dense, y, LinearAlgebra::Dense);
    const RedundancyReport rs = removeRedundantConstraints(sparse, y, LinearAlgebra::Sparse);
    EXPECT_EQ(rd.rank, rs.rank) << entry.path();
    EXPECT_EQ(rd.removed, rs.removed) << entry.path();
    ++compared;
  }
  std::printf("corpus models compared: %d\n", compared);
  // 10 corpus models built when this floor was set (issue 23): fewer means the comparison
  // silently lost models (a reader or builder regression), not that they agree.
  EXPECT_GE(compared, 10);
}

TEST(SparseSetup, GeneratedChainsAgreeWithTheDensePath) {
  expectSameResults(buildText(chain(40, false)), "planar 40");
  expectSameResults(buildText(chain(40, true)), "spatial 40");
  // Ten redundant hinges: 50 equations removed, the same ones both ways.
  const model::Model m = buildText(chain(40, true, true));
  MultibodySystem s(m);
  const RedundancyReport r = removeRedundantConstraints(s, s.initialState(), LinearAlgebra::Sparse);
  EXPECT_EQ(r.removed.size(), 50u);
  EXPECT_EQ(6 * m.bodyCount() - r.rank, 40);
  expectSameResults(m, "spatial 40 with redundant hinges");
}

TEST(SparseSetup, AccelerationAnalysisIsReusedWhileThePatternHolds) {
  // Two coordinates of mass 2 tied by one equation: H = diag(2, 2), C = [1 1].
  SaddlePointSolver solver;
  SaddlePointSolver::SparseMatrix h(2, 2), c(1, 2);
  h.insert(0, 0) = 2.0;
  h.insert(1, 1) = 2.0;
  c.insert(0, 0) = 1.0;
  c.insert(0, 1) = 1.0;
  Eigen::VectorXd x, z;
  ASSERT_TRUE(solver.factor(h, c));
  // 2 x0 + z = 1, 2 x1 + z = 0, x0 + x1 = 0: x0 = 1/4, x1 = -1/4, z = 1/2.
  ASSERT_TRUE(solver.solve(Eigen::Vector2d(1.0, 0.0), Eigen::VectorXd::Zero(1), x, z));
  EXPECT_NEAR(x(0), 0.25, 1e-15);
  EXPECT_NEAR(x(1), -0.25, 1e-15);
  EXPECT_NEAR(z(0), 0.5, 1e-15);
  c.coeffRef(0, 1) = 3.0;  // new values, same pattern: no new analysis
  ASSERT_TRUE(solver.factor(h, c));
  EXPECT_EQ(solver.symbolicAnalyses(), 1);
  // A singular matrix (no mass, no constraint on the second coordinate) is reported.
  SaddlePointSolver::SparseMatrix h0(2, 2), c0(1, 2);
  h0.insert(0, 0) = 1.0;
  c0.insert(0, 0) = 1.0;
  EXPECT_FALSE(solver.factor(h0, c0) && solver.solve(Eigen::Vector2d(1.0, 1.0),
                                                      Eigen::VectorXd::Zero(1), x, z));
  EXPECT_EQ(solver.symbolicAnalyses(), 2);
}

}  // namespace
}  // namespace openmss::mechanics
