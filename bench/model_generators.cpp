#include "model_generators.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace openmss::bench {
namespace {


Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vec3 normalized(const Vec3& a) { return scale(1.0 / norm(a), a); }

// A unit vector perpendicular to `u`, taken from whichever ground axis is least aligned with it,
// so marker x axes (XP) never degenerate.
Vec3 perpendicular(const Vec3& u) {
  const Vec3 axis = std::fabs(u[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalized(cross(u, axis));
}

std::string number(double x) {
  if (x == 0.0) return "0";  // also turns -0 into 0
  // Shortest of 15 or 17 significant digits that reads back as the same double.
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.15g", x);
  if (std::strtod(buffer, nullptr) != x) std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string triple(const Vec3& v) {
  return number(v[0]) + "," + number(v[1]) + "," + number(v[2]);
}

void requirePositive(int n, const char* what) {
  if (n < 1) throw std::invalid_argument(std::string(what) + " must be at least 1");
}

RigidBody slenderLink(const Vec3& proximal, const Vec3& direction, const PendulumChainOptions& o) {
  RigidBody b;
  b.proximal = proximal;
  b.axialDirection = normalized(direction);
  b.distal = add(proximal, scale(o.linkLength, b.axialDirection));
  b.centerOfMass = add(proximal, scale(0.5 * o.linkLength, b.axialDirection));
  b.mass = o.linkMass;
  // Solid cylinder: the small axial inertia keeps the mass matrix regular without changing the
  // swing dynamics noticeably.
  const double r2 = o.linkRadius * o.linkRadius;
  b.axialInertia = 0.5 * o.linkMass * r2;
  b.transverseInertia = o.linkMass * (3.0 * r2 + o.linkLength * o.linkLength) / 12.0;
  return b;
}

ChainModel pendulumChain(int links, const PendulumChainOptions& o, bool spatial) {
  requirePositive(links, "links");
  ChainModel m;
  const double s = std::sin(o.tiltAngle);
  const double c = std::cos(o.tiltAngle);
  // Spatial: tilted equally towards +x and +z so both joint axis families carry gravity torque.
  const Vec3 direction =
      spatial ? Vec3{s / std::sqrt(2.0), -c, s / std::sqrt(2.0)} : Vec3{s, -c, 0.0};
  m.title = std::string(spatial ? "Spatial" : "Planar") + " pendulum chain of " +
            std::to_string(links) + " revolute links, tilted " + number(o.tiltAngle) +
            " rad, released at rest";
  Vec3 point{0, 0, 0};
  for (int i = 0; i < links; ++i) {
    m.bodies.push_back(slenderLink(point, direction, o));
    RevoluteJoint j;
    j.child = i;
    j.parent = i - 1;
    j.point = point;
    j.axis = (spatial && i % 2 == 1) ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
    m.joints.push_back(j);
    point = m.bodies.back().distal;
  }
  m.tipBody = links - 1;
  m.expectedDof = links;
  return m;
}

// ADAMS markers are written in part coordinates; every part frame here coincides with ground
// (no QG/REULER), so part and ground coordinates are the same numbers.
void writeMarker(std::string& out, int id, int part, const Vec3& at, const Vec3* zAxis,
                 const Vec3* xAxis) {
  out += "MARKER/" + std::to_string(id) + ", PART=" + std::to_string(part) + ", QP=" + triple(at);
  if (zAxis != nullptr) {
    out += "\n, ZP=" + triple(add(at, *zAxis)) + ", XP=" + triple(add(at, *xAxis));
  }
  out += "\n";
}

int partId(int body) { return body + 2; }

}  // namespace

std::array<double, 9> inertiaTensorInGround(const RigidBody& b) {
  // I = It (1 - d d^T) + Ia d d^T for a body symmetric about d.
  std::array<double, 9> inertia{};
  const Vec3& d = b.axialDirection;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      const double ddT = d[r] * d[k];
      inertia[3 * r + k] =
          b.transverseInertia * ((r == k ? 1.0 : 0.0) - ddT) + b.axialInertia * ddT;
    }
  return inertia;
}

ChainModel planarPendulumChain(int links, const PendulumChainOptions& options) {
  return pendulumChain(links, options, false);
}

ChainModel spatialPendulumChain(int links, const PendulumChainOptions& options) {
  return pendulumChain(links, options, true);
}

ChainModel stiffPendulumChain(int links, double stiffnessRatio) {
  ChainModel m = pendulumChain(links, PendulumChainOptions{}, false);
  const RigidBody& b = m.bodies.front();
  // Moment of inertia of one link about its joint (parallel axes: half a length off its centre).
  const double half = 0.5 * PendulumChainOptions{}.linkLength;
  const double aboutJoint = b.transverseInertia + b.mass * half * half;
  m.jointSpring.stiffness = stiffnessRatio * aboutJoint;
  m.jointSpring.damping = 2.0 * 0.05 * std::sqrt(m.jointSpring.stiffness * aboutJoint);
  m.title = "Stiff planar pendulum chain of " + std::to_string(links) +
            " revolute links with joint springs k/I = " + number(stiffnessRatio) +
            " 1/s^2, damping ratio 0.05, tilted 0.1 rad, released at rest";
  return m;
}

ChainModel fourBarChain(int loops) {
  requirePositive(loops, "loops");
  ChainModel m;
  m.title = "IFToMM A02 N-four-bar mechanism, N = " + std::to_string(loops) +
            ", unit rods of 1 kg, B0 at 1 m/s";
  PendulumChainOptions rod;  // 1 m, 1 kg, radius 0.02
  // The benchmark's rods are thin with uniformly distributed mass: m L^2 / 12 across them
  // (docs/validation.md, "IFToMM A02"). The radius only gives the axial inertia, which the
  // planar motion never excites but the mass matrix of a spatial part needs.
  auto thin = [&rod](RigidBody b) {
    b.transverseInertia = b.mass * rod.linkLength * rod.linkLength / 12.0;
    return b;
  };
  m.gravity = {0.0, -9.81, 0.0};  // the benchmark's 9.81 N/kg along -y
  const Vec3 up{0, 1, 0};
  const Vec3 right{1, 0, 0};
  const Vec3 z{0, 0, 1};
  // Rockers 0..N first, then couplers 1..N (coupler i spans the tops of rockers i-1 and i).
  for (int i = 0; i <= loops; ++i) {
    RigidBody rocker = thin(slenderLink({double(i), 0, 0}, up, rod));
    // Top moving at +1 m/s along x: rotation -1 rad/s about z; the centre moves at half that.
    rocker.angularVelocity = {0, 0, -1};
    rocker.velocity = {0.5, 0, 0};
    m.bodies.push_back(rocker);
    m.joints.push_back({i, -1, rocker.proximal, z});
  }
  for (int i = 1; i <= loops; ++i) {
    RigidBody coupler = thin(slenderLink({double(i - 1), 1, 0}, right, rod));
    coupler.velocity = {1, 0, 0};
    const int index = static_cast<int>(m.bodies.size());
    m.bodies.push_back(coupler);
    m.joints.push_back({index, i - 1, coupler.proximal, z});
    m.joints.push_back({index, i, coupler.distal, z});
  }
  m.tipBody = 0;  // B0, the benchmark's reference point, is the top of the first rocker
  m.expectedDof = 1;
  return m;
}

ChainModel bushingChain(int links, const ElasticParameters& parameters) {
  requirePositive(links, "links");
  ChainModel m;
  m.title = "Chain of " + std::to_string(links) +
            " free blocks joined by BUSHING and SPRINGDAMPER, tilted, released at rest";
  m.elastic = parameters;
  const double spacing = 1.0;
  const double tilt = 0.1;
  const Vec3 direction = {std::sin(tilt) / std::sqrt(2.0), -std::cos(tilt),
                          std::sin(tilt) / std::sqrt(2.0)};
  Vec3 previousCenter{0, 0, 0};
  for (int i = 0; i < links; ++i) {
    RigidBody b;
    b.axialDirection = direction;
    b.centerOfMass = add(previousCenter, scale(spacing, direction));
    b.proximal = add(b.centerOfMass, scale(-0.5 * spacing, direction));
    b.distal = add(b.centerOfMass, scale(0.5 * spacing, direction));
    b.mass = 1.0;
    b.axialInertia = 0.05;  // a compact block, isotropic
    b.transverseInertia = 0.05;
    ElasticConnection c;
    c.child = i;
    c.parent = i - 1;
    c.point = b.proximal;
    c.childAnchor = b.centerOfMass;
    c.parentAnchor = previousCenter;
    c.springLength = spacing;
    m.bodies.push_back(b);
    m.connections.push_back(c);
    previousCenter = b.centerOfMass;
  }
  m.tipBody = links - 1;
  m.expectedDof = 6 * links;
  return m;
}

int tipMarkerId(const ChainModel& model) { return 10 * partId(model.tipBody) + 1; }

std::string adamsDataset(const ChainModel& m) {
  const int bodyCount = static_cast<int>(m.bodies.size());
  const int jointMarkerBase = 10 * (bodyCount + 2);
  std::string out = m.title + "\n";
  out += "! Generated by openmss-generate (bench/model_generators.cpp). Every part frame is the\n"
         "! ground frame, so marker coordinates are ground coordinates.\n";
  out += "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n";
  out += "PART/1, GROUND\n";
  out += "MARKER/10, PART=1, QP=0,0,0\n";
  for (int i = 0; i < bodyCount; ++i) {
    const RigidBody& b = m.bodies[i];
    const int p = partId(i);
    out += "PART/" + std::to_string(p) + ", MASS=" + number(b.mass) + ", CM=" +
           std::to_string(10 * p) + ", IP=" + number(b.axialInertia) + "," +
           number(b.transverseInertia) + "," + number(b.transverseInertia);
    // VX..VZ are in ground axes; WX..WZ in the CM marker axes, whose z is `across` below.
    const Vec3 across = perpendicular(b.axialDirection);
    const Vec3 third = cross(across, b.axialDirection);  // CM marker y axis
    const Vec3& w = b.angularVelocity;
    const double wx = w[0] * b.axialDirection[0] + w[1] * b.axialDirection[1] +
                      w[2] * b.axialDirection[2];
    const double wy = w[0] * third[0] + w[1] * third[1] + w[2] * third[2];
    const double wz = w[0] * across[0] + w[1] * across[1] + w[2] * across[2];
    if (norm(b.velocity) > 0.0)
      out += "\n, VX=" + number(b.velocity[0]) + ", VY=" + number(b.velocity[1]) +
             ", VZ=" + number(b.velocity[2]);
    if (norm(w) > 0.0) out += "\n, WX=" + number(wx) + ", WY=" + number(wy) + ", WZ=" + number(wz);
    out += "\n";
    // CM marker: x along the body axis (IP's first entry is the axial inertia).
    writeMarker(out, 10 * p, p, b.centerOfMass, &across, &b.axialDirection);
    writeMarker(out, 10 * p + 1, p, b.distal, nullptr, nullptr);
  }
  const int jointCount = static_cast<int>(m.joints.size());
  for (int j = 0; j < jointCount; ++j) {
    const RevoluteJoint& joint = m.joints[j];
    const Vec3 x = perpendicular(joint.axis);
    const int iMarker = jointMarkerBase + 2 * j;
    writeMarker(out, iMarker, partId(joint.child), joint.point, &joint.axis, &x);
    writeMarker(out, iMarker + 1, partId(joint.parent), joint.point, &joint.axis, &x);
    out += "JOINT/" + std::to_string(j + 1) + ", REVOLUTE, I=" + std::to_string(iMarker) +
           ", J=" + std::to_string(iMarker + 1) + "\n";
    // The joint markers share the joint axis as z and start coincident: ANGLE = 0 there. (No
    // model has both joint springs and connections, whose SPRINGDAMPER ids would collide.)
    if (m.jointSpring.stiffness > 0.0)
      out += "SPRINGDAMPER/" + std::to_string(j + 1) + ", ROTATIONAL, I=" +
             std::to_string(iMarker) + ", J=" + std::to_string(iMarker + 1) +
             ", KT=" + number(m.jointSpring.stiffness) + ", CT=" + number(m.jointSpring.damping) +
             ", ANGLE=0\n";
  }
  const ElasticParameters& e = m.elastic;
  for (int c = 0; c < static_cast<int>(m.connections.size()); ++c) {
    const ElasticConnection& k = m.connections[c];
    const int iMarker = jointMarkerBase + 2 * (jointCount + c);
    writeMarker(out, iMarker, partId(k.child), k.point, nullptr, nullptr);
    writeMarker(out, iMarker + 1, partId(k.parent), k.point, nullptr, nullptr);
    const std::string kt = number(e.bushingStiffness), ct = number(e.bushingDamping);
    const std::string kr = number(e.bushingTorsionStiffness),
                      cr = number(e.bushingTorsionDamping);
    out += "BUSHING/" + std::to_string(c + 1) + ", I=" + std::to_string(iMarker) +
           ", J=" + std::to_string(iMarker + 1) + "\n, K=" + kt + "," + kt + "," + kt +
           ", C=" + ct + "," + ct + "," + ct + "\n, KT=" + kr + "," + kr + "," + kr +
           ", CT=" + cr + "," + cr + "," + cr + "\n";
    // The spring runs between the two centres of mass (ground origin for the first block).
    const int childCm = 10 * partId(k.child);
    const int parentCm = k.parent < 0 ? 10 : 10 * partId(k.parent);
    out += "SPRINGDAMPER/" + std::to_string(c + 1) + ", TRANSLATIONAL, I=" +
           std::to_string(childCm) + ", J=" + std::to_string(parentCm) +
           ", K=" + number(e.springStiffness) + ", C=" + number(e.springDamping) +
           ", LENGTH=" + number(k.springLength) + "\n";
  }
  out += "ACCGRAV/IGRAV=" + number(m.gravity[0]) + ", JGRAV=" + number(m.gravity[1]) +
         ", KGRAV=" + number(m.gravity[2]) + "\n";
  const std::string tip = std::to_string(tipMarkerId(m));
  out += "REQUEST/1, DISPLACEMENT, I=" + tip + ", J=10, COMMENT=tip point\n";
  out += "REQUEST/2, VELOCITY, I=" + tip + ", J=10, COMMENT=tip point\n";
  // The .req file prints six significant digits, too few to measure 1e-8 accuracy of a tip a
  // kilometre from the origin. REQUEST/3..5 carry the tip position and velocity split into
  // exactly printable pieces v = AINT(v) + 1e-6 (a + b): a = AINT(1e6 frac(v)) is an integer
  // below 1e6 (six digits, printed exactly) and b in (-1, 1), so v is recovered to ~1e-12.
  const std::string measures[6] = {"DX(" + tip + ",10)", "DY(" + tip + ",10)",
                                   "DZ(" + tip + ",10)", "VX(" + tip + ",10)",
                                   "VY(" + tip + ",10)", "VZ(" + tip + ",10)"};
  for (int r = 0; r < 3; ++r) {
    out += "REQUEST/" + std::to_string(r + 3);
    for (int half = 0; half < 2; ++half) {
      const std::string& v = measures[2 * r + half];
      const std::string fraction = "1E6*(" + v + "-AINT(" + v + "))";
      const int first = 2 + 4 * half;  // F2..F4, then F6..F8
      out += "\n, F" + std::to_string(first) + "=AINT(" + v + ")\n, F" +
             std::to_string(first + 1) + "=AINT(" + fraction + ")\n, F" +
             std::to_string(first + 2) + "=" + fraction + "-AINT(" + fraction + ")";
    }
    out += "\n, COMMENT=tip state digits\n";
  }
  out += "OUTPUT/REQSAVE\n";
  out += "END\n";
  return out;
}

std::string planarPendulumChainAdm(int links) {
  return adamsDataset(planarPendulumChain(links));
}
std::string spatialPendulumChainAdm(int links) {
  return adamsDataset(spatialPendulumChain(links));
}
std::string fourBarChainAdm(int loops) { return adamsDataset(fourBarChain(loops)); }
std::string bushingChainAdm(int links) { return adamsDataset(bushingChain(links)); }

std::string chainAcf(const std::string& datasetFile, const std::string& outputName,
                     double endTime, int steps, double error, const std::string& integrator) {
  return datasetFile + "\n" + outputName + "\n" + "INTEGRATOR/" + integrator +
         ", ERROR=" + number(error) +
         "\n" + "SIMULATE/DYNAMIC, END=" + number(endTime) + ", STEPS=" + std::to_string(steps) +
         "\nSTOP\n";
}

ElasticParameters stiffBushingParameters() {
  // 100x the translational and torsional stiffness of the default chain, damping ratio about
  // 0.1 per block (c = 0.2 sqrt(k m), m = 1 kg, I = 0.05 kg m^2): modes near 1000 rad/s that
  // hold an explicit method's step near 3 ms while the motion is slow (docs/performance.md,
  // "The stiff bushing chain").
  ElasticParameters p;
  p.bushingStiffness = 1.0e6;
  p.bushingDamping = 200.0;
  p.bushingTorsionStiffness = 1.0e4;
  p.bushingTorsionDamping = 4.5;
  p.springStiffness = 1.0e6;
  p.springDamping = 200.0;
  return p;
}

std::vector<std::string> modelNames() {
  return {"chain-planar", "chain-spatial", "chain-stiff4", "chain-stiff8",
          "fourbar",      "bushing",       "bushing-stiff"};
}

ChainModel modelByName(const std::string& kind, int size) {
  if (kind == "chain-planar") return planarPendulumChain(size);
  if (kind == "chain-spatial") return spatialPendulumChain(size);
  if (kind == "chain-stiff4") return stiffPendulumChain(size, 1e4);
  if (kind == "chain-stiff8") return stiffPendulumChain(size, 1e8);
  if (kind == "fourbar") return fourBarChain(size);
  if (kind == "bushing") return bushingChain(size);
  if (kind == "bushing-stiff") return bushingChain(size, stiffBushingParameters());
  throw std::invalid_argument("unknown model kind '" + kind +
                              "' (chain-planar, chain-spatial, chain-stiff4, chain-stiff8, "
                              "fourbar, bushing, bushing-stiff)");
}

}  // namespace openmss::bench
