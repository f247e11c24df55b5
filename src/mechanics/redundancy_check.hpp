#pragma once
// The run-time check of the constraint equations found redundant at the start (docs/theory.md
// §8b): they are not solved for, so nothing keeps them satisfied but the equations they
// duplicated. A motion or a singular position can make them disagree; the run must then stop
// and name the equation, not go on with a mechanism that has come apart.

#include <optional>
#include <string>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

struct RedundantViolation {
  int equation = -1;   // index into the constraint set
  double value = 0.0;  // its |Phi|
  double tolerance = 0.0;
};

// The tolerance a removed equation may drift by: `relative` times the model's size (the
// largest distance of a marker from the ground origin at the data set's configuration, at
// least 1). Angles (dot products) are held to the same number.
double redundantTolerance(const model::Model& model, double relative = 1e-6);

// The most violated removed (inactive) equation beyond `tolerance`, if any.
std::optional<RedundantViolation> violatedRedundantEquation(const MultibodySystem& system,
                                                            double t, const double* y,
                                                            double tolerance);

// "JOINT/2 (REVOLUTE) equation X (I-J), removed as redundant at the start, is violated by ..."
std::string describeViolation(const MultibodySystem& system, const RedundantViolation& v,
                              double t);

}  // namespace openmss::mechanics
