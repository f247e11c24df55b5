#pragma once
// The library narrow phase of CONTACT (docs/theory.md §6c, "FCL"): pairs that no analytic
// routine covers (an ELLIPSOID with unequal scales against a sphere, box, frustum, ellipsoid
// or mesh; two frustums with sides steeper than 5 degrees; a mesh against a solid other than a
// PLANE) go to FCL's libccd penetration (MPR) or its mesh traversal, on values.
//
// FCL gives points, a normal and a depth, not partials (theory §6c, "Partials of the FCL
// pairs"): on duals of one direction a single contact gets central differences of FCL's result
// along that direction; several contacts (meshes) and nested duals use the contact frame (each
// witness point held as a material point of its solid, the normal fixed, d = n . (xJ - xI) on
// T, the first-order gap of a minimal penetration).

#include <vector>

#include "mechanics/contact/contact_point.hpp"

namespace openmss::mechanics::contact {

// One contact from FCL in ground: the witness points of I's and J's solids, the unit normal from
// J towards I and the depth (> 0).
struct LibraryContact {
  V3<double> onI, onJ, normal;
  double depth;
};

// The module's entry point (user::kFclEntryName, extern "C"): libraryContacts by pointers. Module
// and program are built by one compiler in one build, so the C++ types cross as they are.
using LibraryContactsEntry = void(const model::ContactSolid*, const SolidFrame<double>*,
                                  const model::ContactSolid*, const SolidFrame<double>*,
                                  std::vector<LibraryContact>*);

// Sides of the polygon a FRUSTUM of unequal radii is given to FCL as (a convex polytope): its
// rims' chordal error is R (1 - cos(pi / kFrustumSides)) = 3.0e-4 R. A CYLINDER is FCL's exact
// cylinder.
inline constexpr int kFrustumSides = 128;

// A frame's value (the library works on doubles).
template <class T>
SolidFrame<double> valueFrame(const SolidFrame<T>& f) {
  auto v = [](const V3<T>& x) { return V3<double>(valueOf(x.x), valueOf(x.y), valueOf(x.z)); };
  return {v(f.p), {{v(f.a.c[0]), v(f.a.c[1]), v(f.a.c[2])}}};
}

// The contacts FCL finds between solid si (frame fi) and sj (frame fj), appended to `out`.
// Meshes give one per touching triangle (pair); convex solids at most one. A call into the FCL
// module, opened on the first call (fcl_module.cpp; docs/architecture.md, "FCL module").
void libraryContacts(const model::ContactSolid& si, const SolidFrame<double>& fi,
                     const model::ContactSolid& sj, const SolidFrame<double>& fj,
                     std::vector<LibraryContact>& out);

// The frame with its axes divided by their lengths, on T. FCL is given unit axes (away from
// |e| = 1 the Euler parameters' axes have length |e|^2), so the witness points are placed with
// unit axes too: the residual then does not change along |e|, as FCL's result does not, and its
// partials agree with central differences in the Euler-parameter columns (theory §6c,
// "Partials of the FCL pairs").
template <class T>
SolidFrame<T> unitAxes(const SolidFrame<T>& f) {
  SolidFrame<T> u = f;
  for (int k = 0; k < 3; ++k) u.a.c[k] = f.a.c[k] * (T(1.0) / norm(f.a.c[k]));
  return u;
}

// The FCL contacts as contact points on T from the contact frame (above). Several contacts of
// one pair (a mesh's triangles) share one force in proportion to their depths, as the rim
// samples do (theory §6c, "Rim samples").
template <class T>
void contactFramePoints(const model::ContactSolid& si, const SolidFrame<T>& givenI,
                        const model::ContactSolid& sj, const SolidFrame<T>& givenJ,
                        std::vector<ContactPoint<T>>& out) {
  const SolidFrame<T> fi = unitAxes(givenI), fj = unitAxes(givenJ);
  const SolidFrame<double> vi = valueFrame(fi), vj = valueFrame(fj);
  std::vector<LibraryContact> found;
  libraryContacts(si, vi, sj, vj, found);
  const size_t first = out.size();
  T total(0.0);
  for (const LibraryContact& c : found) {
    // The witness points as material points of their solids (local coordinates constant).
    const V3<double> li = vi.a.tmul(c.onI - vi.p), lj = vj.a.tmul(c.onJ - vj.p);
    const V3<T> xi = fi.p + fi.a * V3<T>::from(li);
    const V3<T> xj = fj.p + fj.a * V3<T>::from(lj);
    const V3<T> n = V3<T>::from(c.normal);
    const T depth = dot(xj - xi, n);
    if (valueOf(depth) <= 0.0) continue;
    out.push_back({(xi + xj) * T(0.5), n, depth});
    total += depth;
  }
  if (out.size() - first > 1)
    for (size_t k = first; k < out.size(); ++k) out[k].weight = out[k].depth / total;
}

// Step of the central differences of one FCL contact along the seeded direction: FCL's MPR
// converges to 1e-12 (libraryContacts), so the derivative's error is about 1e-12 / h + h^2
// times the curvature: 1e-6 of its size at h = 1e-6 (theory §6c, "Partials of the FCL pairs").
inline constexpr double kLibraryStep = 1e-6;

// The contact points of an FCL pair on T. On duals of one direction (the Newton matrix's
// columns) a single contact gets the central differences of FCL's point, normal and depth
// along that direction (FCL's MPR penetration is not the minimal one, so the contact frame's
// first-order argument does not hold for it); several contacts (meshes) and nested duals use
// the contact frame.
template <class T>
void libraryNarrowPhase(const model::ContactSolid& si, const SolidFrame<T>& fi,
                        const model::ContactSolid& sj, const SolidFrame<T>& fj,
                        std::vector<ContactPoint<T>>& out) {
  contactFramePoints(si, fi, sj, fj, out);
}

inline void libraryNarrowPhase(const model::ContactSolid& si, const SolidFrame<Dual<double>>& fi,
                               const model::ContactSolid& sj, const SolidFrame<Dual<double>>& fj,
                               std::vector<ContactPoint<Dual<double>>>& out) {
  using D = Dual<double>;
  auto moved = [](const SolidFrame<D>& f, double s) {
    auto at = [s](const V3<D>& x) {
      return V3<double>(x.x.v + s * x.x.d, x.y.v + s * x.y.d, x.z.v + s * x.z.d);
    };
    return SolidFrame<double>{at(f.p), {{at(f.a.c[0]), at(f.a.c[1]), at(f.a.c[2])}}};
  };
  std::vector<LibraryContact> at0, plus, minus;
  libraryContacts(si, moved(fi, 0.0), sj, moved(fj, 0.0), at0);
  if (at0.size() == 1) {
    const double h = kLibraryStep;
    libraryContacts(si, moved(fi, h), sj, moved(fj, h), plus);
    libraryContacts(si, moved(fi, -h), sj, moved(fj, -h), minus);
  }
  if (at0.size() != 1 || plus.size() != 1 || minus.size() != 1) {
    contactFramePoints(si, fi, sj, fj, out);
    return;
  }
  auto dual = [](const V3<double>& v, const V3<double>& p, const V3<double>& m) {
    const double k = 0.5 / kLibraryStep;
    return V3<D>(D(v.x, (p.x - m.x) * k), D(v.y, (p.y - m.y) * k), D(v.z, (p.z - m.z) * k));
  };
  auto mid = [](const LibraryContact& c) { return (c.onI + c.onJ) * 0.5; };
  const LibraryContact &c = at0[0], &p = plus[0], &m = minus[0];
  out.push_back({dual(mid(c), mid(p), mid(m)), dual(c.normal, p.normal, m.normal),
                 D(c.depth, (p.depth - m.depth) * (0.5 / kLibraryStep))});
}

}  // namespace openmss::mechanics::contact
