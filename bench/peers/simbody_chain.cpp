// The benchmark pendulum chains in Simbody (Debian libsimbody-dev 3.7), for scripts/bench.sh.
//
//   simbody_chain KIND N END ACCURACY [INTEGRATOR]
//
// KIND: chain-planar | chain-spatial | chain-stiff4 | chain-stiff8 (the stiff chains' joint
// springs as MobilityLinearSpring and MobilityLinearDamper) | bushing (the bushing chain: see
// buildBushingChain). INTEGRATOR: RKMerson (default)
// or CPodes (Simbody's implicit BDF for stiff systems). Builds the chain of
// bench/model_generators.cpp as a tree of Pin mobilizers (the same inertias, gravity and
// initial state), integrates with the integrator at the given accuracy to END, and prints
// key=value lines: wall times, steps, the tip's final position and velocity, and peak
// resident memory.
// The four-bar row is not built here (not yet).

#include <sys/resource.h>

#include <Simbody.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "../model_generators.hpp"

namespace {

using openmss::bench::ChainModel;

SimTK::Vec3 toSimTK(const openmss::bench::Vec3& v) { return SimTK::Vec3(v[0], v[1], v[2]); }

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The pendulum chains: a tree of Pin mobilizers (see the file header); returns the last link.
SimTK::MobilizedBody buildPinChain(const ChainModel& model, SimTK::SimbodyMatterSubsystem& matter,
                                   SimTK::GeneralForceSubsystem& forces) {
  using namespace SimTK;
  // Body frames sit at each link's proximal joint point with ground-aligned axes; the Pin's
  // mobilizer frames turn its z axis onto the joint axis, so q = 0 is the initial configuration.
  MobilizedBody parent = matter.Ground();
  Vec3 parentOrigin(0);
  MobilizedBody last;
  for (int i = 0; i < static_cast<int>(model.bodies.size()); ++i) {
    const auto& b = model.bodies[i];
    const auto I = openmss::bench::inertiaTensorInGround(b);
    const Vec3 com = toSimTK(b.centerOfMass) - toSimTK(b.proximal);
    const Inertia aboutCom(Mat33(I[0], I[1], I[2], I[3], I[4], I[5], I[6], I[7], I[8]));
    // MassProperties wants the inertia about the body origin: shift from the centre of mass to
    // the origin, which lies at -com from it.
    const Body::Rigid body(MassProperties(b.mass, com, aboutCom.shiftFromMassCenter(-com, b.mass)));
    const Rotation zOntoAxis(UnitVec3(toSimTK(model.joints[i].axis)), ZAxis);
    const Vec3 origin = toSimTK(b.proximal);
    MobilizedBody::Pin pin(parent, Transform(zOntoAxis, origin - parentOrigin), body,
                           Transform(zOntoAxis, Vec3(0)));
    if (model.jointSpring.stiffness > 0.0) {
      Force::MobilityLinearSpring(forces, pin, MobilizerQIndex(0), model.jointSpring.stiffness,
                                  0.0);
      Force::MobilityLinearDamper(forces, pin, MobilizerUIndex(0), model.jointSpring.damping);
    }
    parent = pin;
    parentOrigin = origin;
    last = pin;
  }
  return last;
}

// OpenMSS's BUSHING law (docs/theory.md, "BUSHING, FIELD, BEAM") as a Simbody custom force,
// the benchmark's bushing: projected angles, the relative angular velocity damped, force and
// torque along the J (F) axes on I (M), the reaction on J at I's location. Simbody's own
// Force::LinearBushing (OPENMSS_SIMBODY_LINEAR_BUSHING=1) is a different model beyond first
// order in the rotations, 2.6e-5 m apart at the 10-block tip after 1 s, which would floor the
// matched-accuracy comparison (docs/performance.md, "The bushing chain against Simbody").
class AdamsBushing : public SimTK::Force::Custom::Implementation {
 public:
  AdamsBushing(SimTK::MobilizedBody j, SimTK::Vec3 onJ, SimTK::MobilizedBody i, SimTK::Vec3 onI,
               SimTK::Vec6 k, SimTK::Vec6 c)
      : j_(j), i_(i), onJ_(onJ), onI_(onI), k_(k), c_(c) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    using namespace SimTK;
    const Rotation& rJ = j_.getBodyRotation(s);
    const Rotation& rI = i_.getBodyRotation(s);
    const Vec3 pI = i_.findStationLocationInGround(s, onI_);
    const Vec3 d = pI - j_.findStationLocationInGround(s, onJ_);
    const Vec3 wJ = j_.getBodyAngularVelocity(s);
    const Vec3 v = ~rJ * (i_.findStationVelocityInGround(s, onI_) -
                          j_.findStationVelocityInGround(s, onJ_) - wJ % d);
    const Vec3 w = ~rJ * (i_.getBodyAngularVelocity(s) - wJ);
    const Vec3 xI = rI.x(), zI = rI.z(), xJ = rJ.x(), yJ = rJ.y(), zJ = rJ.z();
    const Vec3 angles(std::atan2(-dot(zI, yJ), dot(zI, zJ)), std::atan2(dot(zI, xJ), dot(zI, zJ)),
                      std::atan2(dot(xI, yJ), dot(xI, xJ)));
    const Vec3 q = ~rJ * d;
    Vec3 f, t;
    for (int a = 0; a < 3; ++a) {
      t[a] = -k_[a] * angles[a] - c_[a] * w[a];
      f[a] = -k_[a + 3] * q[a] - c_[a + 3] * v[a];
    }
    const Vec3 fG = rJ * f, tG = rJ * t;
    i_.applyForceToBodyPoint(s, onI_, fG, bodyForces);
    i_.applyBodyTorque(s, tG, bodyForces);
    j_.applyForceToBodyPoint(s, j_.findStationAtGroundPoint(s, pI), -fG, bodyForces);
    j_.applyBodyTorque(s, -tG, bodyForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody j_, i_;
  SimTK::Vec3 onJ_, onI_;
  SimTK::Vec6 k_, c_;
};

// The bushing chain (bench/model_generators.cpp, bushingChain): one Free mobilizer per block,
// body frame at its centre of mass with ground-aligned axes, so q = 0 is the initial pose.
// BUSHING -> AdamsBushing above (or Force::LinearBushing) with F on the parent (ADAMS's J
// marker) and M on the block (the I marker), both at the shared point and ground-aligned, as
// the generator writes them.
// Both put the force on M/I at its origin and the reaction on F/J at that same point, with
// translations and their damping rate (velocity seen from F/J) along the F/J axes: identical.
// The rotations differ beyond first order (docs/theory.md, "BUSHING, FIELD, BEAM"): OpenMSS
// uses projected angles, damps the relative angular velocity and applies the torque along the
// J axes; Simbody uses body-fixed x-y-z Euler angles, damps their rates and maps the
// generalized moments through the Euler kinematics. The two agree to first order in the
// relative rotation; the difference is second order (measured in docs/performance.md):
// x and z of the 10-block tip come out swapped at 1e-5 m, as each convention breaks the
// model's x-z symmetry its own way.
// Simbody orders the six constants rotations first. SPRINGDAMPER, TRANSLATIONAL ->
// TwoPointLinearSpring (free length springLength, the initial centre distance) plus
// TwoPointLinearDamper between the centres (the first block's to the ground origin).
SimTK::MobilizedBody buildBushingChain(const ChainModel& model,
                                       SimTK::SimbodyMatterSubsystem& matter,
                                       SimTK::GeneralForceSubsystem& forces) {
  using namespace SimTK;
  const auto& e = model.elastic;
  const double kr = e.bushingTorsionStiffness, kt = e.bushingStiffness;
  const double cr = e.bushingTorsionDamping, ct = e.bushingDamping;
  const Vec6 stiffness(kr, kr, kr, kt, kt, kt), damping(cr, cr, cr, ct, ct, ct);
  const char* flag = std::getenv("OPENMSS_SIMBODY_LINEAR_BUSHING");
  const bool adamsLaw = flag == nullptr || std::string(flag) != "1";
  std::vector<MobilizedBody> blocks;
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const auto& b = model.bodies[i];
    const auto I = openmss::bench::inertiaTensorInGround(b);
    const Inertia aboutCom(Mat33(I[0], I[1], I[2], I[3], I[4], I[5], I[6], I[7], I[8]));
    const Body::Rigid body(MassProperties(b.mass, Vec3(0), aboutCom));
    blocks.push_back(MobilizedBody::Free(matter.Ground(), Transform(toSimTK(b.centerOfMass)), body,
                                         Transform()));
  }
  for (const auto& c : model.connections) {
    const MobilizedBody& child = blocks[c.child];
    const MobilizedBody& parent = c.parent < 0 ? matter.Ground() : blocks[c.parent];
    // Body origins: the blocks' centres (ground-aligned at q = 0), ground's at its origin.
    const Vec3 parentOrigin = c.parent < 0 ? Vec3(0) : toSimTK(model.bodies[c.parent].centerOfMass);
    const Vec3 childOrigin = toSimTK(model.bodies[c.child].centerOfMass);
    const Vec3 point = toSimTK(c.point);
    if (adamsLaw)
      Force::Custom(forces, new AdamsBushing(parent, point - parentOrigin, child,
                                             point - childOrigin, stiffness, damping));
    else
      Force::LinearBushing(forces, parent, Transform(point - parentOrigin), child,
                           Transform(point - childOrigin), stiffness, damping);
    const Vec3 parentAnchor = toSimTK(c.parentAnchor) - parentOrigin;
    const Vec3 childAnchor = toSimTK(c.childAnchor) - childOrigin;
    Force::TwoPointLinearSpring(forces, parent, parentAnchor, child, childAnchor, e.springStiffness,
                                c.springLength);
    Force::TwoPointLinearDamper(forces, parent, parentAnchor, child, childAnchor, e.springDamping);
  }
  return blocks.back();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace SimTK;
  if (argc != 5 && argc != 6) {
    std::cerr << "usage: simbody_chain "
                 "chain-planar|chain-spatial|chain-stiff4|chain-stiff8|bushing|bushing-stiff N "
                 "END ACCURACY [RKMerson|CPodes]\n";
    return 64;
  }
  const std::string kind = argv[1];
  const std::string method = argc == 6 ? argv[5] : "RKMerson";
  if (method != "RKMerson" && method != "CPodes") {
    std::cerr << "simbody_chain: unknown integrator " << method << " (RKMerson, CPodes)\n";
    return 64;
  }
  if (kind != "chain-planar" && kind != "chain-spatial" && kind != "chain-stiff4" &&
      kind != "chain-stiff8" && kind != "bushing" && kind != "bushing-stiff") {
    std::cerr << "simbody_chain: " << kind << " is not built for Simbody (see the file header)\n";
    return 3;
  }
  const int links = std::stoi(argv[2]);
  const double end = std::stod(argv[3]);
  const double accuracy = std::stod(argv[4]);
  const auto t0 = std::chrono::steady_clock::now();
  const ChainModel model = openmss::bench::modelByName(kind, links);

  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::UniformGravity gravity(forces, matter, toSimTK(model.gravity));
  // Body frames sit at each link's proximal joint point with ground-aligned axes; the Pin's
  // mobilizer frames turn its z axis onto the joint axis, so q = 0 is the initial configuration.
  MobilizedBody last;
  Vec3 tipStation;
  if (kind == "bushing" || kind == "bushing-stiff") {
    last = buildBushingChain(model, matter, forces);
    const auto& tip = model.bodies[model.tipBody];
    tipStation = toSimTK(tip.distal) - toSimTK(tip.centerOfMass);
  } else {
    last = buildPinChain(model, matter, forces);
    const auto& tipBody = model.bodies.back();
    tipStation = toSimTK(tipBody.distal) - toSimTK(tipBody.proximal);
  }

