#pragma once
// Contact points of a frustum (GRAPHICS CYLINDER or FRUSTUM: a solid of revolution about the
// reference marker's z axis) against spheres, box vertices and box faces (docs/theory.md §6c,
// "Frustum pairs"). Templated on the scalar like narrow_phase.hpp: choices (which edge of the
// meridian, which face) on values, depth, normal and point on T.
// - A point against the frustum: the closest point of its meridian trapezoid (rho, z) in the
//   half-plane through the axis and the point: exact, so a sphere against a cylinder or a
//   frustum is exact.
// - A rim circle of the frustum against a box face: the depth along the rim is
//   delta0 + rho cos(phi), closed form; the rim is sampled at fixed angles from its deepest
//   point, the samples inside sharing one force in proportion to their depths.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mechanics/contact/contact_point.hpp"

namespace openmss::mechanics::contact {

// The frustum in its own terms: axis unit a (towards the top), base centre p, height h > 0,
// bottom radius rb at p, top radius rt at p + h a. A negative LENGTH runs along -z.
template <class T>
struct FrustumGeometry {
  V3<T> p, a;
  double h, rb, rt;
};

template <class T>
FrustumGeometry<T> frustumGeometry(const model::ContactSolid& s, const SolidFrame<T>& f) {
  const double length = s.size[2];
  const V3<T> z = f.a.c[2];
  return {f.p, length < 0.0 ? -z : z, std::abs(length), s.size[0], s.size[1]};
}

// The closest point of the meridian segment A-B to P in (rho, z) coordinates.
template <class T>
void closestOnSegment(const T& pr, const T& pz, double ar, double az, double br, double bz, T& cr,
                      T& cz) {
  const double er = br - ar, ez = bz - az, len2 = er * er + ez * ez;
  const double s = len2 > 0.0 ? ((valueOf(pr) - ar) * er + (valueOf(pz) - az) * ez) / len2 : 0.0;
  if (s <= 0.0) {
    cr = T(ar), cz = T(az);
  } else if (s >= 1.0) {
    cr = T(br), cz = T(bz);
  } else {
    const T st = ((pr - ar) * er + (pz - az) * ez) * (1.0 / len2);
    cr = ar + st * er, cz = az + st * ez;
  }
}

// Point x against frustum g with a margin r (a sphere's radius; 0 for a vertex): true when the
// point lies within r of the solid. `normal` points out of the frustum, `depth` is the
// penetration (r - distance outside, r + depth of x inside) and `surface` the frustum's surface
// point nearest to x.
template <class T>
bool pointInFrustum(const V3<T>& x, const FrustumGeometry<T>& g, const V3<T>& fallbackRadial,
                    double r, V3<T>& normal, T& depth, V3<T>& surface) {
  const V3<T> rel = x - g.p;
  const T z = dot(rel, g.a);
  const V3<T> radial = rel - g.a * z;
  const double rho2 = valueOf(dot(radial, radial));
  // On the axis the radial direction is arbitrary: any perpendicular (the marker's x axis).
  const V3<T> e = rho2 > 1e-30 ? radial * (1.0 / norm(radial)) : fallbackRadial;
  const T rho = rho2 > 1e-30 ? norm(radial) : T(0.0);
  const double zv = valueOf(z), rv = valueOf(rho);
  const double side = g.rb + (g.rt - g.rb) * std::clamp(zv / g.h, 0.0, 1.0);
  const bool inside = zv > 0.0 && zv < g.h && rv < side;
  if (!inside) {
    // Closest of the bottom disc, the slanted side and the top disc of the meridian.
    T cr[3], cz[3];
    closestOnSegment(rho, z, 0.0, 0.0, g.rb, 0.0, cr[0], cz[0]);
    closestOnSegment(rho, z, g.rb, 0.0, g.rt, g.h, cr[1], cz[1]);
    closestOnSegment(rho, z, 0.0, g.h, g.rt, g.h, cr[2], cz[2]);
    int best = 0;
    double bestD = 1e300;
    for (int k = 0; k < 3; ++k) {
      const double dr = rv - valueOf(cr[k]), dz = zv - valueOf(cz[k]);
      if (dr * dr + dz * dz < bestD) bestD = dr * dr + dz * dz, best = k;
    }
    if (bestD >= r * r || bestD == 0.0) return false;
    const T dr = rho - cr[best], dz = z - cz[best];
    const T dist = sqrtOf(dr * dr + dz * dz);
    normal = (e * dr + g.a * dz) * (1.0 / dist);
    depth = r - dist;
    surface = g.p + e * cr[best] + g.a * cz[best];
    return true;
  }
  // Inside: leave through the nearest of bottom, top and side.
  const double slope = g.rt - g.rb, hyp = std::sqrt(slope * slope + g.h * g.h);
  const T sideGap = ((g.rb - rho) * g.h + z * slope) * (1.0 / hyp);  // distance to the side line
  const double gaps[3] = {zv, g.h - zv, valueOf(sideGap)};
  const int best = static_cast<int>(std::min_element(gaps, gaps + 3) - gaps);
  T gap;
  if (best == 0) {
    gap = z, normal = -g.a;
  } else if (best == 1) {
    gap = g.h - z, normal = g.a;
  } else {
    gap = sideGap, normal = e * (g.h / hyp) + g.a * (-slope / hyp);
  }
  depth = gap + r;
  surface = x + normal * gap;
  return true;
}

// Sphere s against frustum: the normal from the frustum towards the sphere.
template <class T>
bool sphereFrustum(const model::ContactSolid& s, const SolidFrame<T>& fs,
                   const model::ContactSolid& c, const SolidFrame<T>& fc, ContactPoint<T>& cp) {
  const FrustumGeometry<T> g = frustumGeometry(c, fc);
  const double r = s.size[0];
  V3<T> n, surface;
  T depth;
  if (!pointInFrustum(fs.p, g, fc.a.c[0], r, n, depth, surface)) return false;
  cp = {(surface + fs.p - n * T(r)) * T(0.5), n, depth};
  return true;
}

// The vertices of box v inside the frustum: normal out of the frustum (flip: negated).
template <class T>
void verticesInFrustum(const model::ContactSolid& v, const SolidFrame<T>& fv,
                       const model::ContactSolid& c, const SolidFrame<T>& fc, bool flip,
                       std::vector<ContactPoint<T>>& out) {
  const FrustumGeometry<T> g = frustumGeometry(c, fc);
  for (int corner = 0; corner < 8; ++corner) {
    const V3<T> local((corner & 1) ? T(v.size[0]) : T(0.0), (corner & 2) ? T(v.size[1]) : T(0.0),
                      (corner & 4) ? T(v.size[2]) : T(0.0));
    const V3<T> x = fv.p + fv.a * local;
    V3<T> n, surface;
    T depth;
    if (!pointInFrustum(x, g, fc.a.c[0], 0.0, n, depth, surface)) continue;
    out.push_back({x + n * (depth * 0.5), flip ? -n : n, depth});
  }
}

// Samples of one rim (theory §6c, "Rim samples"): 12, 30 degrees apart, enough for the
// samples of a rim lying flat on a face to carry its moment and damp its rocking.
inline constexpr int kRimSamples = 12;

// One rim circle (centre c, radius R, axis a, `fallback` a unit perpendicular to a) against
// the half-space depth(x) = hf - nf.x > 0. Along the rim the depth is delta0 + rho cos(phi),
// phi from the deepest direction u, rho = R |nf - (nf.a) a|. The rim is sampled at
// phi_k = 2 pi k / kRimSamples from u; every sample inside is a contact point at the rim point,
// carrying the share d_k / sum d_j of one force (ContactPoint::weight). Appends the samples
// inside (none when the whole rim is outside) with the normal nf (flip: negated).
template <class T>
void rimSamplesInHalfSpace(const V3<T>& c, double radius, const V3<T>& a, const V3<T>& fallback,
                           const V3<T>& nf, const T& hf, bool flip,
                           std::vector<ContactPoint<T>>& out) {
  const T delta0 = hf - dot(nf, c);
  const V3<T> perp = nf - a * dot(nf, a);
  const double p2 = valueOf(dot(perp, perp));
  // Flat on the face (axis along the normal): no deepest direction, rho = 0 (its derivative,
  // |perp|'s, is undefined there; 0 is the value the cone |perp| tends to along every path).
  // The samples' sum of forces and moments does not depend on where the samples start then.
  const bool flat = p2 < 1e-24;
  const T rho = flat ? T(0.0) : radius * norm(perp);
  if (valueOf(delta0) + valueOf(rho) <= 0.0) return;
  const V3<T> u = flat ? fallback : perp * (-1.0 / norm(perp));  // towards the deepest point
  const V3<T> w = cross(a, u);
  const size_t first = out.size();
  T total(0.0);
  const int samples = radius == 0.0 ? 1 : kRimSamples;
  for (int k = 0; k < samples; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / kRimSamples;
    const double cs = std::cos(phi), sn = std::sin(phi);
    const T depth = delta0 + rho * cs;
    if (valueOf(depth) <= 0.0) continue;
    const V3<T> x = c + (u * cs + w * sn) * T(radius);
    out.push_back({x + nf * (depth * 0.5), flip ? -nf : nf, depth});
    total += depth;
  }
  for (size_t k = first; k < out.size(); ++k) out[k].weight = out[k].depth / total;
}

// The two rims of frustum (solid c) against the faces of box b: a rim touches a face when its
// deepest point towards that face lies inside the box with that face the nearest (as
// verticesInBox tests vertices). The normal is the face's outward normal (flip: negated).
template <class T>
void rimsInBox(const model::ContactSolid& c, const SolidFrame<T>& fc, const model::ContactSolid& b,
               const SolidFrame<T>& fb, bool flip, std::vector<ContactPoint<T>>& out) {
  const FrustumGeometry<T> g = frustumGeometry(c, fc);
  double lo[3], hi[3];
  boxBounds(b, lo, hi);
  for (int rim = 0; rim < 2; ++rim) {
    const V3<T> centre = rim == 0 ? g.p : g.p + g.a * g.h;
    const double radius = rim == 0 ? g.rb : g.rt;
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const bool upper = face % 2 == 1;
      const V3<T> nf = upper ? fb.a.c[axis] : -fb.a.c[axis];
      const T hf = dot(nf, fb.p) + (upper ? hi[axis] : -lo[axis]);
      // The deepest rim point towards the face must be inside the box, nearest to this face.
      const V3<T> perp = nf - g.a * dot(nf, g.a);
      const double p2 = valueOf(dot(perp, perp));
      const V3<T> deepest =
          p2 < 1e-24 || radius == 0.0 ? centre : centre - perp * (radius / std::sqrt(p2));
      const V3<T> q = fb.a.tmul(deepest - fb.p);
      bool inside = true;
      int nearest = -1;
      double best = 1e300;
      for (int k = 0; k < 3; ++k) {
        const double up = hi[k] - valueOf(q[k]), down = valueOf(q[k]) - lo[k];
        if (up < 0.0 || down < 0.0) inside = false;
        if (up < best) best = up, nearest = 2 * k + 1;
        if (down < best) best = down, nearest = 2 * k;
      }
      if (!inside || nearest != face) continue;
      rimSamplesInHalfSpace(centre, radius, g.a, fc.a.c[0], nf, hf, flip, out);
    }
  }
}

}  // namespace openmss::mechanics::contact
