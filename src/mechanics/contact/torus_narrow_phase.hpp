#pragma once
// Contact points of a TORUS against a BOX and an EXTERNAL mesh (docs/theory.md §6c, "Torus
// against a box and a mesh"). The torus is the set of points within the tube radius r of its
// centre circle (radius R about the CM marker's z axis), so a point's depth into it is
// r - (distance to the centre circle), closed form. Templated on the scalar like
// narrow_phase.hpp: choices on values, depth, normal and point on T (exact partials between
// switches).
// - Box faces: the centre circle sampled as a rim (rimSamplesInHalfSpace) against each face's
//   half-space raised by r, each sample the ball of radius r about its circle point; a sample
//   counts for the face when the ball's deepest point lies inside the box with that face the
//   nearest (the vertex rule of verticesInBox, per sample). Exact at the deepest sample.
// - Box vertices and mesh vertices inside the torus: one point each, exact.
// - Box edges: the edge points nearest the centre circle (the local minima of the distance
//   along the edge, 1-D Newton on values, one Newton step on T for exact partials), when the
//   circle point lies beyond both faces of the edge (the edge's region, as sphereBox clamps a
//   sphere's centre to an edge). Exact.

#include <algorithm>
#include <cmath>
#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/fcl_narrow_phase.hpp"
#include "mechanics/contact/frustum_narrow_phase.hpp"

namespace openmss::mechanics::contact {

// Point x against the torus (frame ft, radii R = size[0], r = size[1]): true when x lies
// inside. `normal` points out of the torus (from the centre circle through x), `depth` is
// r - distance to the centre circle. On the axis every circle point is nearest: the marker's
// x axis picks one (as torusSphere); a point on the centre circle has no normal (skipped).
template <class T>
bool pointInTorus(const V3<T>& x, const model::ContactSolid& t, const SolidFrame<T>& ft,
                  V3<T>& normal, T& depth) {
  const double big = t.size[0], tube = t.size[1];
  const V3<T> axis = ft.a.c[2];
  const V3<T> rel = x - ft.p;
  const V3<T> planar = rel - axis * dot(rel, axis);
  const double p2 = valueOf(dot(planar, planar));
  const V3<T> radial = p2 > 1e-30 ? planar * (1.0 / norm(planar)) : ft.a.c[0];
  const V3<T> d = x - (ft.p + radial * T(big));
  const double dist = std::sqrt(valueOf(dot(d, d)));
  if (dist >= tube || dist == 0.0) return false;
  const T len = norm(d);
  normal = d * (1.0 / len);
  depth = T(tube) - len;
  return true;
}

// Appends x as a contact point when it lies inside the torus; `torusOnI` orients the normal
// (from J's solid towards I's).
template <class T>
void pointIntoTorus(const V3<T>& x, const model::ContactSolid& t, const SolidFrame<T>& ft,
                    bool torusOnI, std::vector<ContactPoint<T>>& out) {
  V3<T> n;
  T depth;
  if (!pointInTorus(x, t, ft, n, depth)) return;
  out.push_back({x + n * (depth * 0.5), torusOnI ? -n : n, depth});
}

// Whether q (box axes) lies inside box [lo, hi] with `face` (2 k + upper) the nearest face,
// its distance below that face being `own` (the sample's depth, exact where q's own rounding
// could put a point entering at depth 1e-17 outside: the samples then stay the PLANE's).
inline bool insideNearest(const double q[3], const double lo[3], const double hi[3], int face,
                          double own) {
  double gaps[6];
  for (int k = 0; k < 3; ++k) gaps[2 * k] = q[k] - lo[k], gaps[2 * k + 1] = hi[k] - q[k];
  gaps[face] = own;
  for (int k = 0; k < 6; ++k)
    if (gaps[k] <= 0.0 || (k != face && gaps[k] < own)) return false;
  return true;
}

// The centre circle of torus t sampled against the six faces of box b (see the file comment).
template <class T>
void torusOnBoxFaces(const model::ContactSolid& t, const SolidFrame<T>& ft,
                     const model::ContactSolid& b, const SolidFrame<T>& fb, bool torusOnI,
                     std::vector<ContactPoint<T>>& out) {
  const double big = t.size[0], tube = t.size[1];
  double lo[3], hi[3];
  boxBounds(b, lo, hi);
  const SolidFrame<double> vb = valueFrame(fb);
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    const V3<T> nf = upper ? fb.a.c[axis] : -fb.a.c[axis];
    const T hf = dot(nf, fb.p) + (upper ? hi[axis] : -lo[axis]);
    const size_t first = out.size();
    // As torusPlane: the circle against the half-space raised by the tube radius, each
    // sample's point moved onto the tube (the ball's deepest point, plus half the depth).
    rimSamplesInHalfSpace(ft.p, big, ft.a.c[2], ft.a.c[0], nf, hf + tube, !torusOnI, out);
    size_t kept = first;
    for (size_t k = first; k < out.size(); ++k) {
      out[k].point -= nf * T(tube);
      const V3<T> deepest = out[k].point - nf * (out[k].depth * 0.5);
      const V3<double> q =
          vb.a.tmul(V3<double>(valueOf(deepest.x), valueOf(deepest.y), valueOf(deepest.z)) - vb.p);
      const double qa[3] = {q.x, q.y, q.z};
      if (insideNearest(qa, lo, hi, face, valueOf(out[k].depth))) out[kept++] = out[k];
    }
    const bool dropped = kept < out.size();
    out.resize(kept);
    if (!dropped) continue;  // the rim's own shares stand (the same bits as on a PLANE)
    T total(0.0);
    for (size_t k = first; k < kept; ++k) total += out[k].depth;
    for (size_t k = first; k < kept; ++k) out[k].weight = out[k].depth / total;
  }
}

