#pragma once
// The broad phase shared by every CONTACT element of a model (docs/theory.md §6c, "Broad
// phase"): which elements have a pair of solids whose bounding spheres overlap, on values.
// The other elements have no contact point in a neighbourhood of the state (contactLoads makes
// the same test, to the bit, before any work on the scalar), so their loads and partials are
// exactly zero and the residual skips them.
//
// In the compressed passes of a Newton matrix, which read only derivatives, it also tells which
// elements read no seeded state (seeded(), eitherSeeded()): their derivatives are exactly zero,
// so one pass evaluates only the few elements at the seeded parts.
//
// The near answer depends on the positions only, and one Newton matrix evaluates the residual once
// per colour at the same values (local_newton_colours.cpp): it is recomputed only when the
// position values of the bodies the contacts read differ from the last call's (an exact
// comparison, so the cache can never give another answer than computing afresh).
// The test is a sort and sweep over the solids' bounding spheres (contact_sweep.hpp), the same
// answer as testing every solid pair of every element (nearBruteForce) without the N² tests.

#include <type_traits>
#include <vector>

#include "common/dual.hpp"
#include "mechanics/contact/contact_kinematics.hpp"
#include "mechanics/contact/contact_loads.hpp"
#include "mechanics/contact/contact_sweep.hpp"

namespace openmss::mechanics::contact {

class ContactBroadPhase {
 public:
  ContactBroadPhase() = default;
  ContactBroadPhase(const model::Model& m, const StateLayout& layout)
      : m_(&m), layout_(layout), slots_(m, layout), sweep_(m, slots_.marker) {
    slotBody_.assign(static_cast<size_t>(slots_.bodies), -1);
    for (int b = 0; b < layout.bodies; ++b)
      if (slots_.body[b] >= 0) slotBody_[slots_.body[b]] = b;
    slotMarker_.assign(static_cast<size_t>(slots_.markers), -1);
    for (size_t k = 0; k < m.markers.size(); ++k)
      if (slots_.marker[k] >= 0) slotMarker_[slots_.marker[k]] = static_cast<int>(k);
    centres_.resize(static_cast<size_t>(slots_.markers));
  }

  const ContactSlots& slots() const { return slots_; }

  // Per slot body: whether its state in y (r, e, v, w: what the contacts read) carries a
  // nonzero derivative. Without `derivativesOnly`, or on a scalar without derivatives, every
  // body counts as seeded, so nothing is left out.
  template <class T>
  const std::vector<char>& seeded(const T* y, bool derivativesOnly) {
    seeded_.assign(static_cast<size_t>(slots_.bodies), 1);
    if constexpr (std::is_same_v<T, Dual<double>>) {
      if (!derivativesOnly) return seeded_;
      for (int k = 0; k < slots_.bodies; ++k) {
        const T* q = y + layout_.body(slotBody_[k]);
        bool any = false;
        for (int i = StateLayout::kR; i < StateLayout::kMu; ++i) any = any || q[i].d != 0.0;
        seeded_[k] = any ? 1 : 0;
      }
    }
    return seeded_;
  }
  // Whether an element between bodies bi and bj (-1: ground) reads a seeded state.
  bool eitherSeeded(const std::vector<char>& seeded, int bi, int bj) const {
    return (bi >= 0 && seeded[slots_.body[bi]]) || (bj >= 0 && seeded[slots_.body[bj]]);
  }

  // The elements (indices into Model::contacts, ascending) with a pair of solids whose bounding
  // spheres overlap at the positions of y (whether ACTIVE or not).
  template <class T>
  const std::vector<int>& near(const T* y) {
    bool same = valid_;
    key_.resize(static_cast<size_t>(7 * slots_.bodies));
    for (int k = 0; k < slots_.bodies; ++k) {
      const T* q = y + layout_.body(slotBody_[k]);
      for (int i = 0; i < 3; ++i) same = keep(7 * k + i, valueOf(q[StateLayout::kR + i])) && same;
      for (int i = 0; i < 4; ++i)
        same = keep(7 * k + 3 + i, valueOf(q[StateLayout::kE + i])) && same;
    }
    if (same) return near_;
    for (int k = 0; k < slots_.markers; ++k)
      centres_[k] = markerOriginValue(*m_, layout_, slotMarker_[k], y);
    sweep_.near(centres_, 1.0, near_);
    valid_ = true;
    return near_;
  }

  // The elements (ascending) with a pair of solids whose bounding spheres, radii scaled by
  // `factor` (>= 1), overlap at the positions of y: the near set of the Newton matrix's
  // pattern with a margin (docs/theory.md §6c, "Near-pair pattern"). Leaves near()'s cache
  // alone. With factor 1 it is near(y) to the bit (the same test on the same centres).
  std::vector<int> nearWithin(const double* y, double factor) {
    std::vector<V3<double>> centres(static_cast<size_t>(slots_.markers));
    for (int k = 0; k < slots_.markers; ++k)
      centres[k] = markerOriginValue(*m_, layout_, slotMarker_[k], y);
    std::vector<int> out;
    sweep_.near(centres, factor, out);
    return out;
  }

  const BoundingSweep& sweep() const { return sweep_; }

  // The brute-force answer of nearWithin (every solid pair of every element): the reference
  // of the sweep's tests.
  std::vector<int> nearBruteForce(const double* y, double factor) const {
    std::vector<V3<double>> centres(static_cast<size_t>(slots_.markers));
    for (int k = 0; k < slots_.markers; ++k)
      centres[k] = markerOriginValue(*m_, layout_, slotMarker_[k], y);
    std::vector<int> out;
    const auto& contacts = m_->contacts;
    for (size_t e = 0; e < contacts.size(); ++e)
      if (anyPairNear(contacts[e], centres, factor)) out.push_back(static_cast<int>(e));
    return out;
  }

 private:
  // Stores v at key_[i]; true when it equals what was there (bitwise for every finite value).
  bool keep(int i, double v) {
    const bool same = key_[i] == v;
    key_[i] = v;
    return same;
  }
  bool anyPairNear(const model::Contact& c, const std::vector<V3<double>>& centres,
                   double factor) const {
    for (const model::ContactSolid& si : c.iSolids)
      for (const model::ContactSolid& sj : c.jSolids)
        if (boundingSpheresOverlap(centres[slots_.marker[si.marker]], factor * si.boundingRadius,
                                   centres[slots_.marker[sj.marker]], factor * sj.boundingRadius))
          return true;
    return false;
  }

  const model::Model* m_ = nullptr;
  StateLayout layout_;
  ContactSlots slots_;
  BoundingSweep sweep_;
  std::vector<int> slotBody_, slotMarker_;
  std::vector<V3<double>> centres_;  // per marker slot, at the positions of key_
  std::vector<double> key_;          // r and e of each slot body at the last call
  std::vector<int> near_;
  std::vector<char> seeded_;
  bool valid_ = false;
};

}  // namespace openmss::mechanics::contact
