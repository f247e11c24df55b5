// The equations of motion against finite differences: the Newton matrix from forward-mode AD,
// the constraint Jacobian rows (virtual displacements) and the constraint rates.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/newton_matrix_check.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;
Eigen::VectorXd randomState(const MultibodySystem& s, std::mt19937& rng) {
  return testing::randomState(s, rng, testing::RandomMu::Yes);
}


// The bundled piston compressor: revolute, spherical, universal and translational joints, a
// motion and two SFORCEs whose functions read DM and VR.
model::Model pistonModel() {
  language::Dataset ds;
  Diagnostics d;
  EXPECT_TRUE(language::readDatasetFile(OPENMSS_SOURCE_DIR "/examples/piston/piston.adm", ds, d));
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// A state away from any special configuration: the data set's pose perturbed, random
TEST(MultibodySystem, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = pistonModel();
  const MultibodySystem s(m);
  std::mt19937 rng(7);
  const int n = s.layout().size();
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd y = randomState(s, rng);
    Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
    testing::checkNewtonMatrix(s, 0.123, y, yp, 37.0, "trial " + std::to_string(trial));
  }
}

TEST(MultibodySystem, ConstraintRowsAreVirtualDisplacementDerivatives) {
  const model::Model m = pistonModel();
  const MultibodySystem s(m);
  std::mt19937 rng(11);
  const Eigen::VectorXd y = randomState(s, rng);
  const int nb = s.layout().bodies;
  std::vector<double> row(6 * nb);
  for (int k = 0; k < s.constraints().size(); ++k) {
    s.constraintRow(k, y.data(), row.data());
    for (int b = 0; b < nb; ++b) {
      for (int dir = 0; dir < 6; ++dir) {
        // Displace body b by +-h along dir: a ground-axes translation or a body-axes rotation.
        auto displaced = [&](double h) {
          Eigen::VectorXd z = y;
          const int o = s.layout().body(b);
          if (dir < 3) {
            z(o + L::kR + dir) += h;
          } else {
            const Eigen::Vector4d e = z.segment<4>(o + L::kE);
            Eigen::Vector3d axis = Eigen::Vector3d::Zero();
            axis(dir - 3) = 1.0;
            const Eigen::Quaterniond q(e(0), e(1), e(2), e(3));
            const Eigen::Quaterniond r(Eigen::AngleAxisd(h, axis));
            const Eigen::Quaterniond qr = q * r;
            z.segment<4>(o + L::kE) << qr.w(), qr.x(), qr.y(), qr.z();
          }
          return s.constraintValue(k, 0.3, z.data());
        };
        const double h = 1e-6;
        const double fd = (displaced(h) - displaced(-h)) / (2 * h);
        EXPECT_NEAR(row[6 * b + dir], fd, 1e-7 * (1.0 + std::abs(fd)))
            << s.constraints().describe(k, m) << " body " << b << " direction " << dir;
      }
    }
  }
}

TEST(MultibodySystem, ConstraintRatesMatchDifferencesAlongTheMotion) {
  const model::Model m = pistonModel();
  const MultibodySystem s(m);
  std::mt19937 rng(5);
  const Eigen::VectorXd y = randomState(s, rng);
  // Move every body for a time h with constant v and body angular velocity w.
  auto moved = [&](double h) {
    Eigen::VectorXd z = y;
    for (int b = 0; b < s.layout().bodies; ++b) {
      const int o = s.layout().body(b);
      z.segment<3>(o + L::kR) += h * y.segment<3>(o + L::kV);
      const Eigen::Vector3d w = y.segment<3>(o + L::kW);
      const Eigen::Vector4d e = y.segment<4>(o + L::kE);
      const Eigen::Quaterniond q(e(0), e(1), e(2), e(3));
      // Signed angle about a fixed axis (a negative h turns backwards about the same axis).
      const Eigen::Quaterniond r(Eigen::AngleAxisd(h * w.norm(), w / w.norm()));
      const Eigen::Quaterniond qr = q * r;
      z.segment<4>(o + L::kE) << qr.w(), qr.x(), qr.y(), qr.z();
    }
    return z;
  };
  for (int k = 0; k < s.constraints().size(); ++k) {
    const auto& eq = s.constraints().equations()[k];
    if (eq.motion >= 0) continue;  // geometry only; the motion function has its own tests
    double first = 0, second = 0;
    s.constraintRates(k, y.data(), &first, &second);
    const double h = 1e-4;
    const double p = s.constraintValue(k, 0.0, moved(h).data());
    const double z = s.constraintValue(k, 0.0, y.data());
    const double mns = s.constraintValue(k, 0.0, moved(-h).data());
    EXPECT_NEAR(first, (p - mns) / (2 * h), 1e-7 * (1.0 + std::abs(first))) << k;
    EXPECT_NEAR(second, (p - 2 * z + mns) / (h * h), 1e-5 * (1.0 + std::abs(second))) << k;
  }
}

TEST(InitialConditions, AssemblyMovesAMisplacedPartOntoItsJoint) {
  // A pendulum whose joint markers are 0.1 apart: assembly closes the gap and says how far
  // the part moved.
  const char* text =
      "pendulum\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=1,0,0\n"
      "MARKER/21, PART=2, QP=0.1,0,0\n"
      "JOINT/1, REVOLUTE, I=21, J=10\n"
      "END\n";
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "p.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  const MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState();
  const auto r = assemblePositions(s, 0.0, y, 1e-12, 25);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.partMoves[0], 0.1, 1e-9);  // the least change: a pure 0.1 shift
  for (int k = 0; k < s.constraints().size(); ++k)
    EXPECT_NEAR(s.constraintValue(k, 0.0, y.data()), 0.0, 1e-12);
}

TEST(InitialConditions, CoaxialHingesLeaveRedundantEquationsOut) {
  // ADAMS's door (docs/theory.md §5): two revolute hinges on one axis. Five equations of the second hinge
  // repeat the first; DOF stays 1.
  const char* text =
      "door\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0,0,0\n"
      "MARKER/11, PART=1, QP=0,0,2\n"
      "PART/2, MASS=10, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=0.5,0,1\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "MARKER/22, PART=2, QP=0,0,2\n"
      "JOINT/1, REVOLUTE, I=21, J=10\n"
      "JOINT/2, REVOLUTE, I=22, J=11\n"
      "END\n";
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "door.adm", ds, d);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  MultibodySystem s(m);
  const auto red = removeRedundantConstraints(s, s.initialState());
  EXPECT_EQ(red.rank, 5);
  EXPECT_EQ(6 - red.rank, 1);
  ASSERT_EQ(red.removed.size(), 5u);
  for (int k : red.removed) EXPECT_EQ(s.constraints().equations()[k].joint, 1);  // JOINT/2
}

}  // namespace
}  // namespace openmss::mechanics
