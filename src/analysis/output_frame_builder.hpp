#pragma once
// Builds the output snapshot (output/output_frame.hpp) of a solved state: the one place where
// part motion, element forces, request columns and user states are read for the result files
// (docs/output-files.md, "The output snapshot").

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"
#include "output/output_frame.hpp"

namespace openmss::analysis {

using output::OutputFrame;
using output::OutputKind;

// The request columns only (what the .req needs): frame.requests, time and kind.
void fillRequestColumns(const mechanics::MultibodySystem& system, double t,
                        const Eigen::VectorXd& y, const Eigen::VectorXd& yp, OutputFrame& frame);
// Everything else: parts, element forces, VARIABLE values and DIFF states.
void fillStateOutputs(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
                      const Eigen::VectorXd& yp, OutputFrame& frame);

}  // namespace openmss::analysis
