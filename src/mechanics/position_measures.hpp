#pragma once
// Position-level marker measures (DX, DY, DZ, DM, AX, AY, AZ, PSI, THETA, PHI, YAW, PITCH,
// ROLL) as functions of marker frames, templated on the scalar so that constraint equations
// built from them (GCON) get exact first and second derivatives by forward-mode AD.

#include "common/dual.hpp"
#include "common/vec3.hpp"
#include "model/measure.hpp"

namespace openmss::mechanics {

// The measure of marker i (origin pi, axes ai) relative to marker j (pj, aj), components in
// the axes ak. Ground is the zero origin with identity axes. AX, AY and AZ are principal
// values in (-pi, pi] (the ADAMS/Solver function reference of AX, AY, AZ):
//   AX = atan2(-z_i.y_j, z_i.z_j), AY = atan2(z_i.x_j, z_i.z_j), AZ = atan2(x_i.y_j, x_i.x_j).
// Returns false for a kind that is not a position measure.
template <class S>
bool positionMeasure(model::MeasureKind kind, const V3<S>& pi, const M3<S>& ai, const V3<S>& pj,
                     const M3<S>& aj, const M3<S>& ak, S* out) {
  using K = model::MeasureKind;
  const V3<S> d = pi - pj;
  switch (kind) {
    case K::DX: *out = dot(d, ak.c[0]); return true;
    case K::DY: *out = dot(d, ak.c[1]); return true;
    case K::DZ: *out = dot(d, ak.c[2]); return true;
    case K::DM: *out = norm(d); return true;
    case K::AX: *out = atan2Of(-dot(ai.c[2], aj.c[1]), dot(ai.c[2], aj.c[2])); return true;
    case K::AY: *out = atan2Of(dot(ai.c[2], aj.c[0]), dot(ai.c[2], aj.c[2])); return true;
    case K::AZ: *out = atan2Of(dot(ai.c[0], aj.c[1]), dot(ai.c[0], aj.c[0])); return true;
    case K::PSI: case K::THETA: case K::PHI: {
      // Body 3-1-3 angles of I relative to J from R = A_J^T A_I; R(a, b) = (axis a of J).(axis
      // b of I).
      const S r22 = dot(aj.c[2], ai.c[2]);
      if (kind == K::THETA) *out = acosOf(r22);
      else if (kind == K::PSI) *out = atan2Of(dot(aj.c[0], ai.c[2]), -dot(aj.c[1], ai.c[2]));
      else *out = atan2Of(dot(aj.c[2], ai.c[0]), dot(aj.c[2], ai.c[1]));
      return true;
    }
    case K::YAW: case K::PITCH: case K::ROLL: {
      // Body 3-2-1 angles; PITCH is the negative of the second angle (ADAMS convention).
      if (kind == K::YAW) {
        *out = atan2Of(dot(aj.c[1], ai.c[0]), dot(aj.c[0], ai.c[0]));
      } else if (kind == K::ROLL) {
        *out = atan2Of(dot(aj.c[2], ai.c[1]), dot(aj.c[2], ai.c[2]));
      } else {
        const S r20 = dot(aj.c[2], ai.c[0]);
        const S r21 = dot(aj.c[2], ai.c[1]);
        const S r22 = dot(aj.c[2], ai.c[2]);
        *out = atan2Of(r20, sqrtOf(r21 * r21 + r22 * r22));
      }
      return true;
    }
    default:
      return false;
  }
}

}  // namespace openmss::mechanics
