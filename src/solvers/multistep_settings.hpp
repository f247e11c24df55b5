#pragma once
// The settings of the variable-step, variable-order multistep integrators: the BDF of GSTIFF and
// WSTIFF (solvers/bdf_integrator.hpp), SUNDIALS IDA (solvers/ida_integrator.hpp) and the
// Adams-Bashforth-Moulton ABAM (analysis/abam_integrator.hpp). ERROR, HINIT, HMAX, HMIN, KMAX
// and MAXIT mean the same for all three (docs/integrators.md); KMAX is at most 5 for IDA and
// 12 for ABAM. HHT is a one-step method with its own settings (solvers/hht_integrator.hpp).

#include <limits>

#include "solvers/pivot_order.hpp"

namespace openmss::solvers {

struct MultistepSettings {
  double error = 1e-3;  // ERROR: local error tolerance (relative and absolute)
  double hinit = 0.0;   // HINIT: first step (0: chosen by the caller)
  double hmax = std::numeric_limits<double>::infinity();  // HMAX
  double hmin = 0.0;  // HMIN: smallest step before the run fails
  int kmax = 6;       // KMAX: highest order
  int maxit = 10;     // MAXIT: corrector iterations per attempt
  // Corrector coefficients (docs/integrators.md, "GSTIFF and WSTIFF"). Variable: the BDF
  // through the actual past times (WSTIFF). Fixed: the constant-step BDF through the past
  // solution interpolated to an equally spaced grid at the new step (GSTIFF's Nordsieck
  // rescaling); a step change then costs an interpolation error.
  bool fixedCoefficients = false;
  // PATTERN: when set, the Jacobian is also re-formed at every corrector iteration j whose
  // flag pattern[j % 10] is true, and always at the first (docs/integrators.md, "Defaults"). Unset:
  // it is re-formed only when cj has drifted or the corrector fails.
  bool patternGiven = false;
  bool pattern[10] = {true, false, false, false, true, false, false, false, true, false};
  // CORRECTOR=MODIFIED (docs/integrators.md, "Corrector"): the corrector's convergence test
  // weighs only the unknowns of the integration error test (I3: the displacements), not every
  // differential unknown (ORIGINAL, the default).
  bool modifiedCorrector = false;
  // ADAPTIVITY (docs/integrators.md, "ADAPTIVITY"): ADAPTIVITY / h added to the corrector's
  // tolerance (BdfIntegrator only; 0: none).
  double adaptivity = 0.0;
  // KLU's pivot order on the sparse path (solvers/pivot_order.hpp; tests and benches only).
  PivotOrder pivotOrder = PivotOrder::Default;
};

}  // namespace openmss::solvers
