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
  }
  return "?";
}

}  // namespace openmss::model
