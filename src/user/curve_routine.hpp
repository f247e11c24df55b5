#pragma once
// CURSUB: CURVE/id, FUNCTION=USER(r1, ..., r30) [, MINPAR=, MAXPAR=, CLOSED] (docs/user-
// subroutines.md). The routine gives the curve point and its first and second derivatives in
// alpha; the curve then serves every consumer of a MATRIX curve (CURVE(), PTCV, CVCV, GTCURV).

#include <memory>
#include <string>

#include "common/bspline_curve.hpp"
#include "user/element_routine.hpp"

namespace openmss::user {

struct CurveShape {
  bool closed = false;
  int order = 4;  // passed to the C struct only
  double minPar = -1.0, maxPar = 1.0;
};

// Loads CURSUB and runs its initialization call (IFLAG = 1, then 3, at MINPAR). Null with the
// reason in `error`.
std::shared_ptr<const BSplineCurve> loadCurveRoutine(const ElementData& element,
                                                     const CurveShape& shape,
                                                     const RoutineName& routine,
                                                     const std::string& baseDirectory,
                                                     std::string& error);

}  // namespace openmss::user
