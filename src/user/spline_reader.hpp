#pragma once
// SPLINE_READ: SPLINE/id, FILE=name, BLOCK=name, ROUTINE=lib::name (docs/user-subroutines.md).
// The user's reader opens the file itself and hands the data back through PUT_SPLINE.

#include <memory>
#include <string>
#include <vector>

#include "user/element_routine.hpp"

namespace openmss::user {

struct SplineValues {
  std::vector<double> x, z;                 // z: one per curve (a single curve: {0})
  std::vector<std::vector<double>> curves;  // y of each curve at x
};

// Loads SPLINE_READ and calls it once for SPLINE/element.id with `file` and `block`. False
// with the reason in `error` (no routine, IERR nonzero, no PUT_SPLINE, a crash, ...); the
// values are not checked here (the SPLINE builder checks them as for X= and Y=).
bool readUserSpline(const ElementData& element, const std::string& file, const std::string& block,
                    const RoutineName& routine, const std::string& baseDirectory, SplineValues& out,
                    std::string& error);

}  // namespace openmss::user
