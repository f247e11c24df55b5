#pragma once
// Contact points of the ELLIPSOID (unequal scales), TORUS and EXTERNAL mesh solids
// (docs/theory.md §6c, "Ellipsoids, tori and meshes"). Analytic where it is exact and cheap, on
// T with exact partials as narrow_phase.hpp:
// - ellipsoid against a PLANE: its support point along the plane's inward normal;
// - torus against a PLANE: its centre circle as a rim sampled against the half-space lowered
//   by the tube radius (rimSamplesInHalfSpace), each sample's point moved onto the tube;
// - torus against a sphere: the centre-circle point nearest the sphere's centre (exact);
// - torus against a BOX or a mesh: torus_narrow_phase.hpp; two tori:
//   torus_pair_narrow_phase.hpp;
// - mesh against a PLANE: its vertices below the plane (as a BOX's, verticesBelowPlane).
// Every other pair with an ellipsoid or a mesh, and two frustums steeper than 5 degrees, go to
// FCL (fcl_narrow_phase.hpp).

#include <cmath>
#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/fcl_narrow_phase.hpp"
#include "mechanics/contact/frustum_narrow_phase.hpp"
#include "mechanics/contact/plane_narrow_phase.hpp"
#include "mechanics/contact/torus_narrow_phase.hpp"
#include "mechanics/contact/torus_pair_narrow_phase.hpp"

