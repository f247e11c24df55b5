#include "model/model.hpp"

namespace openmss::model {

const char* jointTypeName(JointType t) {
  switch (t) {
    case JointType::Revolute: return "REVOLUTE";
    case JointType::Spherical: return "SPHERICAL";
    case JointType::Universal: return "UNIVERSAL";
    case JointType::Hooke: return "HOOKE";
    case JointType::Translational: return "TRANSLATIONAL";
    case JointType::Cylindrical: return "CYLINDRICAL";
    case JointType::Fixed: return "FIXED";
    case JointType::Convel: return "CONVEL";
    case JointType::Planar: return "PLANAR";
    case JointType::RackPin: return "RACKPIN";
    case JointType::Screw: return "SCREW";
  }
  return "?";
}

const char* jprimTypeName(JPrimType t) {
  switch (t) {
    case JPrimType::AtPoint: return "ATPOINT";
    case JPrimType::InLine: return "INLINE";
    case JPrimType::InPlane: return "INPLANE";
    case JPrimType::Orientation: return "ORIENTATION";
    case JPrimType::ParallelAxes: return "PARALLEL_AXES";
    case JPrimType::Perpendicular: return "PERPENDICULAR";
  }
  return "?";
}

}  // namespace openmss::model
