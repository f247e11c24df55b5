#pragma once
// Sort and sweep over the bounding spheres of the CONTACT solids (docs/theory.md §6c,
// "Broad phase"): which elements have a pair of solids whose bounding spheres overlap, without
// testing every pair of every element. The solids are distinct (marker, bounding radius)
// objects; their intervals along ground x, widened by a round-off pad, are sorted (by lower
// end, then object index: a total order, so the sweep is deterministic) and only the objects
// whose intervals overlap are tested, with the same boundingSpheresOverlap as the brute-force
// test. The pad makes every pair the exact test accepts overlap along x, so the answer is the
// brute force's to the bit (ContactPile.SweepEqualsBruteForce compares them). Elements are
// returned ascending.

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "mechanics/contact/contact_loads.hpp"

namespace openmss::mechanics::contact {

class BoundingSweep {
 public:
  BoundingSweep() = default;
  // markerSlot: the slot of each model marker (ContactSlots::marker), whose centre the queries
  // pass at that slot.
  BoundingSweep(const model::Model& m, const std::vector<int>& markerSlot) {
    std::map<std::pair<int, double>, int> index;  // (marker slot, radius) -> object
    auto object = [&](const model::ContactSolid& s) {
      const std::pair<int, double> key{markerSlot[s.marker], s.boundingRadius};
      const auto [it, added] = index.emplace(key, static_cast<int>(slot_.size()));
      if (added) {
        slot_.push_back(key.first);
        radius_.push_back(key.second);
      }
      return it->second;
    };
    for (size_t e = 0; e < m.contacts.size(); ++e) {
      const int element = static_cast<int>(e);
      for (const model::ContactSolid& si : m.contacts[e].iSolids)
        for (const model::ContactSolid& sj : m.contacts[e].jSolids) {
          const int a = object(si), b = object(sj);
          if (a == b)  // a solid against itself: tested directly
            self_.push_back({a, element});
          else
            pairs_.push_back({std::min(a, b), std::max(a, b), element});
        }
    }
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  }

  // The elements (ascending) with a pair of solids whose bounding spheres, radii times
  // `factor`, overlap; centres per marker slot.
  void near(const std::vector<V3<double>>& centres, double factor, std::vector<int>& out) {
    const int n = static_cast<int>(slot_.size());
    lo_.resize(static_cast<size_t>(n));
    hi_.resize(static_cast<size_t>(n));
    order_.clear();
    for (int k = 0; k < n; ++k) {
      const double x = centres[slot_[k]].x, r = factor * radius_[k];
      // A NaN centre overlaps nothing in the exact test (and could not be sorted).
      if (std::isnan(x)) continue;
      // The pad covers the rounding of the exact test's differences and squares (relative
      // 1e-12 of the coordinates and radii involved is far above it).
      const double pad = 1e-12 * (std::abs(x) + r) + 1e-300;
      lo_[k] = x - r - pad;
      hi_[k] = x + r + pad;
      order_.push_back(k);
    }
    std::sort(order_.begin(), order_.end(),
              [&](int a, int b) { return lo_[a] < lo_[b] || (lo_[a] == lo_[b] && a < b); });
    out.clear();
    active_.clear();
    for (const int k : order_) {
      active_.erase(
          std::remove_if(active_.begin(), active_.end(), [&](int a) { return hi_[a] < lo_[k]; }),
          active_.end());
      for (const int a : active_) {
        if (!boundingSpheresOverlap(centres[slot_[a]], factor * radius_[a], centres[slot_[k]],
                                    factor * radius_[k]))
          continue;
        const Pair key{std::min(a, k), std::max(a, k), -1};
        for (auto it = std::lower_bound(pairs_.begin(), pairs_.end(), key);
             it != pairs_.end() && it->a == key.a && it->b == key.b; ++it)
          out.push_back(it->element);
      }
      active_.push_back(k);
    }
    for (const Self& s : self_) {
      const V3<double>& c = centres[slot_[s.object]];
      if (boundingSpheresOverlap(c, factor * radius_[s.object], c, factor * radius_[s.object]))
        out.push_back(s.element);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

 private:
  struct Pair {
    int a, b, element;
    bool operator<(const Pair& o) const {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : element < o.element;
    }
    bool operator==(const Pair& o) const = default;
  };
  struct Self {
    int object, element;
  };
  std::vector<int> slot_;       // per object: its marker slot
  std::vector<double> radius_;  // per object: its bounding radius
  std::vector<Pair> pairs_;     // object pairs (a < b) of every element, sorted
  std::vector<Self> self_;
  std::vector<double> lo_, hi_;  // work: interval along x per object
  std::vector<int> order_, active_;
};

}  // namespace openmss::mechanics::contact