// Distance squared from a point rel(s) (relative to the circle's centre) to the circle of
// radius R about the unit axis a, and its first two derivatives in s, given rel's derivatives
// d1 and d2: f = |rel|^2 - 2 R rho + R^2 with rho the distance from the axis (theory §6c,
// "Torus against a box and a mesh"). False where rho vanishes (on the axis).
template <class T>
bool circleDistance2(const V3<T>& rel, const V3<T>& d1, const V3<T>& d2, const V3<T>& a, double big,
                     T& f, T& f1, T& f2) {
  const T z = dot(rel, a), z1 = dot(d1, a), z2 = dot(d2, a), rr = dot(rel, rel);
  const T rho2 = rr - z * z;
  if (valueOf(rho2) < 1e-24) return false;
  const T rho = sqrtOf(rho2);
  const T rd1 = dot(rel, d1), curv = dot(d1, d1) + dot(rel, d2);
  const T rho1 = (rd1 - z * z1) / rho;
  const T rhoTwo = (curv - z1 * z1 - z * z2 - rho1 * rho1) / rho;
  f = rr - 2.0 * big * rho + big * big;
  f1 = 2.0 * rd1 - 2.0 * big * rho1;
  f2 = 2.0 * curv - 2.0 * big * rhoTwo;
  return true;
}

// The same along the line rel0 + s e.
template <class T>
bool lineCircleDistance2(const V3<T>& rel0, const V3<T>& e, const V3<T>& a, double big, const T& s,
                         T& f, T& f1, T& f2) {
  return circleDistance2(rel0 + e * s, e, V3<T>(), a, big, f, f1, f2);
}

// Coarse samples of the distance along a box edge (within the torus's bounding sphere) that
// bracket its local minima before Newton: a line meets a circle's distance function in at most
// two minima, and each lies within a sample spacing of one of these.
inline constexpr int kEdgeSamples = 16;

// The parameters s in (0, 1) of the local minima of the distance from the edge A + s e to the
// centre circle, on values (coarse samples, then Newton on f' = 0).
inline void edgeMinima(const V3<double>& rel0, const V3<double>& e, const V3<double>& a, double big,
                       double reach, std::vector<double>& found) {
  // The part of the edge within the bounding sphere |rel| <= reach (R + r).
  const double qa = dot(e, e), qb = dot(rel0, e), qc = dot(rel0, rel0) - reach * reach;
  const double disc = qb * qb - qa * qc;
  if (qa <= 0.0 || disc <= 0.0) return;
  const double root = std::sqrt(disc);
  const double sLo = std::max(0.0, (-qb - root) / qa), sHi = std::min(1.0, (-qb + root) / qa);
  if (!(sLo < sHi)) return;
  double fs[kEdgeSamples];
  double ss[kEdgeSamples];
  for (int k = 0; k < kEdgeSamples; ++k) {
    ss[k] = sLo + (sHi - sLo) * k / (kEdgeSamples - 1);
    double f1, f2;
    if (!lineCircleDistance2(rel0, e, a, big, ss[k], fs[k], f1, f2)) fs[k] = HUGE_VAL;
  }
  for (int k = 0; k < kEdgeSamples; ++k) {
    if ((k > 0 && fs[k] > fs[k - 1]) || (k + 1 < kEdgeSamples && fs[k] >= fs[k + 1])) continue;
    double s = ss[k];
    bool convex = false;
    for (int it = 0; it < 50; ++it) {
      double f, f1, f2;
      convex = lineCircleDistance2(rel0, e, a, big, s, f, f1, f2) && f2 > 0.0;
      if (!convex) break;
      const double next = std::clamp(s - f1 / f2, sLo, sHi);
      const bool done = std::abs(next - s) <= 1e-15 * (1.0 + std::abs(s));
      s = next;
      if (done) break;
    }
    if (!convex || s <= 0.0 || s >= 1.0) continue;
    if (std::none_of(found.begin(), found.end(), [s](double o) { return std::abs(o - s) < 1e-9; }))
      found.push_back(s);
  }
}

