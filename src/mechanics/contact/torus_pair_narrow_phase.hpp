#pragma once
// Contact points of two TORUS solids (docs/theory.md §6c, "Torus against a torus"). Each torus
// is the set of points within its tube radius of its centre circle, so two tori touch where
// their centre circles come within rA + rB: at a local minimum over A's circle angle theta of
// F(theta) = (distance from A(theta) to B's circle)^2 (closed form per theta: circleDistance2)
// the segment between A(theta) and B's nearest circle point is normal to both circles, the
// depth is rA + rB - its length and the normal lies along it. Exact; the minima are found on
// values (coarse samples of theta, then Newton) and one Newton step on T gives their partials
// (the implicit function's, as the box edges of torus_narrow_phase.hpp).
// Each minimum is a region sampled as a rim (theory §6c, "Rim samples"): A's circle at 12
// angles from the minimum, each sample the ball about its circle point against B's tube, the
// samples inside sharing one force, so rings stacked face to face carry their weight and their
// tilt. When F is constant along A's circle (coaxial rings) there is no minimum and the samples
// start at A's marker x axis.

#include <cmath>
#include <numbers>
#include <vector>

#include "mechanics/contact/contact_point.hpp"
#include "mechanics/contact/torus_narrow_phase.hpp"

namespace openmss::mechanics::contact {

// Coarse samples of A's circle that bracket the minima of F before Newton.
inline constexpr int kTorusPairSamples = 24;

// A's circle point at angle theta from its marker's x axis and its first two derivatives, on T.
template <class T>
void circlePoint(const SolidFrame<T>& f, double big, const T& theta, V3<T>& x, V3<T>& d1,
                 V3<T>& d2) {
  const T c = cosOf(theta), s = sinOf(theta);
  const V3<T> radial = f.a.c[0] * c + f.a.c[1] * s;
  x = f.p + radial * T(big);
  d1 = (f.a.c[1] * c - f.a.c[0] * s) * T(big);
  d2 = -radial * T(big);
}

// F and its derivatives at theta (values or T); false on B's axis.
template <class T>
bool torusPairDistance2(const SolidFrame<T>& fa, double bigA, const SolidFrame<T>& fb, double bigB,
                        const T& theta, T& f, T& f1, T& f2, V3<T>& x) {
  V3<T> d1, d2;
  circlePoint(fa, bigA, theta, x, d1, d2);
  return circleDistance2(x - fb.p, d1, d2, fb.a.c[2], bigB, f, f1, f2);
}

// The angles of the local minima of F on A's circle with F < reach^2, on values; `flat` when F
// does not vary along the circle (coaxial rings).
inline void torusPairMinima(const SolidFrame<double>& fa, double bigA, const SolidFrame<double>& fb,
                            double bigB, double reach, std::vector<double>& found, bool& flat) {
  constexpr int n = kTorusPairSamples;
  double fs[n];
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int k = 0; k < n; ++k) {
    double f1, f2;
    V3<double> x;
    if (!torusPairDistance2(fa, bigA, fb, bigB, 2.0 * std::numbers::pi * k / n, fs[k], f1, f2, x))
      fs[k] = HUGE_VAL;
    lo = std::min(lo, fs[k]), hi = std::max(hi, fs[k]);
  }
  // Constant to 1e-12 of the squared reach: coaxial (the value's own rounding is ~1e-16).
  flat = hi - lo <= 1e-12 * reach * reach;
  if (flat || lo >= reach * reach) return;
  for (int k = 0; k < n; ++k) {
    const double prev = fs[(k + n - 1) % n], next = fs[(k + 1) % n];
    if (fs[k] > prev || fs[k] >= next || fs[k] >= reach * reach) continue;
    // Newton on F' = 0, steps limited to half a sample spacing. Nearly coaxial rings leave F'
    // at its rounding (the angle then wanders within the flat bottom, where every angle has
    // the same depth to that rounding): the last iterate is kept when F'' > 0 there.
    double theta = 2.0 * std::numbers::pi * k / n;
    bool convex = false;
    for (int it = 0; it < 50; ++it) {
      double f, f1, f2;
      V3<double> x;
      convex = torusPairDistance2(fa, bigA, fb, bigB, theta, f, f1, f2, x) && f2 > 0.0;
      if (!convex) break;
      const double step = std::clamp(-f1 / f2, -std::numbers::pi / n, std::numbers::pi / n);
      theta += step;
      if (std::abs(step) <= 1e-15 * (1.0 + std::abs(theta))) break;
    }
    if (!convex) continue;
    const double wrapped = std::remainder(theta, 2.0 * std::numbers::pi);
    bool seen = false;
    for (const double o : found)
      seen = seen || std::abs(std::remainder(o - wrapped, 2.0 * std::numbers::pi)) < 1e-9;
    if (!seen) found.push_back(wrapped);
  }
}

