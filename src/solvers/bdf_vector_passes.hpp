#pragma once
// The per-unknown passes of BdfIntegrator's step written as single loops over the unknowns
// (solvers/bdf_integrator.cpp; docs/performance.md, "GSTIFF's cost per step, cheaper"). Each
// makes the same floating-point operations, in the same order on every entry, as the Eigen
// vector expressions it replaces, one pass per expression (-ffp-contract=off keeps each product
// and sum a separate rounding), so the results are bit-identical; what goes is the reloading
// and restoring of the intermediate vectors between the passes.

#include <Eigen/Dense>

namespace openmss::solvers::bdf {

// out = 0 + w[0] src[0] + w[1] src[1] + ... + w[m-1] src[m-1], added left to right: the bits
// of out.setZero() followed by out += w[j] * src[j] for j = 0..m-1 (unrolled for m <= 8). out may
// not be one of the sources.
void combineFromZero(double* out, const double* const* src, const double* w, int m, Eigen::Index n);
// out = w[0] src[0] + w[1] src[1] + ...: the bits of out = w[0] * src[0] followed by
// out += w[j] * src[j] for j = 1..m-1 (m >= 1; unrolled for m <= 8).
void combine(double* out, const double* const* src, const double* w, int m, Eigen::Index n);

// One corrector update after the linear solve: d = dy colScale (times cjFactor when rescale),
// stored back into dy, then y -= d and yp = cj y + base at the new y (the next iteration's and
// the step's derivative); with later, laterChanges = |d| (first later iteration) or
// laterChanges += |d| (the others).
struct CorrectorUpdate {
  bool rescale = false;
  double cjFactor = 1.0;
  double cj = 0.0;
  enum class Later { None, Assign, Add } later = Later::None;
};
void applyCorrectorChange(const CorrectorUpdate& u, double* dy, const double* colScale, double* y,
                          const double* base, double* yp, double* laterChanges, Eigen::Index n);

}  // namespace openmss::solvers::bdf
