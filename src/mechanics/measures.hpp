#pragma once
// Values of the model measures that function expressions read (DX, DM, VR, WZ, ORIENT, ...),
// templated on the scalar so that force functions get exact derivatives through them.

#include <cmath>

#include "common/rotation.hpp"
#include "mechanics/orientation_measure.hpp"
#include "mechanics/pose.hpp"
#include "mechanics/analysis_status_measures.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/user_measures.hpp"
#include "model/measure.hpp"

namespace openmss::mechanics {

template <class T>
MarkerState<T> markerOrGround(const model::Model& m, const StateLayout& l, int marker,
                              const T* y) {
  if (marker >= 0) return markerState(m, l, marker, y);
  MarkerState<T> g;
  g.a = M3<T>::from(Eigen::Matrix3d::Identity().eval());
  return g;
}

// Position- and velocity-level measures. Returns false for kinds that need accelerations or
// reaction forces (those are evaluated by the output code from a solved state). `run` holds
// the references of the cumulative AX, AY, AZ (without it they are principal values).
template <class T>
bool kinematicMeasure(const model::Model& m, const StateLayout& l, const model::Measure& ms,
                      const T* y, T* out, const ExpressionRunState* run = nullptr) {
  using K = model::MeasureKind;
  if (userMeasure(m, l, ms, y, out, run)) return true;  // VARVAL, DIF, ARYVAL, ... read y
  if (analysisStatusMeasure(ms, out, run)) return true;  // MODE, HSIZE, ORDER, NJAC, NRHS
  const MarkerState<T> i = markerOrGround(m, l, ms.i, y);
  const MarkerState<T> j = markerOrGround(m, l, ms.j, y);
  const M3<T> k = ms.k >= 0 ? markerState(m, l, ms.k, y).a
                            : M3<T>::from(Eigen::Matrix3d::Identity().eval());
  const V3<T> d = i.p - j.p;
  // The time derivative of d in the frame of marker l (ground when absent):
  // v_l = d' - w_l x d (docs/theory.md §11b). VR does not depend on it.
  const V3<T> v = ms.l >= 0 ? (i.pdot - j.pdot) - cross(markerState(m, l, ms.l, y).w, d)
                            : i.pdot - j.pdot;
  const V3<T> w = i.w - j.w;
  switch (ms.kind) {
    case K::DX: *out = dot(d, k.c[0]); return true;
    case K::DY: *out = dot(d, k.c[1]); return true;
    case K::DZ: *out = dot(d, k.c[2]); return true;
    case K::DM: *out = norm(d); return true;
    case K::VX: *out = dot(v, k.c[0]); return true;
    case K::VY: *out = dot(v, k.c[1]); return true;
    case K::VZ: *out = dot(v, k.c[2]); return true;
    // |v| with a zero derivative at v = 0 (at rest; sqrt's derivative there would be 0/0).
    case K::VM: *out = valueOf(dot(v, v)) == 0.0 ? T(0.0) : norm(v); return true;
    case K::VR: *out = dot(i.pdot - j.pdot, d) / norm(d); return true;  // = (v_l . d)/|d|
    case K::WX: *out = dot(w, k.c[0]); return true;
    case K::WY: *out = dot(w, k.c[1]); return true;
    case K::WZ: *out = dot(w, k.c[2]); return true;
    case K::WM: *out = valueOf(dot(w, w)) == 0.0 ? T(0.0) : norm(w); return true;
    case K::PSI: case K::THETA: case K::PHI: {
      // Body 3-1-3 angles of I relative to J from R = A_J^T A_I.
      const M3<T> r = j.a.transpose() * i.a;
      if (ms.kind == K::THETA) *out = acosOf(r.at(2, 2));
      else if (ms.kind == K::PSI) *out = atan2Of(r.at(0, 2), -r.at(1, 2));
      else *out = atan2Of(r.at(2, 0), r.at(2, 1));
      return true;
    }
    case K::YAW: case K::PITCH: case K::ROLL: {
      // Body 3-2-1 angles; PITCH is the negative of the second angle (ADAMS convention).
      const M3<T> r = j.a.transpose() * i.a;
      if (ms.kind == K::YAW) *out = atan2Of(r.at(1, 0), r.at(0, 0));
      else if (ms.kind == K::ROLL) *out = atan2Of(r.at(2, 1), r.at(2, 2));
      else {
        const T s = r.at(2, 0);
        *out = atan2Of(s, sqrtOf(r.at(2, 1) * r.at(2, 1) + r.at(2, 2) * r.at(2, 2)));
      }
      return true;
    }
    case K::IncludedAngle: {
      // The angle between the line from I to J and the line from J to K (always >= 0).
      const V3<T> kp = markerOrGround(m, l, ms.k, y).p;
      const V3<T> a = j.p - i.p, b = kp - j.p;
      *out = acosOf(dot(a, b) / (norm(a) * norm(b)));
      return true;
    }
    case K::AX: case K::AY: case K::AZ: {
      // Cumulative (docs/theory.md §11a): the principal angle of position_measures.hpp plus the whole turns
      // counted from the run's last accepted value.
      const M3<T>& ai = i.a;
      const M3<T>& aj = j.a;
      const T principal =
          ms.kind == K::AX   ? atan2Of(-dot(ai.c[2], aj.c[1]), dot(ai.c[2], aj.c[2]))
          : ms.kind == K::AY ? atan2Of(dot(ai.c[2], aj.c[0]), dot(ai.c[2], aj.c[2]))
                             : atan2Of(dot(ai.c[0], aj.c[1]), dot(ai.c[0], aj.c[0]));
      *out = cumulativeAngle(principal, run != nullptr ? run->angleReference(ms) : nullptr);
      return true;
    }
    case K::Orient:  // on any scalar, so force functions get its derivatives
      return orientValue(j.a.transpose() * i.a, ms.code, ms.component, out);
    default:
      return false;
  }
}

}  // namespace openmss::mechanics
