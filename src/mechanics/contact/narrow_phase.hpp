#pragma once
// Contact points between two solids of a CONTACT (docs/theory.md §6c, "Geometry"), templated
// on the scalar: the choices (which face, which vertex) are made on values, the depth, normal
// and point are computed on T so their partials are exact between switches.
// Analytic pairs: sphere-sphere, sphere-box (a box floor is the plane), box-box (the vertices
// of each box inside the other: exact for face-on-face and vertex-on-face contact); the pairs
// with a frustum (CYLINDER, FRUSTUM) are in frustum_narrow_phase.hpp, two frustums in
// frustum_pair_narrow_phase.hpp, a PLANE's in plane_narrow_phase.hpp; ellipsoids, tori, meshes
// and steep frustum pairs in curved_narrow_phase.hpp (analytic or FCL); the 2-D geometries of
// planar contact in planar_narrow_phase.hpp.

#include <algorithm>
#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/curved_narrow_phase.hpp"
#include "mechanics/contact/frustum_narrow_phase.hpp"
#include "mechanics/contact/frustum_pair_narrow_phase.hpp"
#include "mechanics/contact/planar_narrow_phase.hpp"
#include "mechanics/contact/plane_narrow_phase.hpp"

namespace openmss::mechanics::contact {

template <class T>
void sphereSphere(const model::ContactSolid& si, const SolidFrame<T>& fi,
                  const model::ContactSolid& sj, const SolidFrame<T>& fj,
                  std::vector<ContactPoint<T>>& out) {
  const V3<T> d = fi.p - fj.p;
  const double ri = si.size[0], rj = sj.size[0];
  const double dist = std::sqrt(valueOf(dot(d, d)));
  if (dist >= ri + rj || dist == 0.0) return;  // concentric spheres have no normal
  const T len = norm(d);
  const V3<T> n = d * (1.0 / len);
  const T depth = (ri + rj) - len;
  // Midway between the surface points fj.p + rj n and fi.p - ri n.
  out.push_back({(fj.p + fi.p + n * T(rj - ri)) * T(0.5), n, depth});
}

// Sphere s (centre c) against box b: normal from the box towards the sphere.
template <class T>
bool sphereBox(const model::ContactSolid& s, const SolidFrame<T>& fs, const model::ContactSolid& b,
               const SolidFrame<T>& fb, ContactPoint<T>& cp) {
  double lo[3], hi[3];
  boxBounds(b, lo, hi);
  const double r = s.size[0];
  const V3<T> q = fb.a.tmul(fs.p - fb.p);  // sphere centre in box axes
  bool inside = true;
  V3<T> closest = q;
  for (int k = 0; k < 3; ++k) {
    if (valueOf(q[k]) < lo[k]) {
      closest[k] = T(lo[k]);
      inside = false;
    } else if (valueOf(q[k]) > hi[k]) {
      closest[k] = T(hi[k]);
      inside = false;
    }
  }
  if (!inside) {
    const V3<T> d = q - closest;
    const double dist = std::sqrt(valueOf(dot(d, d)));
    if (dist >= r) return false;
    const T len = norm(d);
    const V3<T> n = fb.a * (d * (1.0 / len));
    const V3<T> surface = fb.p + fb.a * closest;
    cp = {(surface + fs.p - n * T(r)) * T(0.5), n, T(r) - len};
    return true;
  }
  // Centre inside the box: push out through the nearest face.
  int axis = 0;
  bool upper = true;
  double best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const double up = hi[k] - valueOf(q[k]), down = valueOf(q[k]) - lo[k];
    if (up < best) best = up, axis = k, upper = true;
    if (down < best) best = down, axis = k, upper = false;
  }
  const T gap = upper ? T(hi[axis]) - q[axis] : q[axis] - T(lo[axis]);
  const V3<T> n = upper ? fb.a.c[axis] : -fb.a.c[axis];
  cp = {fs.p + n * ((gap - T(r)) * 0.5), n, gap + r};
  return true;
}

