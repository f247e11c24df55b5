#pragma once
// The loads of one CONTACT element (docs/theory.md §6c): every pair of an I solid and a J
// solid whose bounding spheres overlap goes to the narrow phase; each contact point gets the
// normal law and, when friction is on, the friction law; the sums act on I's part through the
// I marker's origin and, equal and opposite, on J's part through the J marker's origin.

#include <vector>

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

// `withFriction` is false when COULOMB_FRICTION is OFF, or DYNAMICS_ONLY outside dynamics.
template <class T>
ContactLoads<T> contactLoads(const model::Model& m, const StateLayout& layout,
                             const model::Contact& c, const T* y, bool withFriction) {
  ContactLoads<T> out;
  const MarkerState<T> mi = markerState(m, layout, c.iMarker, y);
  const MarkerState<T> mj = markerState(m, layout, c.jMarker, y);
  out.iOrigin = mi.p;
  out.jOrigin = mj.p;
  if (!c.active) return out;
  std::vector<SolidFrame<T>> jFrames;
  jFrames.reserve(c.jSolids.size());
  for (const model::ContactSolid& sj : c.jSolids) {
    const MarkerState<T> s = markerState(m, layout, sj.marker, y);
    jFrames.push_back({s.p, s.a});
  }
  std::vector<ContactPoint<T>> points;
  for (const model::ContactSolid& si : c.iSolids) {
    const MarkerState<T> s = markerState(m, layout, si.marker, y);
    const SolidFrame<T> fi{s.p, s.a};
    for (size_t q = 0; q < c.jSolids.size(); ++q) {
      // Broad phase: bounding spheres about the reference markers, on values.
      const V3<double> gap{valueOf(fi.p.x - jFrames[q].p.x), valueOf(fi.p.y - jFrames[q].p.y),
                           valueOf(fi.p.z - jFrames[q].p.z)};
      const double reach = si.boundingRadius + c.jSolids[q].boundingRadius;
      if (dot(gap, gap) > reach * reach) continue;
      narrowPhase(si, fi, c.jSolids[q], jFrames[q], points);
    }
  }
  for (const ContactPoint<T>& p : points) {
    // Velocity of the material point of I at the contact point relative to that of J.
    const V3<T> vi = mi.pdot + cross(mi.w, p.point - mi.p);
    const V3<T> vj = mj.pdot + cross(mj.w, p.point - mj.p);
    const V3<T> vrel = vi - vj;
    const T approach = -dot(vrel, p.normal);  // the rate of the penetration
    const T fn = normalForce(c, p.depth, approach) * p.weight;
    V3<T> f = p.normal * fn;
    if (withFriction) f += frictionForce(c, fn, vrel - p.normal * dot(vrel, p.normal));
    out.force += f;
    out.torqueAtI += cross(p.point - mi.p, f);
    out.torqueAtJ -= cross(p.point - mj.p, f);
    out.maxDepth = std::max(out.maxDepth, valueOf(p.depth));
  }
  out.points = static_cast<int>(points.size());
  return out;
}

}  // namespace openmss::mechanics::contact
