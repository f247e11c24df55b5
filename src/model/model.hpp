#pragma once
// The Model: a validated, flat, index-based description of the mechanism, built once from a
// Dataset and immutable during an analysis. Cross references are indices into the vectors
// below (never ids); ids are kept for output and diagnostics.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "common/source_location.hpp"
#include "expr/expression.hpp"
#include "model/measure.hpp"

namespace openmss::model {

struct Units {
  double ucf = 1.0;                     // Force * UCF = Mass * Acceleration
  // Unit names as the UNITS statement gives them (canonical words).
  std::string length = "METER", mass = "KILOGRAM", time = "SECOND", force = "NEWTON";
  std::string description = "m, kg, s, N";
};

struct Part {
  long id = 0;
  bool ground = false;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the CM, in body (CM marker) axes
  // Pose of the body frame (origin at the CM, axes of the CM marker) at the data set's
  // configuration, in ground.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  // Initial velocities as given: translational in ground axes, angular in CM-marker axes.
  std::array<std::optional<double>, 3> velocity;
  std::array<std::optional<double>, 3> angularVelocity;
  int body = -1;  // index of the moving body in the state (-1 for ground)
  SourceLocation where;
};

struct Marker {
  long id = 0;
  int part = -1;
  // Pose in the part's body frame (origin at the CM, CM-marker axes).
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  SourceLocation where;
};

enum class JointType { Revolute, Spherical, Universal, Hooke, Translational, Cylindrical, Fixed };
const char* jointTypeName(JointType t);

struct Joint {
  long id = 0;
  JointType type = JointType::Revolute;
  int iMarker = -1;
  int jMarker = -1;
  SourceLocation where;
};

struct Motion {
  long id = 0;
  int joint = -1;
  bool rotation = true;  // rotational (revolute, cylindrical ROTATION) or translational
  expr::Expression function;  // displacement as a function of TIME
  SourceLocation where;
};

// An expression together with the model quantities its host calls read.
struct BoundExpression {
  expr::Expression expression;
  std::vector<Measure> measures;  // measures[k] is the value of expression.hostCalls()[k]
};

struct SForce {
  long id = 0;
  int iMarker = -1;
  int jMarker = -1;
  bool rotation = false;
  bool actionOnly = false;
  BoundExpression function;
  SourceLocation where;
};

struct Request {
  enum class Kind { Displacement, Velocity, Acceleration, Force, Expressions };
  long id = 0;
  Kind kind = Kind::Expressions;
  int iMarker = -1;
  int jMarker = -1;  // -1: ground origin
  int rmMarker = -1; // -1: ground axes
  std::array<std::optional<BoundExpression>, 8> columns;  // F1..F8 for Kind::Expressions
  std::string comment;
  SourceLocation where;
};

struct OutputSettings {
  bool reqsave = false;
  bool grsave = false;
  bool noseparator = false;
};

struct Model {
  std::string title;
  std::string file;
  Units units;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<Part> parts;
  std::vector<Marker> markers;
  std::vector<Joint> joints;
  std::vector<Motion> motions;
  std::vector<SForce> sforces;
  std::vector<Request> requests;
  OutputSettings output;
  std::vector<int> movingParts;  // part index of each moving body, in state order
  int groundPart = -1;

  std::map<long, int> partIndex, markerIndex, jointIndex;

  int bodyCount() const { return static_cast<int>(movingParts.size()); }
};

}  // namespace openmss::model
