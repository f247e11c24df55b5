#include "support/validation_data.hpp"

namespace openmss::testing {

// OPENMSS_SHARED_DIR is defined for this file alone (tests/CMakeLists.txt).
std::filesystem::path corpusDir() {
  return std::filesystem::path(OPENMSS_SHARED_DIR) / "validation" / "corpus";
}

}  // namespace openmss::testing
