#pragma once
// Parts with no mass or with zero principal moments (docs/theory.md, "Parts as ADAMS accepts
// them"): the equations of motion M u' + C^T lambda = Q, C u' = gamma determine u' and lambda
// only if no motion allowed by the constraints (C u = 0) carries zero inertia (M u = 0). The
// motions with zero inertia are few and known per body, so the test is the rank of C restricted
// to them: C E, with E the unit motions spanning the null space of M.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

struct UnheldMotion {
  int body = -1;          // moving body index
  bool rotation = false;  // a rotation about `axis` (body axes) or a translation along it (ground)
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
};

// The zero-inertia motions the active constraints at y leave free, one per independent free
// motion: the body and kind the rank-revealing LU leaves without a pivot, the kernel's axis. Empty when M is positive definite on the
// null space of C, which is always the case for bodies with positive mass and inertia.
std::vector<UnheldMotion> unheldMasslessMotions(const MultibodySystem& system, const double* y);

// "a translation along (1, 0, 0) in ground axes" / "a rotation about (0, 0, 1) in its CM axes".
std::string describeMotion(const UnheldMotion& motion);

}  // namespace openmss::mechanics
