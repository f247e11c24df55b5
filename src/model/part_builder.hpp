#pragma once
// Dataset -> Model for PART and MARKER statements: the rigid bodies (mass, inertia, body frame
// at the CM marker, initial velocities, EXACT), the ground part, and every marker's pose in its
// body frame (QP with REULER or ZP/XP, RM). docs/theory.md §2 states the conventions: body
// frame = CM marker frame, inertia about the CM in CM axes (IM and products of inertia
// converted), REULER body 3-1-3 angles. Also the reference from another statement's marker
// argument (I=, J=, RM=, ...) to a marker index.

#include <map>
#include <optional>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Reads PART and MARKER statements in data-set order (read*), then builds the parts and
// markers once every statement is read (build): a MARKER may precede its PART, and a PART's
// CM and IM markers follow it.
class PartBuilder {
 public:
  void readPart(const language::Statement& s, Diagnostics& diags);
  void readMarker(const language::Statement& s, Diagnostics& diags);

  // Model::parts, groundPart, movingParts, markers and their indices. Needs the PART and
  // MARKER statements read so far; reports every inconsistency among them.
  void build(const language::Dataset& dataset, Model& model, Diagnostics& diags) const;

 private:
  struct RawPart {
    const language::Statement* s = nullptr;
    Eigen::Vector3d qg = Eigen::Vector3d::Zero();
    Eigen::Matrix3d a = Eigen::Matrix3d::Identity();  // BCS in ground
    std::optional<long> cm, im;
    Eigen::Vector3d ip = Eigen::Vector3d::Zero();
    Eigen::Vector3d products = Eigen::Vector3d::Zero();
  };
  struct RawMarker {
    const language::Statement* s = nullptr;
    long part = 0;
    Eigen::Vector3d qp = Eigen::Vector3d::Zero();  // in BCS (or in RM's axes)
    Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
    std::optional<long> rm;
  };
  // Marker poses in ground at the data set's configuration, by marker id.
  struct GroundPoses {
    std::map<long, Eigen::Vector3d> position;
    std::map<long, Eigen::Matrix3d> rotation;
    std::map<long, long> part;
  };

  void buildParts(const language::Dataset& dataset, Model& model, Diagnostics& diags,
                  std::map<long, size_t>& rawPartIndex) const;
  GroundPoses markerPoses(const std::map<long, size_t>& rawPartIndex, Diagnostics& diags) const;
  void bodyFrames(const std::map<long, size_t>& rawPartIndex, const GroundPoses& poses,
                  Model& model, Diagnostics& diags) const;
  void relativeMarkers(const GroundPoses& poses, Model& model) const;

  std::vector<RawPart> parts_;
  std::vector<RawMarker> markers_;
  long lastPartId_ = 0;  // a MARKER without PART= belongs to the preceding PART
};

// The marker named by argument `name` of `s` (I=, J=, RM=, ...): its index in Model::markers,
// or -1 after a diagnostic (missing and not optional, unknown id, or a FLOATING marker, which
// only JFLOAT of VFORCE, VTORQUE and GFORCE may name).
int markerReference(const Model& model, const language::Statement& s, const char* name,
                    Diagnostics& diags);

}  // namespace openmss::model
