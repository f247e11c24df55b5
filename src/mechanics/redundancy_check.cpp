#include "mechanics/redundancy_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace openmss::mechanics {

double redundantTolerance(const model::Model& model, double relative) {
  double size = 1.0;
  for (const model::Marker& mk : model.markers) {
    const model::Part& p = model.parts[mk.part];
    size = std::max(size, (p.position + p.orientation * mk.position).norm());
  }
  return relative * size;
}

std::optional<RedundantViolation> violatedRedundantEquation(const MultibodySystem& system,
                                                            double t, const double* y,
                                                            double tolerance) {
  std::optional<RedundantViolation> worst;
  const auto& eqs = system.constraints().equations();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    if (eqs[k].active) continue;
    const double value = std::abs(system.constraintValue(k, t, y));
    // NaN counts as violated.
    if (!(value <= tolerance) && (!worst || !(value <= worst->value)))
      worst = RedundantViolation{k, value, tolerance};
  }
  return worst;
}

std::string describeViolation(const MultibodySystem& system, const RedundantViolation& v,
                              double t) {
  char buf[160];
  std::snprintf(buf, sizeof buf, " is violated by %.3E (tolerance %.3E) at time %.6E", v.value,
                v.tolerance, t);
  return system.constraints().describe(v.equation, system.model()) +
         ", removed as redundant at the start," + buf +
         ": the equations kept no longer imply it, so the mechanism does not hold together";
}

}  // namespace openmss::mechanics
