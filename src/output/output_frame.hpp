#pragma once
// One output step as the analyses hand it to the writers of result files (.res, .req, .out):
// a read-only snapshot of the solved state at an output time. The analyses build it
// (analysis/output_frame_builder.hpp) and the writers read only it, never the equations.
// Frames, units and signs of every quantity: docs/output-files.md, "The output snapshot".

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace openmss::output {

// The analysis that produced a step. ADAMS's .res names its data blocks after it
// (initialConditions_001, static_001, kinematic_001, dynamic_001).
enum class OutputKind { InitialConditions, Static, Kinematic, Dynamic };
// "initialConditions", "static", "kinematic", "dynamic".
const char* outputKindName(OutputKind kind);

// A moving part (not ground): its body frame, origin at the centre of mass and axes of the CM
// marker, in ground (the frame the data set's PART/CM= and IP= describe).
struct PartOutput {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();             // CM in ground (length)
  Eigen::Vector3d angles = Eigen::Vector3d::Zero();               // body 3-1-3 PSI THETA PHI (rad)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();             // of the CM, ground axes
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();      // ground axes (rad/time)
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();         // of the CM, ground axes
  Eigen::Vector3d angularAcceleration = Eigen::Vector3d::Zero();  // ground axes (rad/time^2)
};

// The force and torque an element exerts on the part of its I marker: force in ground axes,
// torque about the I marker's origin in ground axes. This is what REQUEST/id, FORCE, I=i, J=j
// (RM omitted) reports for that element alone.
struct ElementForceOutput {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

struct OutputFrame {
  double time = 0.0;
  OutputKind kind = OutputKind::Dynamic;
  // One per moving part, in Model::parts order (ground left out).
  std::vector<PartOutput> parts;
  // Constraint reactions, one per element in the model's lists (Model::joints, jprims, motions).
  std::vector<ElementForceOutput> joints, jprims, motions;
  // Applied forces: Model::sforces, springDampers, linearFields (BUSHING, FIELD, BEAM) and
  // vectorForces (VFORCE, VTORQUE, GFORCE).
  std::vector<ElementForceOutput> sforces, springDampers, linearFields, vectorForces;
  // Coupling reactions on the I marker of the first coupled joint (Model::couplers, gears) and
  // GCON reactions on its I marker (Model::gcons).
  std::vector<ElementForceOutput> couplers, gears, gcons;
  // FRICTION on its joint's I marker, CONTACT on its I solid's part (about the I marker's
  // origin), NFORCE on its J marker (the resultant its I markers' forces react on J).
  std::vector<ElementForceOutput> frictions, contacts, nforces;
  // States of each LSE/TFSISO (Model::linearStates), each GSE's continuous states and outputs.
  std::vector<std::vector<double>> linearStates, gseStates, gseOutputs;
  // The eight columns F1..F8 of every REQUEST (Model::requests order): columns 1 and 5 are the
  // translational and rotational magnitudes; angles in radians (docs/output-files.md).
  std::vector<std::array<double, 8>> requests;
  // VARIABLE values (Model::variables order) and DIFF states (Model::diffs order).
  std::vector<double> variables, diffs;
};

}  // namespace openmss::output