namespace openmss::mechanics::contact {

// Ellipsoid e (semi-axes size) against plane pl: the support point of e along -z (z the plane's
// normal) is c + A diag(s^2) u / |diag(s) u| with u = A^T (-z); normal z (flip: negated).
template <class T>
void ellipsoidPlane(const model::ContactSolid& e, const SolidFrame<T>& fe,
                    const model::ContactSolid& pl, const SolidFrame<T>& fp, bool flip,
                    std::vector<ContactPoint<T>>& out) {
  const V3<T> z = fp.a.c[2];
  const V3<T> u = fe.a.tmul(-z);
  const V3<T> su(u.x * e.size[0], u.y * e.size[1], u.z * e.size[2]);
  const T reach = norm(su);  // the support distance along -z
  const V3<T> local(su.x * (e.size[0] / reach), su.y * (e.size[1] / reach),
                    su.z * (e.size[2] / reach));
  const V3<T> x = fe.p + fe.a * local;
  const T depth = -dot(x - fp.p, z);
  if (valueOf(depth) <= 0.0 || !overPlane(pl, fp, x)) return;
  out.push_back({x + z * (depth * 0.5), flip ? -z : z, depth});
}

// Torus t (centre circle radius R in its marker's xy-plane, tube radius r) against plane pl.
template <class T>
void torusPlane(const model::ContactSolid& t, const SolidFrame<T>& ft,
                const model::ContactSolid& pl, const SolidFrame<T>& fp, bool flip,
                std::vector<ContactPoint<T>>& out) {
  const double big = t.size[0], tube = t.size[1];
  const V3<T> z = fp.a.c[2], axis = ft.a.c[2];
  const V3<T> perp = z - axis * dot(z, axis);
  const double p2 = valueOf(dot(perp, perp));
  const V3<T> deepest = p2 < 1e-24 ? ft.p : ft.p - perp * (big / std::sqrt(p2));
  if (!overPlane(pl, fp, deepest)) return;
  const size_t first = out.size();
  // The circle's points x have depth (hf - z.x) with hf lowered by the tube radius.
  rimSamplesInHalfSpace(ft.p, big, axis, ft.a.c[0], z, dot(z, fp.p) + tube, flip, out);
  for (size_t k = first; k < out.size(); ++k) out[k].point -= z * T(tube);
}

// Torus t (on J when flip is false) against sphere s: the normal from the torus to the sphere.
template <class T>
bool torusSphere(const model::ContactSolid& t, const SolidFrame<T>& ft,
                 const model::ContactSolid& s, const SolidFrame<T>& fs, ContactPoint<T>& cp) {
  const double big = t.size[0], tube = t.size[1], r = s.size[0];
  const V3<T> axis = ft.a.c[2];
  const V3<T> rel = fs.p - ft.p;
  const V3<T> planar = rel - axis * dot(rel, axis);
  const double p2 = valueOf(dot(planar, planar));
  // On the axis every circle point is nearest: the marker's x axis picks one.
  const V3<T> radial = p2 > 1e-30 ? planar * (1.0 / norm(planar)) : ft.a.c[0];
  const V3<T> q = ft.p + radial * T(big);  // nearest point of the centre circle
  const V3<T> d = fs.p - q;
  const double dist = std::sqrt(valueOf(dot(d, d)));
  if (dist >= tube + r || dist == 0.0) return false;
  const T len = norm(d);
  const V3<T> n = d * (1.0 / len);
  cp = {(q + n * T(tube) + fs.p - n * T(r)) * T(0.5), n, T(tube + r) - len};
  return true;
}

// The vertices of mesh m below plane pl (flip: the plane on I).
template <class T>
void meshVerticesBelowPlane(const model::ContactSolid& m, const SolidFrame<T>& fm,
                            const model::ContactSolid& pl, const SolidFrame<T>& fp, bool flip,
                            std::vector<ContactPoint<T>>& out) {
  const V3<T> z = fp.a.c[2];
  const double lowest = valueOf(dot(fp.p, z));
  for (const Eigen::Vector3d& v : m.mesh->vertices) {
    const V3<T> x = fm.p + fm.a * V3<T>::from(v);
    if (valueOf(dot(x, z)) >= lowest) continue;  // above the plane: most vertices, cheaply
    const T depth = -dot(x - fp.p, z);
    if (valueOf(depth) <= 0.0 || !overPlane(pl, fp, x)) continue;
    out.push_back({x + z * (depth * 0.5), flip ? -z : z, depth});
  }
}

// Whether the pair is one of this file's (or FCL's): an ellipsoid, torus or mesh on either
// side, or two frustums steeper than kMaxFrustumPairHalfAngle.
inline bool curvedPair(const model::ContactSolid& a, const model::ContactSolid& b) {
  using S = model::ContactSolid::Shape;
  auto curved = [](S s) { return s == S::Ellipsoid || s == S::Torus || s == S::Mesh; };
  if (curved(a.shape) || curved(b.shape)) return true;
  return a.shape == S::Frustum && b.shape == S::Frustum &&
         std::max(model::frustumHalfAngle(a), model::frustumHalfAngle(b)) >
             model::kMaxFrustumPairHalfAngle;
}

// The contact points of a curvedPair (si on I, sj on J).
template <class T>
void curvedNarrowPhase(const model::ContactSolid& si, const SolidFrame<T>& fi,
                       const model::ContactSolid& sj, const SolidFrame<T>& fj,
                       std::vector<ContactPoint<T>>& out) {
  using S = model::ContactSolid::Shape;
  const bool planeOnI = si.shape == S::Plane;
  if (planeOnI || sj.shape == S::Plane) {
    const model::ContactSolid& pl = planeOnI ? si : sj;
    const model::ContactSolid& o = planeOnI ? sj : si;
    const SolidFrame<T> fp = planeFrame(pl, planeOnI ? fi : fj);
    const SolidFrame<T>& fo = planeOnI ? fj : fi;
    if (o.shape == S::Ellipsoid) ellipsoidPlane(o, fo, pl, fp, planeOnI, out);
    if (o.shape == S::Torus) torusPlane(o, fo, pl, fp, planeOnI, out);
    if (o.shape == S::Mesh) meshVerticesBelowPlane(o, fo, pl, fp, planeOnI, out);
    return;
  }
  if (si.shape == S::Torus || sj.shape == S::Torus) {
    // The builder lets a torus meet a plane, a sphere, a box, a mesh or a torus only.
    const bool torusOnI = si.shape == S::Torus;
    const model::ContactSolid &t = torusOnI ? si : sj, &o = torusOnI ? sj : si;
    const SolidFrame<T>&ft = torusOnI ? fi : fj, &fo = torusOnI ? fj : fi;
    if (o.shape == S::Box) return torusBox(t, ft, o, fo, torusOnI, out);
    if (o.shape == S::Mesh) return torusMesh(t, ft, o, fo, torusOnI, out);
    if (o.shape == S::Torus) return torusTorus(si, fi, sj, fj, out);
    ContactPoint<T> cp;
    if (torusSphere(t, ft, o, fo, cp)) {
      if (torusOnI) cp.normal = -cp.normal;
      out.push_back(cp);
    }
    return;
  }
  libraryNarrowPhase(si, fi, sj, fj, out);
}

}  // namespace openmss::mechanics::contact
