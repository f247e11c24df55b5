#include "output/output_frame.hpp"

namespace openmss::output {

const char* outputKindName(OutputKind kind) {
  switch (kind) {
    case OutputKind::InitialConditions:
      return "initialConditions";
    case OutputKind::Static:
      return "static";
    case OutputKind::Kinematic:
      return "kinematic";
    case OutputKind::Dynamic:
      return "dynamic";
  }
  return "dynamic";
}

}  // namespace openmss::output
