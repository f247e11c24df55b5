#pragma once
// Contact points between two frustums (GRAPHICS CYLINDER or FRUSTUM against CYLINDER or
// FRUSTUM), side against side (docs/theory.md §6c, "Frustum against frustum"). Templated on the
// scalar like narrow_phase.hpp: the regime and the stations are chosen on values, depth, normal
// and point are computed on T.
// - Parallel axes (|a x b| <= kParallelAxes): line contact. The stations are the two ends of
//   the stretch of A's axis that B spans; at each, the section perpendicular to the axes holds
//   two discs, whose overlap rA + rB - D is the station's depth (one contact point per end, as
//   a cylinder lying on a floor has one per rim).
// - Crossed axes: one point on the common perpendicular of the axes, when its feet lie inside
//   both solids' lengths: depth rA(t) + rB(s) - D, exact for two cylinders.
// Rim against side, face against face and the feet beyond an end are not covered (theory §6c).

#include <cmath>
#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/frustum_narrow_phase.hpp"

namespace openmss::mechanics::contact {

// Sine of the angle between the axes below which two frustums are treated as parallel: the
// distance between the axes then changes by at most 1e-3 of the length along the contact.
inline constexpr double kParallelAxes = 1e-3;

// Radius of frustum g at axial coordinate z (measured from its bottom along g.a).
template <class T>
T frustumRadiusAt(const FrustumGeometry<T>& g, const T& z) {
  return g.rb + (z * (1.0 / g.h)) * (g.rt - g.rb);
}

// The section of A and B through A's axis point at coordinate t (on A's axis): the depth
// rA(t) + rB(s) - D with s the axial coordinate of that point on B and D its distance from B's
// axis; the normal from B towards A. False when the discs do not overlap or the point is on
// B's axis (no normal).
template <class T>
bool frustumSection(const FrustumGeometry<T>& ga, const FrustumGeometry<T>& gb, const T& t,
                    bool flip, std::vector<ContactPoint<T>>& out) {
  const V3<T> x = ga.p + ga.a * t;
  const V3<T> rel = x - gb.p;
  const T s = dot(rel, gb.a);  // inside B's length: the callers choose t so
  const V3<T> radial = rel - gb.a * s;
  const double d2 = valueOf(dot(radial, radial));
  if (d2 < 1e-30) return false;
  const T dist = norm(radial);
  const T ra = frustumRadiusAt(ga, t), rb = frustumRadiusAt(gb, s);
  const T depth = ra + rb - dist;
  if (valueOf(depth) <= 0.0) return false;
  const V3<T> n = radial * (1.0 / dist);  // from B's axis towards A's
  // Midway between A's surface point x - n rA and B's gb.p + gb.a s + n rB.
  const V3<T> point = (x - n * ra + gb.p + gb.a * s + n * rb) * T(0.5);
  out.push_back({point, flip ? -n : n, depth});
  return true;
}

// Frustum A (solid ca) against frustum B (solid cb); the normal from B towards A (flip:
// negated, for A on the J side).
template <class T>
void frustumFrustum(const model::ContactSolid& ca, const SolidFrame<T>& fa,
                    const model::ContactSolid& cb, const SolidFrame<T>& fb, bool flip,
                    std::vector<ContactPoint<T>>& out) {
  const FrustumGeometry<T> ga = frustumGeometry(ca, fa), gb = frustumGeometry(cb, fb);
  const V3<T> axb = cross(ga.a, gb.a);
  const double sin2 = valueOf(dot(axb, axb));
  if (sin2 <= kParallelAxes * kParallelAxes) {
    // B's ends projected on A's axis; the stations are the ends of their overlap with [0, hA].
    const T z0 = dot(gb.p - ga.p, ga.a);
    const T z1 = z0 + dot(gb.a, ga.a) * gb.h;
    const bool rising = valueOf(z1) >= valueOf(z0);
    const T lo = rising ? z0 : z1, hi = rising ? z1 : z0;
    const T t0 = valueOf(lo) > 0.0 ? lo : T(0.0);
    const T t1 = valueOf(hi) < ga.h ? hi : T(ga.h);
    if (valueOf(t1) <= valueOf(t0)) return;
    frustumSection(ga, gb, t0, flip, out);
    frustumSection(ga, gb, t1, flip, out);
    return;
  }
  // Crossed: the feet of the common perpendicular, A's at t, B's at s.
  const V3<T> w = ga.p - gb.p;
  const T c = dot(ga.a, gb.a), d = dot(ga.a, w), e = dot(gb.a, w);
  const T denom = 1.0 - c * c;
  const T t = (c * e - d) / denom;
  const T s = (e - c * d) / denom;
  if (valueOf(t) <= 0.0 || valueOf(t) >= ga.h || valueOf(s) <= 0.0 || valueOf(s) >= gb.h) return;
  frustumSection(ga, gb, t, flip, out);
}

}  // namespace openmss::mechanics::contact
