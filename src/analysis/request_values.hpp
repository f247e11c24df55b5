#pragma once
// The eight columns of a REQUEST at a solved state (positions, velocities, accelerations and
// multipliers consistent), and the value of any measure an expression reads.

#include <array>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

// Columns 1..8 (index 0..7). Angles in radians.
std::array<double, 8> requestColumns(const mechanics::MultibodySystem& system,
                                     const model::Request& request, double t,
                                     const Eigen::VectorXd& y, const Eigen::VectorXd& yp);

double measureValue(const mechanics::MultibodySystem& system, const model::Measure& measure,
                    double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp);

}  // namespace openmss::analysis
