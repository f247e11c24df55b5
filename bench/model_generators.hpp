// Benchmark models, written once as plain geometry and then as ADAMS data sets.
//
// The same geometry (ChainModel) is what the MuJoCo and Simbody programs in bench/peers/ build,
// so every engine integrates the same bodies, joints, inertias and initial state. The code is
// plain C++ without OpenMSS dependencies so the peer programs can compile it directly.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace openmss::bench {

using Vec3 = std::array<double, 3>;

// One rigid link of a benchmark model: a slender cylinder (or, for the bushing chain, a compact
// block) with its principal inertias along `axialDirection` and two directions across it.
struct RigidBody {
  Vec3 proximal{};        // joint point to the parent (pendulum chains, four-bar rockers)
  Vec3 distal{};          // far end (the tip of the last link)
  Vec3 centerOfMass{};
  Vec3 axialDirection{};  // unit vector from proximal to distal
  double mass = 0.0;
  double axialInertia = 0.0;       // about axialDirection through the centre of mass
  double transverseInertia = 0.0;  // about any direction across it through the centre of mass
  Vec3 velocity{};                 // initial velocity of the centre of mass (ground frame)
  Vec3 angularVelocity{};          // initial angular velocity (ground frame)
};

// Inertia tensor about the centre of mass in ground axes, row-major 3x3 (the tensor itself:
// off-diagonal entries are minus the products of inertia).
std::array<double, 9> inertiaTensorInGround(const RigidBody& body);

// A revolute joint between two bodies (index -1 is ground) at a point about a unit axis.
struct RevoluteJoint {
  int child = 0;
  int parent = -1;
  Vec3 point{};
  Vec3 axis{};
};

// Bushing plus translational spring-damper between two bodies at a shared point.
struct ElasticConnection {
  int child = 0;
  int parent = -1;
  Vec3 point{};  // bushing location (both markers start coincident and ground-aligned)
  Vec3 childAnchor{};
  Vec3 parentAnchor{};  // spring-damper end points
  double springLength = 0.0;
};

struct ElasticParameters {
  double bushingStiffness = 1.0e4;         // N/m, each axis
  double bushingDamping = 20.0;            // N s/m
  double bushingTorsionStiffness = 100.0;  // N m/rad, each axis
  double bushingTorsionDamping = 0.5;      // N m s/rad
  double springStiffness = 1.0e4;          // N/m
  double springDamping = 20.0;             // N s/m
};

// A rotational spring-damper across every revolute joint of a stiff chain (torque
// -stiffness angle - damping rate about the joint axis, zero at the initial configuration).
struct JointSpring {
  double stiffness = 0.0;  // N m/rad
  double damping = 0.0;    // N m s/rad
};

struct ChainModel {
  std::string title;
  std::vector<RigidBody> bodies;
  std::vector<RevoluteJoint> joints;
  JointSpring jointSpring;  // on every joint when its stiffness is positive
  std::vector<ElasticConnection> connections;
  ElasticParameters elastic;
  Vec3 gravity{0.0, -9.80665, 0.0};
  int tipBody = 0;  // the reported point is bodies[tipBody].distal
  int expectedDof = 0;
};

// Options of the pendulum chains. The chain starts straight, tilted by `tiltAngle` from the
// downward vertical, at rest: a small tilt keeps the motion near-linear (not chaotic), so that
// the tip state after 10 s is a meaningful accuracy measure.
struct PendulumChainOptions {
  double linkLength = 1.0;
  double linkMass = 1.0;
  double linkRadius = 0.02;
  double tiltAngle = 0.1;  // rad
};

// Planar chain: all joint axes along ground z, motion in the x-y plane, gravity -y.
ChainModel planarPendulumChain(int links, const PendulumChainOptions& options = {});
// Spatial chain: joint axes alternate between ground z and ground x and the chain is tilted
// towards x and z, so every link moves out of any one plane.
ChainModel spatialPendulumChain(int links, const PendulumChainOptions& options = {});
// Stiff planar chain: the planar chain with a rotational spring-damper on every joint whose
// stiffness over the link's moment of inertia about its joint is `stiffnessRatio` (1/s^2;
// 1e4 and 1e8 for the kinds "chain-stiff4" and "chain-stiff8") and whose damping ratio of that
// single-link oscillator is 0.05. The springs hold the chain nearly straight: the motion is
// the tilted chain swinging almost as one pendulum, with fast joint modes up to
// 2 sqrt(stiffnessRatio) rad/s that an explicit method must resolve for stability and an
// implicit one may step over.
ChainModel stiffPendulumChain(int links, double stiffnessRatio);
// IFToMM multibody benchmark A02 "N four-bar mechanism": N square windows of unit rods
// (N+1 rockers pinned to ground at x = 0..N, N couplers across their tops), 1 kg each,
// gravity -y, started from the square configuration with point B0 (top of the first rocker)
// moving at 1 m/s along +x. One degree of freedom; 3N redundant revolute equations.
ChainModel fourBarChain(int loops);
// N free blocks hanging in a tilted line, each held to the previous (the first to ground) by a
// BUSHING and a translational SPRINGDAMPER: 6N degrees of freedom.
ChainModel bushingChain(int links, const ElasticParameters& parameters = {});
// The stiff variant's constants ("bushing-stiff"): 100x the stiffness, damping ratio ~0.1.
ElasticParameters stiffBushingParameters();

// The model as an ADAMS data set. Numbering: ground is PART/1, body i is PART/(i+2); part p
// owns markers 10p (centre of mass; on ground the origin) and 10p+1 (the tip point, distal end).
// Joint j has I and J markers B+2j and B+2j+1, connection c has B+2(J+c) and B+2(J+c)+1, where
// B = 10 (bodies + 2) and J = joint count. REQUEST/1 and /2: displacement and velocity of the tip
// marker relative to the ground origin marker 10, in ground axes.
std::string adamsDataset(const ChainModel& model);

// The four benchmark data sets.
std::string planarPendulumChainAdm(int links);
std::string spatialPendulumChainAdm(int links);
std::string fourBarChainAdm(int loops);
std::string bushingChainAdm(int links);

// The ADAMS marker id of the tip point (I marker of REQUEST/1).
int tipMarkerId(const ChainModel& model);

// Command file: read `datasetFile`, write outputs as `outputName`, `integrator` (an INTEGRATOR
// method: GSTIFF, MERSON, ...) at `error`, simulate dynamics to `endTime` with `steps` output
// steps, stop.
std::string chainAcf(const std::string& datasetFile, const std::string& outputName,
                     double endTime = 10.0, int steps = 100, double error = 1.0e-6,
                     const std::string& integrator = "GSTIFF");

// Model kinds known by name ("chain-planar", "chain-spatial", "chain-stiff4", "chain-stiff8",
// "fourbar", "bushing").
ChainModel modelByName(const std::string& kind, int size);
std::vector<std::string> modelNames();

}  // namespace openmss::bench
