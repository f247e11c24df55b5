#pragma once
// KLU's pivot order for the sparse Newton matrices of GSTIFF, WSTIFF and DSTIFF: an internal
// setting, not an ADAMS argument. Only tests and benches choose another order than the default,
// to show that a run does not depend on round-off luck (`openmss run --pivot-order`, not in
// --help; docs/integrators.md, "A second failure at a flat passage, on another pivot order").

namespace openmss::solvers {

enum class PivotOrder {
  Default,  // block triangular form (BTF), then AMD per block (KluLinearSolver::Options{})
  NoBtf,    // AMD on the whole matrix, no BTF
  Colamd,   // BTF, then COLAMD per block
};

}  // namespace openmss::solvers
