#pragma once
// The contact of two planar CURVEs, for CVCV, the curve-to-curve constraint (docs/theory.md
// §5e). Curve I, c_i(alpha), lies in the x-y plane of marker IRM; curve J, c_j(beta), in the x-y
// plane of marker JRM. Everything is written in IRM's coordinates: curve J's point and tangent
// there are
//     p_j(beta) = o + R c_j(beta),   t_j(beta) = R c_j'(beta),
//     o = A_IRM^T (o_JRM - o_IRM),   R = A_IRM^T A_JRM.
// As for PTCV (common/curve_projection.hpp) the curve parameters are not unknowns of the DAE:
// at any configuration (alpha*, beta*) is the pair of points with a common normal, the root of
//     g_1 = (p_j - c_i) . c_i' = 0       (p_j lies on c_i's normal at alpha),
//     g_2 = z . (c_i' x t_j) = 0          (the tangents are parallel in the plane),
// and the constraint is the two components of the gap p_j - c_i(alpha*) normal to the tangent:
//     e_1 = (p_j - c_i) . n,  n = unit(z x c_i'),   e_2 = (p_j - c_i) . z,   z = z_IRM.
// In contact p_j = c_i and t_j is parallel to c_i', so the gradients of e_1, e_2 are the common
// normal and the plane's normal at the contact point: exactly the two degrees of freedom
// ADAMS's CVCV removes, and the reaction is a force along the common normal through the contact
// point (plus the out-of-plane force that keeps the curves in one plane).
//
// (alpha*, beta*) in double: the closest pair of a coarse sampling of both curves (in the plane),
// then Newton on (g_1, g_2) with steps limited to one sample interval. The 2x2 Newton matrix is
// regular unless the curves osculate (equal and opposite curvature at the contact: a circle
// rolling inside a circle of the same radius), where the contact point itself is undefined. On a
// dual scalar two Newton steps from the double root give the parameters' first and second
// derivatives exactly (implicit function theorem), as in curve_projection.hpp.

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include "common/curve_projection.hpp"

