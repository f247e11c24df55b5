#pragma once
// Contact points of the 2-D geometries of planar contact (docs/theory.md §6c, "2-D contact"):
// CIRCLE and ARC (a disc, or a hole when flipped), POINT and CURVE, all in one plane. Each pair
// gives at most one point, computed in the plane of its circle or curve, with a normal in that
// plane; the forces then come from the same normal and friction laws as the 3-D contacts
// (contact_loads.hpp). Choices (which side, inside the arc's sweep, beyond a curve's end) on
// values; depth, normal and point on T (exact partials between switches; a curve's nearest
// parameter by Newton steps on T from its value, as PTCV's, common/curve_projection.hpp).

#include <cmath>
#include <numbers>
#include <type_traits>
#include <vector>

#include "common/curve_projection.hpp"
#include "mechanics/contact/contact_point.hpp"

namespace openmss::mechanics::contact {

// Radius and side of a circle-like geometry: a POINT is a disc of radius 0; side +1 for a disc
// (material inside), -1 for a hole (material outside).
inline double planarRadius(const model::ContactSolid& s) {
  return s.shape == model::ContactSolid::Shape::Point ? 0.0 : s.size[0];
}
inline double planarSide(const model::ContactSolid& s) { return s.flipped ? -1.0 : 1.0; }

// Whether the unit direction u (from an ARC's centre, in its plane) lies within its sweep of
// size[1] radians from its marker's x axis (negative: clockwise about z). On values.
template <class T>
bool withinSweep(const model::ContactSolid& s, const SolidFrame<T>& f, const V3<T>& u) {
  const double sweep = s.size[1], turn = 2.0 * std::numbers::pi;
  if (s.shape != model::ContactSolid::Shape::Circle || std::abs(sweep) >= turn) return true;
  double angle = std::atan2(valueOf(dot(u, f.a.c[1])), valueOf(dot(u, f.a.c[0])));
  if (sweep < 0.0) angle = -angle;  // measured along the sweep
  if (angle < 0.0) angle += turn;
  return angle <= std::abs(sweep);
}

// Circle or point si (I) against circle or point sj (J), in the plane of normal z: disc on
// disc, or a disc (point) against a hole. With d the centres' offset in the plane and
// sigma = +1 for two discs, -1 with a hole: depth = s_I r_I + s_J r_J - sigma |d|, normal
// sigma d/|d| (from J towards I), the point midway between the two circles along it.
template <class T>
void circleCircle(const model::ContactSolid& si, const SolidFrame<T>& fi,
                  const model::ContactSolid& sj, const SolidFrame<T>& fj, const V3<T>& z,
                  std::vector<ContactPoint<T>>& out) {
  const double ri = planarRadius(si), rj = planarRadius(sj);
  const double side_i = planarSide(si), side_j = planarSide(sj);
  const double sigma = side_i * side_j;  // the builder refuses two holes
  V3<T> d = fi.p - fj.p;
  d = d - z * dot(d, z);
  const double dist = std::sqrt(valueOf(dot(d, d)));
  const double reach = side_i * ri + side_j * rj;          // depth at zero offset
  if (dist == 0.0 || reach - sigma * dist <= 0.0) return;  // concentric: no normal
  const T len = norm(d);
  const V3<T> n = d * (sigma / len);
  const V3<T> onI = fi.p - n * T(side_i * ri), onJ = fj.p + n * T(side_j * rj);
  if (!withinSweep(si, fi, n * T(-side_i)) || !withinSweep(sj, fj, n * T(side_j))) return;
  out.push_back({(onI + onJ) * T(0.5), n, T(reach) - len * sigma});
}

// Disc or point c against curve k: the curve point nearest c's centre (in the curve's CRM
// axes), its outward normal t x z (t the unit tangent; -(t x z) when flipped), the signed
// distance s of the centre along it and depth r - s. `curveOnJ`: the normal from J towards I
// is the outward normal, else its opposite. Beyond the end of an open curve: no contact.
template <class T>
void circleCurve(const model::ContactSolid& c, const SolidFrame<T>& fc,
                 const model::ContactSolid& k, const SolidFrame<T>& fk, bool curveOnJ,
                 std::vector<ContactPoint<T>>& out) {
  const BSplineCurve& curve = *k.curve;
  const V3<T> q = fk.a.tmul(fc.p - fk.p);
  const V3<double> q0(valueOf(q.x), valueOf(q.y), 0.0);
  const double a0 = nearestCurveParameter(curve, q0, k.curveSamples);
  if (!curve.closed() && (a0 < curve.minParameter() || a0 > curve.maxParameter())) return;
  T alpha(a0);
  const V3<T> qp(q.x, q.y, T(0.0));  // the centre in the curve's plane
  if constexpr (!std::is_same_v<T, double>) {
    for (int step = 0; step < 2; ++step) {  // exact first and second derivatives of alpha*
      const V3<T> p = curveDerivative(curve, alpha, 0), p1 = curveDerivative(curve, alpha, 1),
                  p2 = curveDerivative(curve, alpha, 2);
      alpha = alpha - dot(p - qp, p1) / (dot(p1, p1) + dot(p - qp, p2));
    }
  }
  const V3<T> p = curveDerivative(curve, alpha, 0), p1 = curveDerivative(curve, alpha, 1);
  const T speed = sqrtOf(p1.x * p1.x + p1.y * p1.y);
  const double side = k.flipped ? -1.0 : 1.0;
  const V3<T> outward(p1.y * (side / speed), p1.x * (-side / speed), T(0.0));  // t x z
  const T s = dot(qp - p, outward);
  const double r = planarRadius(c);
  if (r - valueOf(s) <= 0.0) return;
  const V3<T> n = fk.a * outward;  // ground axes
  const V3<T> onCurve = fk.p + fk.a * p, onCircle = fc.p - n * T(r);
  out.push_back({(onCurve + onCircle) * T(0.5), curveOnJ ? n : -n, T(r) - s});
}

// Every contact point of two 2-D geometries (the builder admits: circle or point against
// circle or point, not two points nor two holes; a disc or point against a curve).
template <class T>
void planarNarrowPhase(const model::ContactSolid& si, const SolidFrame<T>& fi,
                       const model::ContactSolid& sj, const SolidFrame<T>& fj,
                       std::vector<ContactPoint<T>>& out) {
  using S = model::ContactSolid::Shape;
  if (sj.shape == S::Curve) {
    circleCurve(si, fi, sj, fj, true, out);
  } else if (si.shape == S::Curve) {
    circleCurve(sj, fj, si, fi, false, out);
  } else {
    // The plane's normal: the z axis of a circle's marker (a POINT's marker may be turned).
    circleCircle(si, fi, sj, fj, sj.shape == S::Circle ? fj.a.c[2] : fi.a.c[2], out);
  }
}

}  // namespace openmss::mechanics::contact
