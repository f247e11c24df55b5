#pragma once
// FRICTION(id, index) (docs/theory.md, "Joint friction", read-back table), ADAMS's indices:
//   1-3   friction force on the I marker's part along x, y, z of the joint's J marker
//   4-6   friction torque on it about x, y, z of J
//   7-12  friction coefficient along x, y, z and about x, y, z of J (signed: opposing the slip)
//   13    the effective coefficient in stiction (|mu| in the static regime, 0 when sliding)
//   14-16 slip velocity of I relative to J along x, y, z of J
//   17-19 relative angular velocity about x, y, z of J
//   20-22 creep along x, y, z of J (translational joints; rotational creep is in 7-12's units
//         of the radius and not reported)

#include <cmath>

#include "mechanics/expression_run_state.hpp"
#include "mechanics/friction/joint_friction.hpp"

namespace openmss::mechanics::friction {

// Index `index` of a friction result, on any scalar: the requests read it on double, force,
// VARIABLE and DIFF functions on the residual's scalar (ForceElements::readBack), so that the
// Newton matrix gets its exact partials (slip, creep, the joint's multipliers).
template <class T>
T frictionOutputOf(const FrictionResult<T>& r, int index) {
  const FrictionKinematics<T>& k = r.kinematics;
  if (index >= 1 && index <= 3) return r.forceJ[index - 1];
  if (index >= 4 && index <= 6) return r.torqueJ[index - 4];
  if (index >= 7 && index <= 12) return r.mu[index - 7];
  if (index == 13) {
    if (!r.active || r.regime != 0) return T(0.0);
    T mu2(0.0);
    for (const T& mu : r.mu) mu2 = mu2 + mu * mu;
    // |mu| is not differentiable at 0; there the coefficient and its slope read as 0.
    return valueOf(mu2) > 0.0 ? sqrtOf(mu2) : T(0.0);
  }
  if (index >= 14 && index <= 16) return k.slip[index - 14];
  if (index >= 17 && index <= 19) return k.slip[index - 14] / k.channels.radius;
  if (index >= 20 && index <= 22) return k.creep[index - 20];
  return T(0.0);
}

inline double frictionOutput(const model::Model& m, const StateLayout& l,
                             const ConstraintSet* constraints, const ExpressionRunState* run,
                             int friction, int index, const double* y) {
  const FrictionAnchor* anchor = run != nullptr ? run->frictionAnchor(friction) : nullptr;
  const model::AnalysisMode mode =
      run != nullptr ? run->status().mode : model::AnalysisStatus{}.mode;
  return frictionOutputOf(frictionLoads(m, l, constraints, friction, y, anchor, mode), index);
}

}  // namespace openmss::mechanics::friction