// The twelve edges of box b against torus t: each edge point nearest the centre circle (a
// local minimum of the distance) inside the tube, strictly between the edge's ends (the ends
// are vertices) and with its circle point beyond both faces of the edge.
template <class T>
void boxEdgesInTorus(const model::ContactSolid& b, const SolidFrame<T>& fb,
                     const model::ContactSolid& t, const SolidFrame<T>& ft, bool torusOnI,
                     std::vector<ContactPoint<T>>& out) {
  const double big = t.size[0], tube = t.size[1];
  double lo[3], hi[3];
  boxBounds(b, lo, hi);
  const SolidFrame<double> vb = valueFrame(fb), vt = valueFrame(ft);
  for (int axis = 0; axis < 3; ++axis) {
    const int m1 = (axis + 1) % 3, m2 = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      double local[3];
      local[axis] = 0.0;
      local[m1] = corner & 1 ? b.size[m1] : 0.0;
      local[m2] = corner & 2 ? b.size[m2] : 0.0;
      const V3<double> start = vb.p + vb.a * V3<double>(local[0], local[1], local[2]);
      const V3<double> e = vb.a.c[axis] * b.size[axis];
      std::vector<double> minima;
      edgeMinima(start - vt.p, e, vt.a.c[2], big, big + tube, minima);
      for (const double s0 : minima) {
        const V3<T> startT = fb.p + fb.a * V3<T>(T(local[0]), T(local[1]), T(local[2]));
        const V3<T> eT = fb.a.c[axis] * b.size[axis];
        // One Newton step on T from the converged value: its value is s0 to rounding and its
        // partials are the implicit function's, -(df'/dq) / f'' (theory §6c).
        T f, f1, f2;
        if (!lineCircleDistance2(startT - ft.p, eT, ft.a.c[2], big, T(s0), f, f1, f2)) continue;
        const T s = s0 - f1 / f2;
        const V3<T> x = startT + eT * s;
        V3<T> n;
        T depth;
        if (!pointInTorus(x, t, ft, n, depth)) continue;
        // The circle point x - n (r - depth) must lie in the edge's region: beyond both faces.
        const V3<T> centre = x - n * (T(tube) - depth);
        const V3<double> q =
            vb.a.tmul(V3<double>(valueOf(centre.x), valueOf(centre.y), valueOf(centre.z)) - vb.p);
        auto beyond = [&](int k) {
          const double v = local[k], qk = q[k];
          return v == hi[k] ? qk > hi[k] : qk < lo[k];
        };
        if (!beyond(m1) || !beyond(m2)) continue;
        out.push_back({x + n * (depth * 0.5), torusOnI ? -n : n, depth});
      }
    }
  }
}

// Torus t against box b: face samples, box vertices inside the torus and box edges.
template <class T>
void torusBox(const model::ContactSolid& t, const SolidFrame<T>& ft, const model::ContactSolid& b,
              const SolidFrame<T>& fb, bool torusOnI, std::vector<ContactPoint<T>>& out) {
  torusOnBoxFaces(t, ft, b, fb, torusOnI, out);
  for (int corner = 0; corner < 8; ++corner) {
    const V3<T> local((corner & 1) ? T(b.size[0]) : T(0.0), (corner & 2) ? T(b.size[1]) : T(0.0),
                      (corner & 4) ? T(b.size[2]) : T(0.0));
    pointIntoTorus(fb.p + fb.a * local, t, ft, torusOnI, out);
  }
  boxEdgesInTorus(b, fb, t, ft, torusOnI, out);
}

// Torus t against mesh m: the mesh's vertices inside the torus, one point each (as
// meshVerticesBelowPlane), tested on values before any work on T.
template <class T>
void torusMesh(const model::ContactSolid& t, const SolidFrame<T>& ft, const model::ContactSolid& m,
               const SolidFrame<T>& fm, bool torusOnI, std::vector<ContactPoint<T>>& out) {
  const SolidFrame<double> vm = valueFrame(fm), vt = valueFrame(ft);
  const double reach = t.size[0] + t.size[1];
  for (const Eigen::Vector3d& v : m.mesh->vertices) {
    const V3<double> rel = vm.p + vm.a * V3<double>::from(v) - vt.p;
    if (dot(rel, rel) >= reach * reach) continue;  // outside the bounding sphere: most, cheaply
    pointIntoTorus(fm.p + fm.a * V3<T>::from(v), t, ft, torusOnI, out);
  }
}

}  // namespace openmss::mechanics::contact
