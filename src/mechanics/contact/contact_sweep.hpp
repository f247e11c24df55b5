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
// When the small solids fill a compact region (a heap of spheres), a uniform grid of cells as
// wide as the largest small pair's reach replaces the sweep: along x alone a 3-D heap of N
// leaves about N^(2/3) solids in each solid's interval, against a few in the 27 cells around
// it; the solids far larger than the rest (walls, floors) are tested against every solid. The
// grid also tests every pair the exact test accepts, so it gives the same answer.

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
    // Small solids: up to 4x the median bounding radius (the spheres of a heap); the rest
    // (walls, floors) are few and tested against all.
    if (!radius_.empty()) {
      std::vector<double> r = radius_;
      std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
      const double limit = 4.0 * r[r.size() / 2];
      for (const double x : radius_)
        if (x <= limit) smallRadiusMax_ = std::max(smallRadiusMax_, x);
    }
  }

  // The elements (ascending) with a pair of solids whose bounding spheres, radii times
  // `factor`, overlap; centres per marker slot.
  void near(const std::vector<V3<double>>& centres, double factor, std::vector<int>& out) {
    out.clear();
    if (gridNear(centres, factor, out))
      ++gridAnswers_;
    else
      sweepNear(centres, factor, out);
    for (const Self& s : self_) {
      const V3<double>& c = centres[slot_[s.object]];
      if (boundingSpheresOverlap(c, factor * radius_[s.object], c, factor * radius_[s.object]))
        out.push_back(s.element);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // How many near() calls the grid answered (the rest: the sweep); tests check both ran.
  long gridAnswers() const { return gridAnswers_; }

 private:
  // The elements of objects a and b when their spheres overlap.
  void test(const std::vector<V3<double>>& centres, double factor, int a, int b,
            std::vector<int>& out) const {
    if (!boundingSpheresOverlap(centres[slot_[a]], factor * radius_[a], centres[slot_[b]],
                                factor * radius_[b]))
      return;
    const Pair key{std::min(a, b), std::max(a, b), -1};
    for (auto it = std::lower_bound(pairs_.begin(), pairs_.end(), key);
         it != pairs_.end() && it->a == key.a && it->b == key.b; ++it)
      out.push_back(it->element);
  }

  // The grid's candidates (see the file's comment); false, with nothing added, when the grid
  // does not suit these centres (spread too thin, too far from the origin for the cell
  // arithmetic, few solids, none small of positive size): the sweep answers then.
  bool gridNear(const std::vector<V3<double>>& centres, double factor, std::vector<int>& out) {
    const int n = static_cast<int>(slot_.size());
    // A cell is as wide as any small pair's reach: |x_a - x_b| <= reach <= h, with a margin far
    // above the rounding of the exact test and of the divisions below.
    const double h = 2.0 * factor * smallRadiusMax_ * (1.0 + 1e-9);
    if (!(h > 0.0) || n < 64) return false;
    small_.clear();
    big_.clear();
    long long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    cellXyz_.resize(3 * static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const V3<double>& c = centres[slot_[k]];
      // A NaN centre overlaps nothing in the exact test.
      if (std::isnan(c.x) || std::isnan(c.y) || std::isnan(c.z)) continue;
      if (radius_[k] > smallRadiusMax_) {
        big_.push_back(k);
        continue;
      }
      const double q[3] = {c.x / h, c.y / h, c.z / h};
      for (int d = 0; d < 3; ++d) {
        // Beyond 1e12 cells the division's rounding could matter: sweep instead.
        if (!(std::abs(q[d]) < 1e12)) return false;
        const long long i = static_cast<long long>(std::floor(q[d]));
        cellXyz_[3 * static_cast<size_t>(k) + d] = i;
        if (small_.empty() || i < lo[d]) lo[d] = i;
        if (small_.empty() || i > hi[d]) hi[d] = i;
      }
      small_.push_back(k);
    }
    const long long nx = hi[0] - lo[0] + 1, ny = hi[1] - lo[1] + 1, nz = hi[2] - lo[2] + 1;
    const long long limit = 8 * static_cast<long long>(small_.size()) + 64;
    if (small_.empty() || nx > limit || ny > limit || nz > limit || nx * ny > limit ||
        nx * ny * nz > limit)
      return false;
    // Counting sort of the small objects by cell (ascending object order within a cell).
    const auto cellIndex = [&](long long x, long long y, long long z) {
      return static_cast<size_t>(((z - lo[2]) * ny + (y - lo[1])) * nx + (x - lo[0]));
    };
    const auto cellOf = [&](int k) {
      const long long* c = &cellXyz_[3 * static_cast<size_t>(k)];
      return cellIndex(c[0], c[1], c[2]);
    };
    cellStart_.assign(static_cast<size_t>(nx * ny * nz) + 1, 0);
    for (const int k : small_) ++cellStart_[cellOf(k) + 1];
    for (size_t i = 1; i < cellStart_.size(); ++i) cellStart_[i] += cellStart_[i - 1];
    cellObjects_.resize(small_.size());
    cellFill_.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (const int k : small_) cellObjects_[static_cast<size_t>(cellFill_[cellOf(k)]++)] = k;
    for (const int k : small_) {
      const long long* c = &cellXyz_[3 * static_cast<size_t>(k)];
      for (long long z = std::max(c[2] - 1, lo[2]); z <= std::min(c[2] + 1, hi[2]); ++z)
        for (long long y = std::max(c[1] - 1, lo[1]); y <= std::min(c[1] + 1, hi[1]); ++y)
          for (long long x = std::max(c[0] - 1, lo[0]); x <= std::min(c[0] + 1, hi[0]); ++x) {
            const size_t cell = cellIndex(x, y, z);
            for (int i = cellStart_[cell]; i < cellStart_[cell + 1]; ++i) {
              const int b = cellObjects_[static_cast<size_t>(i)];
              if (b > k) test(centres, factor, k, b, out);
            }
          }
    }
    // The large solids against every other solid (each pair once).
    for (size_t i = 0; i < big_.size(); ++i) {
      for (const int k : small_) test(centres, factor, big_[i], k, out);
      for (size_t j = i + 1; j < big_.size(); ++j) test(centres, factor, big_[i], big_[j], out);
    }
    return true;
  }

  void sweepNear(const std::vector<V3<double>>& centres, double factor, std::vector<int>& out) {
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
    active_.clear();
    for (const int k : order_) {
      active_.erase(
          std::remove_if(active_.begin(), active_.end(), [&](int a) { return hi_[a] < lo_[k]; }),
          active_.end());
      for (const int a : active_) test(centres, factor, a, k, out);
      active_.push_back(k);
    }
  }

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
  double smallRadiusMax_ = 0.0;
  long gridAnswers_ = 0;  // the largest bounding radius the grid holds
  // Work of the grid: small and large objects, each small object's cell, the cells' objects.
  std::vector<int> small_, big_, cellStart_, cellFill_, cellObjects_;
  std::vector<long long> cellXyz_;
};

}  // namespace openmss::mechanics::contact