// The contact at A's circle point x (theta on T) against torus B: appended when the tubes
// overlap. The normal points from B towards A (flip: negated); `weight` set by the caller.
template <class T>
void tubePoint(const V3<T>& x, double tubeA, const model::ContactSolid& b, const SolidFrame<T>& fb,
               bool flip, std::vector<ContactPoint<T>>& out) {
  model::ContactSolid widened = b;  // the point against B's tube widened by A's tube radius
  widened.size[1] = b.size[1] + tubeA;
  V3<T> n;
  T depth;
  if (!pointInTorus(x, widened, fb, n, depth)) return;
  // Midway between A's surface x - n rA and B's, depth further along n.
  const V3<T> onA = x - n * T(tubeA);
  out.push_back({onA + n * (depth * 0.5), flip ? -n : n, depth});
}

// Torus a (on I) against torus b (on J): for each minimum theta* of F, A's circle sampled at
// the kRimSamples angles theta* + 2 pi k / kRimSamples (the first the exact minimum), each sample
// the ball of radius rA about its circle point against B's tube, those inside sharing one force
// in proportion to their depths (the rim samples' rule); a sample belongs to the angularly
// nearest minimum, so two regions do not count a sample twice.
template <class T>
void torusTorus(const model::ContactSolid& a, const SolidFrame<T>& fa, const model::ContactSolid& b,
                const SolidFrame<T>& fb, std::vector<ContactPoint<T>>& out) {
  const double bigA = a.size[0], bigB = b.size[0], tubeA = a.size[1];
  const double reach = a.size[1] + b.size[1], turn = 2.0 * std::numbers::pi;
  std::vector<double> minima;
  bool flat = false;
  torusPairMinima(valueFrame(fa), bigA, valueFrame(fb), bigB, reach, minima, flat);
  if (flat) minima.assign(1, 0.0);  // coaxial: no deepest angle, A's marker x axis starts
  for (size_t m = 0; m < minima.size(); ++m) {
    T theta(minima[m]);
    if (!flat) {  // one Newton step on T: the value stays, the partials are the implicit ones
      T f, f1, f2;
      V3<T> x;
      if (!torusPairDistance2(fa, bigA, fb, bigB, theta, f, f1, f2, x)) continue;
      theta = theta - f1 / f2;
    }
    const size_t first = out.size();
    for (int k = 0; k < kRimSamples; ++k) {
      const double offset = turn * k / kRimSamples, at = minima[m] + offset;
      bool nearest = true;
      for (size_t o = 0; o < minima.size() && nearest; ++o)
        nearest = o == m || std::abs(std::remainder(at - minima[o], turn)) >
                                std::abs(std::remainder(offset, turn));
      if (!nearest) continue;
      V3<T> x, d1, d2;
      circlePoint(fa, bigA, theta + offset, x, d1, d2);
      tubePoint(x, tubeA, b, fb, false, out);
    }
    T total(0.0);
    for (size_t k = first; k < out.size(); ++k) total += out[k].depth;
    for (size_t k = first; k < out.size(); ++k) out[k].weight = out[k].depth / total;
  }
}

}  // namespace openmss::mechanics::contact
