#pragma once
// The pieces every narrow-phase routine of CONTACT shares (docs/theory.md §6c): a solid's
// reference frame and one contact point, templated on the scalar.

#include <algorithm>

#include "common/vec3.hpp"
#include "model/contact.hpp"

namespace openmss::mechanics::contact {

// A solid's reference marker in ground: origin and axes.
template <class T>
struct SolidFrame {
  V3<T> p;
  M3<T> a;
};

template <class T>
struct ContactPoint {
  V3<T> point;   // where the force acts, midway between the two surfaces
  V3<T> normal;  // unit, from J's solid towards I's (the normal force pushes I along it)
  T depth;       // penetration, > 0
  // Share of the normal law's force this point carries (theory §6c, "Rim samples"): 1 for a
  // point that is a contact of its own; the depth-weighted share d_k / sum d_j for the samples
  // of one rim, so that the samples together carry one force of their region.
  T weight = T(1.0);
};

// The box's extents along each axis of its corner frame: [lo, hi] (X, Y, Z may be negative).
inline void boxBounds(const model::ContactSolid& b, double lo[3], double hi[3]) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(0.0, b.size[k]);
    hi[k] = std::max(0.0, b.size[k]);
  }
}

}  // namespace openmss::mechanics::contact