// The vertices of box v inside box b: normal out of b's nearest face, depth to that face.
template <class T>
void verticesInBox(const model::ContactSolid& v, const SolidFrame<T>& fv,
                   const model::ContactSolid& b, const SolidFrame<T>& fb, bool flip,
                   std::vector<ContactPoint<T>>& out) {
  double lo[3], hi[3];
  boxBounds(b, lo, hi);
  for (int corner = 0; corner < 8; ++corner) {
    const V3<T> local((corner & 1) ? T(v.size[0]) : T(0.0), (corner & 2) ? T(v.size[1]) : T(0.0),
                      (corner & 4) ? T(v.size[2]) : T(0.0));
    const V3<T> x = fv.p + fv.a * local;
    const V3<T> q = fb.a.tmul(x - fb.p);
    int axis = -1;
    bool upper = true;
    double best = 1e300;
    for (int k = 0; k < 3 && best > 0.0; ++k) {
      const double up = hi[k] - valueOf(q[k]), down = valueOf(q[k]) - lo[k];
      if (up <= 0.0 || down <= 0.0) best = 0.0;  // outside
      if (up < best && up > 0.0) best = up, axis = k, upper = true;
      if (down < best && down > 0.0) best = down, axis = k, upper = false;
    }
    if (best <= 0.0 || axis < 0) continue;
    const T depth = upper ? T(hi[axis]) - q[axis] : q[axis] - T(lo[axis]);
    const V3<T> outward = upper ? fb.a.c[axis] : -fb.a.c[axis];
    // The force on the vertex's box pushes it out of b: along `outward`; the normal of the
    // contact points from J to I.
    out.push_back({x + outward * (depth * 0.5), flip ? -outward : outward, depth});
  }
}

// Every contact point between solid si (on I) and sj (on J). Returns false for a pair of
// shapes the analytic narrow phase does not cover (the builder refuses those first).
template <class T>
bool narrowPhase(const model::ContactSolid& si, const SolidFrame<T>& fi,
                 const model::ContactSolid& sj, const SolidFrame<T>& fj,
                 std::vector<ContactPoint<T>>& out) {
  using S = model::ContactSolid::Shape;
  if (model::planarShape(si.shape) || model::planarShape(sj.shape)) {  // 2-D contact
    planarNarrowPhase(si, fi, sj, fj, out);
    return true;
  }
  if (curvedPair(si, sj)) {
    curvedNarrowPhase(si, fi, sj, fj, out);
    return true;
  }
  if (si.shape == S::Plane || sj.shape == S::Plane) return planeNarrowPhase(si, fi, sj, fj, out);
  if (si.shape == S::Sphere && sj.shape == S::Sphere) {
    sphereSphere(si, fi, sj, fj, out);
  } else if (si.shape == S::Sphere && sj.shape == S::Box) {
    ContactPoint<T> cp;
    if (sphereBox(si, fi, sj, fj, cp)) out.push_back(cp);
  } else if (si.shape == S::Box && sj.shape == S::Sphere) {
    ContactPoint<T> cp;
    if (sphereBox(sj, fj, si, fi, cp)) {
      cp.normal = -cp.normal;
      out.push_back(cp);
    }
  } else if (si.shape == S::Box && sj.shape == S::Box) {
    verticesInBox(si, fi, sj, fj, false, out);
    verticesInBox(sj, fj, si, fi, true, out);
  } else if (si.shape == S::Sphere && sj.shape == S::Frustum) {
    ContactPoint<T> cp;
    if (sphereFrustum(si, fi, sj, fj, cp)) out.push_back(cp);
  } else if (si.shape == S::Frustum && sj.shape == S::Sphere) {
    ContactPoint<T> cp;
    if (sphereFrustum(sj, fj, si, fi, cp)) {
      cp.normal = -cp.normal;
      out.push_back(cp);
    }
  } else if (si.shape == S::Frustum && sj.shape == S::Box) {
    rimsInBox(si, fi, sj, fj, false, out);
    verticesInFrustum(sj, fj, si, fi, true, out);
  } else if (si.shape == S::Box && sj.shape == S::Frustum) {
    verticesInFrustum(si, fi, sj, fj, false, out);
    rimsInBox(sj, fj, si, fi, true, out);
  } else if (si.shape == S::Frustum && sj.shape == S::Frustum) {
    frustumFrustum(si, fi, sj, fj, false, out);
  } else {
    return false;
  }
  return true;
}

}  // namespace openmss::mechanics::contact