  system.realizeTopology();
  State state = system.getDefaultState();
  std::unique_ptr<Integrator> owned;
  if (method == "CPodes")
    owned = std::make_unique<CPodesIntegrator>(system, CPodes::BDF, CPodes::Newton);
  else
    owned = std::make_unique<RungeKuttaMersonIntegrator>(system);
  Integrator& integrator = *owned;
  integrator.setAccuracy(accuracy);
  TimeStepper stepper(system, integrator);
  stepper.initialize(state);
  const auto t1 = std::chrono::steady_clock::now();
  stepper.stepTo(end);
  const auto t2 = std::chrono::steady_clock::now();
  const State& final = integrator.getState();
  system.realize(final, Stage::Velocity);
  const Vec3 p = last.findStationLocationInGround(final, tipStation);
  const Vec3 v = last.findStationVelocityInGround(final, tipStation);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("engine=simbody\nsetting=%s accuracy=%g\nbuild_s=%.6f\nintegrate_s=%.6f\n",
              method.c_str(), accuracy, seconds(t0, t1), seconds(t1, t2));
  std::printf("steps=%d\ntime=%.17g\n", integrator.getNumStepsTaken(), final.getTime());
  std::printf("tip=%.17g %.17g %.17g %.17g %.17g %.17g\n", p[0], p[1], p[2], v[0], v[1], v[2]);
  std::printf("rss_mb=%.1f\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}