namespace openmss {

// One Newton step on (g_1, g_2) at (a, b) for curve J placed by (o, r): returns the step.
template <class S>
std::array<S, 2> curveContactStep(const BSplineCurve& ci, const BSplineCurve& cj, const V3<S>& o,
                                  const M3<S>& r, const S& a, const S& b) {
  const V3<S> c = curveDerivative(ci, a, 0), c1 = curveDerivative(ci, a, 1),
              c2 = curveDerivative(ci, a, 2);
  const V3<S> p = o + r * curveDerivative(cj, b, 0), t = r * curveDerivative(cj, b, 1),
              t1 = r * curveDerivative(cj, b, 2);
  const V3<S> d = p - c;
  const S g1 = dot(d, c1), g2 = c1.x * t.y - c1.y * t.x;
  const S g1a = dot(d, c2) - dot(c1, c1), g1b = dot(t, c1);
  const S g2a = c2.x * t.y - c2.y * t.x, g2b = c1.x * t1.y - c1.y * t1.x;
  const S det = g1a * g2b - g1b * g2a;
  return {-(g2b * g1 - g1b * g2) / det, -(g1a * g2 - g2a * g1) / det};
}

// Newton on (g_1, g_2) from a warm start (the parameters of the last accepted state), as
// localCurveParameter (curve_projection.hpp): accepted when it converges within 12 steps of at
// most one sample interval each, no farther than 4 intervals from the start.
inline bool localContactParameters(const BSplineCurve& ci, int samplesI, const BSplineCurve& cj,
                                   int samplesJ, const V3<double>& o, const M3<double>& r,
                                   const double* start, std::array<double, 2>& out) {
  const double stepA = (ci.maxParameter() - ci.minParameter()) / samplesI,
               stepB = (cj.maxParameter() - cj.minParameter()) / samplesJ;
  double a = start[0], b = start[1];
  bool closing = false;
  for (int it = 0; it < 12; ++it) {
    const std::array<double, 2> step = curveContactStep(ci, cj, o, r, a, b);
    if (!std::isfinite(step[0]) || !std::isfinite(step[1])) return false;
    const double da = std::max(-stepA, std::min(stepA, step[0]));
    const double db = std::max(-stepB, std::min(stepB, step[1]));
    a += da;
    b += db;
    if (std::abs(a - start[0]) > 4.0 * stepA || std::abs(b - start[1]) > 4.0 * stepB) return false;
    if (closing) {
      out = {a, b};
      return true;
    }
    closing =
        std::abs(da) < 1e-9 * (1.0 + std::abs(a)) && std::abs(db) < 1e-9 * (1.0 + std::abs(b));
  }
  return false;
}

// The contact parameters (alpha*, beta*) in double (see above): from the warm start (two
// values) when given (finite) and accepted, otherwise by the global search. `samplesI`,
// `samplesJ`: the coarse sampling of each curve over [-1, 1]. Deterministic: fixed samples and
// iterations.
inline std::array<double, 2> curveContactParameters(const BSplineCurve& ci, int samplesI,
                                                    const BSplineCurve& cj, int samplesJ,
                                                    const V3<double>& o, const M3<double>& r,
                                                    const double* warm = nullptr) {
  if (warm && std::isfinite(warm[0]) && std::isfinite(warm[1])) {
    std::array<double, 2> ab{};
    if (localContactParameters(ci, samplesI, cj, samplesJ, o, r, warm, ab)) return ab;
  }
  // Samples over each curve's parameter range (-1..1, or a user curve's MINPAR..MAXPAR).
  const double a0 = ci.minParameter(), spanA = ci.maxParameter() - a0;
  const double b0 = cj.minParameter(), spanB = cj.maxParameter() - b0;
  std::vector<V3<double>> pj(samplesJ + 1);
  for (int s = 0; s <= samplesJ; ++s)
    pj[s] = o + r * curveDerivative(cj, b0 + spanB * s / samplesJ, 0);
  double bestA = a0, bestB = b0, best = INFINITY;
  for (int s = 0; s <= samplesI; ++s) {
    const double a = a0 + spanA * s / samplesI;
    const V3<double> c = curveDerivative(ci, a, 0);
    for (int u = 0; u <= samplesJ; ++u) {
      const double dx = pj[u].x - c.x, dy = pj[u].y - c.y, d2 = dx * dx + dy * dy;
      if (d2 < best) {
        best = d2;
        bestA = a;
        bestB = b0 + spanB * u / samplesJ;
      }
    }
  }
  const double stepA = spanA / samplesI, stepB = spanB / samplesJ;
  double a = bestA, b = bestB;
  for (int it = 0; it < 50; ++it) {
    const std::array<double, 2> step = curveContactStep(ci, cj, o, r, a, b);
    if (!std::isfinite(step[0]) || !std::isfinite(step[1])) break;  // osculating: keep samples
    const double da = std::max(-stepA, std::min(stepA, step[0]));
    const double db = std::max(-stepB, std::min(stepB, step[1]));
    a += da;
    b += db;
    if (std::abs(da) < 1e-15 * (1.0 + std::abs(a)) && std::abs(db) < 1e-15 * (1.0 + std::abs(b)))
      break;
  }
  return {a, b};
}

// The two equations e_1, e_2 of a CVCV for the frames of IRM (pi, ai) and JRM (pj, aj), any
// scalar; `parameters` (optional) receives (alpha*, beta*).
template <class S>
std::array<S, 2> curveCurveResiduals(const BSplineCurve& ci, int samplesI, const BSplineCurve& cj,
                                     int samplesJ, const V3<S>& pi, const M3<S>& ai,
                                     const V3<S>& pj, const M3<S>& aj, const double* warm = nullptr,
                                     std::array<double, 2>* parameters = nullptr) {
  const V3<S> o = ai.tmul(pj - pi);
  const M3<S> r{{ai.tmul(aj.c[0]), ai.tmul(aj.c[1]), ai.tmul(aj.c[2])}};
  const V3<double> o0(valueOf(o.x), valueOf(o.y), valueOf(o.z));
  M3<double> r0;
  for (int k = 0; k < 3; ++k)
    r0.c[k] = V3<double>(valueOf(r.c[k].x), valueOf(r.c[k].y), valueOf(r.c[k].z));
  const std::array<double, 2> ab = curveContactParameters(ci, samplesI, cj, samplesJ, o0, r0, warm);
  if (parameters) *parameters = ab;
  S a(ab[0]), b(ab[1]);
  if constexpr (!std::is_same_v<S, double>) {
    for (int step = 0; step < 2; ++step) {  // exact first and second derivatives of (a*, b*)
      const std::array<S, 2> d = curveContactStep(ci, cj, o, r, a, b);
      a = a + d[0];
      b = b + d[1];
    }
  }
  const V3<S> c = curveDerivative(ci, a, 0), c1 = curveDerivative(ci, a, 1);
  const V3<S> d = o + r * curveDerivative(cj, b, 0) - c;
  const S length = sqrtOf(c1.x * c1.x + c1.y * c1.y);
  return {(d.y * c1.x - d.x * c1.y) / length, d.z};
}

}  // namespace openmss
