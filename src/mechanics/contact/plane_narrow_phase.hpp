#pragma once
// Contact points of a PLANE solid (docs/theory.md §6c, "Plane"): the half-space below the RM
// marker's xy-plane, limited sideways to XMIN..XMAX, YMIN..YMAX. Every point is exact, as the
// top face of a large BOX: a sphere's lowest point, a box's vertices below the plane, a
// frustum's rims sampled as against a box face (frustum_narrow_phase.hpp). Choices on values,
// depth, normal and point on the scalar type (exact partials between switches).

#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/frustum_narrow_phase.hpp"

namespace openmss::mechanics::contact {

// Whether (x, y) lies inside the polygon (even-odd rule: a ray along +x crosses its edges an
// odd number of times). Deterministic, on values; a point on an edge may count either way.
inline bool insidePolygon(const std::vector<Eigen::Vector2d>& poly, double x, double y) {
  bool inside = false;
  for (size_t k = 0, j = poly.size() - 1; k < poly.size(); j = k++) {
    const Eigen::Vector2d &a = poly[k], &b = poly[j];
    if ((a.y() > y) != (b.y() > y) && x < a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

// The plane's own frame: the reference marker's, turned to the OUTLINE's plane axes when the
// plane is an OUTLINE (theory §6c, "OUTLINE floors"); a PLANE's is its RM marker's.
template <class T>
SolidFrame<T> planeFrame(const model::ContactSolid& pl, const SolidFrame<T>& fm) {
  if (pl.polygon.empty()) return fm;
  return {fm.p, fm.a * M3<T>::from(pl.planeAxes)};
}

// Whether x lies over the plane's rectangle or OUTLINE polygon (its projection on the
// xy-plane of the plane's frame `fp`, on values).
template <class T>
bool overPlane(const model::ContactSolid& pl, const SolidFrame<T>& fp, const V3<T>& x) {
  const V3<T> q = fp.a.tmul(x - fp.p);
  const double qx = valueOf(q[0]), qy = valueOf(q[1]);
  if (!pl.polygon.empty()) return insidePolygon(pl.polygon, qx, qy);
  return qx >= pl.bounds[0] && qx <= pl.bounds[1] && qy >= pl.bounds[2] && qy <= pl.bounds[3];
}

// Sphere s against plane pl: the normal is the plane's z axis (from the plane towards the
// sphere); the point midway between the sphere's lowest point and the plane below its centre.
template <class T>
bool spherePlane(const model::ContactSolid& s, const SolidFrame<T>& fs,
                 const model::ContactSolid& pl, const SolidFrame<T>& fp, ContactPoint<T>& cp) {
  const double r = s.size[0];
  const V3<T> z = fp.a.c[2];
  const T h = dot(fs.p - fp.p, z);  // height of the centre above the plane
  if (valueOf(h) >= r || !overPlane(pl, fp, fs.p)) return false;
  cp = {fs.p - z * ((h + r) * 0.5), z, T(r) - h};
  return true;
}

// The vertices of box v below plane pl: depth the vertex's distance below, normal the plane's
// z axis (flip: negated, for a plane on the I side).
template <class T>
void verticesBelowPlane(const model::ContactSolid& v, const SolidFrame<T>& fv,
                        const model::ContactSolid& pl, const SolidFrame<T>& fp, bool flip,
                        std::vector<ContactPoint<T>>& out) {
  const V3<T> z = fp.a.c[2];
  for (int corner = 0; corner < 8; ++corner) {
    const V3<T> local((corner & 1) ? T(v.size[0]) : T(0.0), (corner & 2) ? T(v.size[1]) : T(0.0),
                      (corner & 4) ? T(v.size[2]) : T(0.0));
    const V3<T> x = fv.p + fv.a * local;
    const T depth = -dot(x - fp.p, z);
    if (valueOf(depth) <= 0.0 || !overPlane(pl, fp, x)) continue;
    out.push_back({x + z * (depth * 0.5), flip ? -z : z, depth});
  }
}

// The two rims of frustum c against plane pl, sampled as against a box face (theory §6c, "Rim
// samples"); a rim counts when its deepest point lies over the plane's rectangle.
template <class T>
void rimsBelowPlane(const model::ContactSolid& c, const SolidFrame<T>& fc,
                    const model::ContactSolid& pl, const SolidFrame<T>& fp, bool flip,
                    std::vector<ContactPoint<T>>& out) {
  const FrustumGeometry<T> g = frustumGeometry(c, fc);
  const V3<T> z = fp.a.c[2];
  const T hf = dot(z, fp.p);  // depth(x) = hf - z.x
  for (int rim = 0; rim < 2; ++rim) {
    const V3<T> centre = rim == 0 ? g.p : g.p + g.a * g.h;
    const double radius = rim == 0 ? g.rb : g.rt;
    const V3<T> perp = z - g.a * dot(z, g.a);
    const double p2 = valueOf(dot(perp, perp));
    const V3<T> deepest =
        p2 < 1e-24 || radius == 0.0 ? centre : centre - perp * (radius / std::sqrt(p2));
    if (!overPlane(pl, fp, deepest)) continue;
    rimSamplesInHalfSpace(centre, radius, g.a, fc.a.c[0], z, hf, flip, out);
  }
}

// Solid si (I) against sj (J) when one of them is a plane; false for a pair it does not cover
// (two planes: the builder refuses them first).
template <class T>
bool planeNarrowPhase(const model::ContactSolid& si, const SolidFrame<T>& fi,
                      const model::ContactSolid& sj, const SolidFrame<T>& fj,
                      std::vector<ContactPoint<T>>& out) {
  using S = model::ContactSolid::Shape;
  const bool planeOnI = si.shape == S::Plane;
  if (planeOnI == (sj.shape == S::Plane)) return false;
  const model::ContactSolid& pl = planeOnI ? si : sj;
  const model::ContactSolid& other = planeOnI ? sj : si;
  const SolidFrame<T> fp = planeFrame(pl, planeOnI ? fi : fj);
  const SolidFrame<T>& fo = planeOnI ? fj : fi;
  if (other.shape == S::Sphere) {
    ContactPoint<T> cp;
    if (spherePlane(other, fo, pl, fp, cp)) {
      if (planeOnI) cp.normal = -cp.normal;
      out.push_back(cp);
    }
  } else if (other.shape == S::Box) {
    verticesBelowPlane(other, fo, pl, fp, planeOnI, out);
  } else if (other.shape == S::Frustum) {
    rimsBelowPlane(other, fo, pl, fp, planeOnI, out);
  } else {
    return false;
  }
  return true;
}

}  // namespace openmss::mechanics::contact
