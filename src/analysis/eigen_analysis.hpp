#pragma once
// Eigenvalues and mode shapes of a linearised model (LINEAR/EIGENSOL, docs/theory.md "Linear
// analysis"): the eigenvalues of the state matrix A, each with its damping ratio and natural
// frequency, and the mode shapes back-transformed to part coordinates.

#include <complex>
#include <string>
#include <vector>

#include "analysis/linearization.hpp"
#include "model/model.hpp"

namespace openmss::analysis {

struct EigenMode {
  std::complex<double> value;
  double dampingRatio = 0.0;      // -Re / |lambda| (1 for a real negative eigenvalue)
  double naturalFrequency = 0.0;  // |lambda| / (2 pi), Hz (undamped)
  double dampedFrequency = 0.0;   // |Im| / (2 pi), Hz
  // Mode shape per moving body (6 ground coordinates: X Y Z RX RY RZ), scaled so that its
  // largest component is 1 (real), then each user state.
  Eigen::VectorXcd shape;
};

// Eigenvalues sorted by |lambda|, then by imaginary part (negative first).
std::vector<EigenMode> eigenModes(const LinearSystem& linear);

// The .msg table: eigenvalues, then (unless withoutShapes) each mode shape with Im >= 0, one
// line per part.
std::vector<std::string> eigenReport(const std::vector<EigenMode>& modes,
                                     const LinearSystem& linear, const model::Model& model,
                                     double time, bool withoutShapes);

}  // namespace openmss::analysis
