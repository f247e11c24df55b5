#pragma once
// The degree-of-freedom analysis of a loaded model (docs/theory.md §3): the Gruebler count,
// the independent loops, the redundant constraint equations removed, and the degrees of
// freedom from the rank of the constraint Jacobian; and the model summary the message file
// opens with.

#include <string>
#include <vector>

#include "mechanics/loop_count.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

struct DegreeOfFreedomCount {
  int gruebler = 0;          // 6 per moving part minus the equations the joints remove
  int degreesOfFreedom = 0;  // 6 per moving part minus the rank of the constraint Jacobian
  mechanics::LoopCount loops;
  std::vector<int> removed;  // redundant constraint equations, deactivated in the system
};

// Finds and deactivates the redundant constraint equations of `system` at y.
DegreeOfFreedomCount countDegreesOfFreedom(mechanics::MultibodySystem& system,
                                           const Eigen::VectorXd& y);

// The " Model summary" block of the message file.
std::vector<std::string> modelSummaryLines(const mechanics::MultibodySystem& system,
                                           const DegreeOfFreedomCount& count);

}  // namespace openmss::analysis
