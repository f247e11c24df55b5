// The benchmark model generators (bench/model_generators.*): the data sets they write are read
// by `openmss check` with the expected degrees of freedom, the initial states they describe are
// consistent with the joints, and the command file runs.

#include "model_generators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::bench;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::write;

void expectDof(const std::string& name, const std::string& dataset, int dof) {
  const fs::path dir = scratch("generated-" + name);
  write(dir / "model.adm", dataset);
  const Result r = run("check model.adm", dir);
  EXPECT_EQ(r.status, 0) << name << ":\n" << r.output;
  EXPECT_NE(r.output.find("\nDOF " + std::to_string(dof) + "\n"), std::string::npos)
      << name << ":\n" << r.output;
  EXPECT_NE(r.output.find("0 error(s), 0 warning(s)"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(ModelGenerators, CheckReportsTheExpectedDegreesOfFreedom) {
  const int n = 3;
  expectDof("planar", planarPendulumChainAdm(n), n);
  expectDof("spatial", spatialPendulumChainAdm(n), n);
  expectDof("fourbar", fourBarChainAdm(n), 1);
  expectDof("bushing", bushingChainAdm(n), 6 * n);
  expectDof("stiff", adamsDataset(modelByName("chain-stiff8", n)), n);
}

TEST(ModelGenerators, StiffChainsCarryTheStatedJointSprings) {
  // k = ratio * I about the joint, I = m (3 r^2 + L^2) / 12 + m (L/2)^2 for the 1 kg, 1 m,
  // r = 0.02 m links (the parallel-axis theorem, computed here independently of the
  // generator); damping ratio 0.05 of that one-link oscillator: c = 2 0.05 sqrt(k I).
  const double inertia = (3.0 * 0.02 * 0.02 + 1.0) / 12.0 + 0.25;
  for (const auto& [kind, ratio] :
       {std::pair{"chain-stiff4", 1e4}, std::pair{"chain-stiff8", 1e8}}) {
    const ChainModel m = modelByName(kind, 5);
    EXPECT_NEAR(m.jointSpring.stiffness / (ratio * inertia), 1.0, 1e-14) << kind;
    EXPECT_NEAR(m.jointSpring.damping / (0.1 * std::sqrt(m.jointSpring.stiffness * inertia)), 1.0,
                1e-14)
        << kind;
    const std::string adm = adamsDataset(m);
    int springs = 0;
    for (size_t at = adm.find(", ROTATIONAL, "); at != std::string::npos;
         at = adm.find(", ROTATIONAL, ", at + 1))
      ++springs;
    EXPECT_EQ(springs, 5) << kind;  // one per joint
  }
  EXPECT_EQ(planarPendulumChain(5).jointSpring.stiffness, 0.0);  // the plain chains have none
}

Vec3 pointVelocity(const RigidBody& b, const Vec3& p) {
  const Vec3 r{p[0] - b.centerOfMass[0], p[1] - b.centerOfMass[1], p[2] - b.centerOfMass[2]};
  const Vec3& w = b.angularVelocity;
  return {b.velocity[0] + w[1] * r[2] - w[2] * r[1], b.velocity[1] + w[2] * r[0] - w[0] * r[2],
          b.velocity[2] + w[0] * r[1] - w[1] * r[0]};
}

// Every joint point must be the same point on both bodies, move with the same velocity on both
// (the initial state is then consistent and the solver's velocity IC changes nothing), and the
// joint axis must be a unit vector. Exact arithmetic on these small numbers, so 1e-12.
void expectConsistentJoints(const ChainModel& m) {
  for (const RevoluteJoint& j : m.joints) {
    EXPECT_NEAR(std::hypot(j.axis[0], j.axis[1], j.axis[2]), 1.0, 1e-12);
    const RigidBody& child = m.bodies[j.child];
    const Vec3 vc = pointVelocity(child, j.point);
    const Vec3 vp = j.parent < 0 ? Vec3{0, 0, 0} : pointVelocity(m.bodies[j.parent], j.point);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(vc[k], vp[k], 1e-12) << m.title;
    // The joint point is an end of the child.
    const bool atEnd =
        std::hypot(j.point[0] - child.proximal[0], j.point[1] - child.proximal[1],
                   j.point[2] - child.proximal[2]) < 1e-12 ||
        std::hypot(j.point[0] - child.distal[0], j.point[1] - child.distal[1],
                   j.point[2] - child.distal[2]) < 1e-12;
    EXPECT_TRUE(atEnd) << m.title;
  }
}

TEST(ModelGenerators, InitialStatesSatisfyTheJoints) {
  expectConsistentJoints(planarPendulumChain(4));
  expectConsistentJoints(spatialPendulumChain(4));
  expectConsistentJoints(fourBarChain(3));
}

TEST(ModelGenerators, FourBarRowMatchesTheIftommDefinition) {
  // N windows: 2N+1 unit rods, 3N+1 revolute joints, B0 at (0,1) moving at +1 m/s along x.
  const ChainModel m = fourBarChain(5);
  EXPECT_EQ(m.bodies.size(), 11u);
  EXPECT_EQ(m.joints.size(), 16u);
  const RigidBody& rocker0 = m.bodies[m.tipBody];
  EXPECT_NEAR(rocker0.distal[0], 0.0, 1e-15);
  EXPECT_NEAR(rocker0.distal[1], 1.0, 1e-15);
  const Vec3 vB0 = pointVelocity(rocker0, rocker0.distal);
  EXPECT_NEAR(vB0[0], 1.0, 1e-15);
  EXPECT_NEAR(vB0[1], 0.0, 1e-15);
}

TEST(ModelGenerators, InertiaTensorHasTheStatedPrincipalValues) {
  // For a body symmetric about d: I d = Ia d, and trace = Ia + 2 It.
  const RigidBody& b = spatialPendulumChain(2).bodies[1];
  const auto inertia = inertiaTensorInGround(b);
  const Vec3& d = b.axialDirection;
  for (int r = 0; r < 3; ++r) {
    const double id =
        inertia[3 * r] * d[0] + inertia[3 * r + 1] * d[1] + inertia[3 * r + 2] * d[2];
    EXPECT_NEAR(id, b.axialInertia * d[r], 1e-15);
  }
  EXPECT_NEAR(inertia[0] + inertia[4] + inertia[8], b.axialInertia + 2 * b.transverseInertia,
              1e-15);
}

TEST(ModelGenerators, CommandFileRunsTheGeneratedModel) {
  const fs::path dir = scratch("generated-acf");
  write(dir / "chain.adm", planarPendulumChainAdm(2));
  write(dir / "chain.acf", chainAcf("chain.adm", "chain", 0.05, 5, 1e-6));
  const Result r = run("run chain.acf", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "chain.req")) << r.output;
  fs::remove_all(dir);
}

TEST(ModelGenerators, UnknownKindIsRejected) {
  EXPECT_THROW(modelByName("no-such-model", 3), std::invalid_argument);
  EXPECT_THROW(planarPendulumChain(0), std::invalid_argument);
}

}  // namespace
