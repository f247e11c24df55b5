#pragma once
// The loads of one CONTACT element (docs/theory.md §6c): every pair of an I solid and a J
// solid whose bounding spheres overlap (tested on values first) goes to the narrow phase; each
// contact point gets the normal law and, when friction is on, the friction law; the sums act on I's
// part through the I marker's origin and, equal and opposite, on J's part through the J marker's
// origin.

#include <limits>
#include <utility>
#include <vector>

#include "mechanics/contact/contact_kinematics.hpp"
#include "mechanics/contact/contact_law.hpp"
#include "mechanics/contact/narrow_phase.hpp"
#include "mechanics/pose.hpp"

namespace openmss::mechanics::contact {

template <class T>
struct ContactLoads {
  V3<T> force;      // on I's part, through iOrigin
  V3<T> torqueAtI;  // about iOrigin
  V3<T> torqueAtJ;  // of the reaction -force, about jOrigin
  V3<T> iOrigin, jOrigin;
  int points = 0;  // contact points found (0: separated)
  double maxDepth = 0.0;
};

// A marker's origin in ground on values: the broad phase needs no partials, and the dual
// states of the markers are the costly part of a Newton matrix (theory §6c, "Benchmark").
// The same operations as markerState's, so the value is the same to the bit.
template <class T>
V3<double> markerOriginValue(const model::Model& m, const StateLayout& layout, int marker,
                             const T* y) {
  const model::Marker& mk = m.markers[marker];
  const V3<double> sb = V3<double>::from(mk.position);
  const int body = m.parts[mk.part].body;
  if (body < 0) return sb;
  const T* q = y + layout.body(body);
  const V3<double> r{valueOf(q[StateLayout::kR]), valueOf(q[StateLayout::kR + 1]),
                     valueOf(q[StateLayout::kR + 2])};
  const Quat<double> e{valueOf(q[StateLayout::kE]), valueOf(q[StateLayout::kE + 1]),
                       valueOf(q[StateLayout::kE + 2]), valueOf(q[StateLayout::kE + 3])};
  return r + rotationOf(e) * sb;
}

// The broad-phase test of two solids: their bounding spheres (about the reference markers'
// origins, on values) overlap. One function for contactLoads and the shared broad phase
// (contact_broad_phase.hpp), so both take the same decision to the bit.
inline bool boundingSpheresOverlap(const V3<double>& ci, double ri, const V3<double>& cj,
                                   double rj) {
  const V3<double> gap = ci - cj;
  const double reach = ri + rj;
  return dot(gap, gap) <= reach * reach;
}

// `withFriction` is false when COULOMB_FRICTION is OFF, or DYNAMICS_ONLY outside dynamics.
// `kin` gives the marker states (shared by the elements of one evaluation, or computed afresh:
// contact_kinematics.hpp); the result does not depend on which. `t` is the time user laws are
// called at; NaN asks for the contact points only (pointNormalForce).
template <class T>
ContactLoads<T> contactLoads(const model::Model& m, const StateLayout& layout,
                             const model::Contact& c, ContactKinematics<T>& kin,
                             bool withFriction,
                             double t = std::numeric_limits<double>::quiet_NaN()) {
  ContactLoads<T> out;
  const T* y = kin.y();
  // Broad phase: bounding spheres about the reference markers, on values, before any work on
  // T. With no pair near, the loads are zero in a neighbourhood of y (partials zero too).
  std::vector<V3<double>> iCentres, jCentres;
  for (const model::ContactSolid& s : c.iSolids)
    iCentres.push_back(markerOriginValue(m, layout, s.marker, y));
  for (const model::ContactSolid& s : c.jSolids)
    jCentres.push_back(markerOriginValue(m, layout, s.marker, y));
  std::vector<std::pair<size_t, size_t>> near;
  for (size_t p = 0; p < c.iSolids.size(); ++p)
    for (size_t q = 0; q < c.jSolids.size(); ++q)
      if (boundingSpheresOverlap(iCentres[p], c.iSolids[p].boundingRadius, jCentres[q],
                                 c.jSolids[q].boundingRadius))
        near.emplace_back(p, q);
  if (!c.active || near.empty()) {
    out.iOrigin = V3<T>::from(markerOriginValue(m, layout, c.iMarker, y));
    out.jOrigin = V3<T>::from(markerOriginValue(m, layout, c.jMarker, y));
    return out;
  }
  const MarkerState<T> mi = kin.marker(c.iMarker);
  const MarkerState<T> mj = kin.marker(c.jMarker);
  out.iOrigin = mi.p;
  out.jOrigin = mj.p;
  // The frames of the solids of the near pairs only, each once.
  std::vector<SolidFrame<T>> iFrames(c.iSolids.size()), jFrames(c.jSolids.size());
  std::vector<char> iDone(c.iSolids.size(), 0), jDone(c.jSolids.size(), 0);
  auto frameOf = [&](const model::ContactSolid& s) {
    const MarkerState<T> st = kin.marker(s.marker);
    return SolidFrame<T>{st.p, st.a};
  };
  std::vector<ContactPoint<T>> points;
  for (const auto& [p, q] : near) {
    if (!iDone[p]) iFrames[p] = frameOf(c.iSolids[p]), iDone[p] = 1;
    if (!jDone[q]) jFrames[q] = frameOf(c.jSolids[q]), jDone[q] = 1;
    narrowPhase(c.iSolids[p], iFrames[p], c.jSolids[q], jFrames[q], points);
  }
  for (const ContactPoint<T>& p : points) {
    // Velocity of the material point of I at the contact point relative to that of J.
    const V3<T> vi = mi.pdot + cross(mi.w, p.point - mi.p);
    const V3<T> vj = mj.pdot + cross(mj.w, p.point - mj.p);
    const V3<T> vrel = vi - vj;
    const T approach = -dot(vrel, p.normal);  // the rate of the penetration
    const T fn = pointNormalForce(c, t, p, approach) * p.weight;
    V3<T> f = p.normal * fn;
    if (withFriction) f += pointFrictionForce(c, t, p, fn, vrel - p.normal * dot(vrel, p.normal));
    out.force += f;
    out.torqueAtI += cross(p.point - mi.p, f);
    out.torqueAtJ -= cross(p.point - mj.p, f);
    out.maxDepth = std::max(out.maxDepth, valueOf(p.depth));
  }
  out.points = static_cast<int>(points.size());
  return out;
}

// One element on its own, every marker state computed afresh (read-backs, events).
template <class T>
ContactLoads<T> contactLoads(const model::Model& m, const StateLayout& layout,
                             const model::Contact& c, const T* y, bool withFriction,
                             double t = std::numeric_limits<double>::quiet_NaN()) {
  ContactKinematics<T> kin(m, layout, y);
  return contactLoads(m, layout, c, kin, withFriction, t);
}

}  // namespace openmss::mechanics::contact
