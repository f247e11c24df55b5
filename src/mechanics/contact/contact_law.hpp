#pragma once
// The force laws of CONTACT (docs/theory.md §6c), templated on the scalar so the Newton matrix
// gets their exact partials from dual numbers:
// - IMPACT: Fn = k d^e + STEP(d, 0, 0, DMAX, c) d', clipped at 0 (never pulls), d > 0 the
//   penetration and d' its rate; the same law as the IMPACT function with x1 - x = d.
// - POISSON: Fn = p d [ (1 + r^2)/2 + (1 - r^2)/2 STEP(d', -vt, -1, vt, 1) ]: p d while the
//   solids approach, r^2 p d while they separate, so a linear contact returns the fraction r
//   of the approach speed (the energy stored is p d^2/2, the energy released r^2 p d^2/2).
// - Coulomb friction with ADAMS's mu(v) curve: the cubic STEP from 0 to mu_s over |v| < vs,
//   from mu_s to mu_d over vs..vd, mu_d above; along -v_slip/|v_slip|.
// - User laws, NORMAL_FUNCTION=USER (CNFSUB) and FRICTION_FUNCTION=USER (CFFSUB): the routine's
//   value and partials chained into the duals (docs/user-subroutines.md, "CNFSUB and CFFSUB").

#include <cmath>
#include <type_traits>

#include "common/dual.hpp"
#include "common/vec3.hpp"
#include "mechanics/contact/contact_point.hpp"
#include "model/contact.hpp"

namespace openmss::mechanics::contact {

// Normal transition velocity of POISSON (model velocity units): ADAMS's CONTACT statement has
// no argument for it; 1e-3 keeps the rebound ratio within 1e-6 of r for approach speeds of
// order 1 (theory §6c).
inline constexpr double kPoissonTransitionVelocity = 1e-3;

inline double powOf(double x, double e) { return std::pow(x, e); }
template <class T>
Dual<T> powOf(const Dual<T>& x, double e) {
  return {powOf(x.v, e), e * powOf(x.v, e - 1.0) * x.d};
}

// ADAMS's cubic STEP(x, x0, h0, x1, h1) with constant ends.
template <class T>
T cubicStep(const T& x, double x0, double h0, double x1, double h1) {
  if (valueOf(x) <= x0) return T(h0);
  if (valueOf(x) >= x1) return T(h1);
  const T u = (x - x0) * (1.0 / (x1 - x0));
  return h0 + (h1 - h0) * (u * u * (3.0 - 2.0 * u));
}

// Normal force magnitude (>= 0) at penetration `depth` > 0 growing at `rate`.
template <class T>
T normalForce(const model::Contact& c, const T& depth, const T& rate) {
  if (c.law == model::Contact::NormalLaw::Impact) {
    const T damping = c.dmax > 0.0 ? cubicStep(depth, 0.0, 0.0, c.dmax, c.damping) : T(c.damping);
    const T f = c.stiffness * powOf(depth, c.exponent) + damping * rate;
    return valueOf(f) > 0.0 ? f : T(0.0);
  }
  const double r2 = c.restitution * c.restitution;
  const double vt = kPoissonTransitionVelocity;
  const T blend = cubicStep(rate, -vt, -1.0, vt, 1.0);
  const T f = c.penalty * depth * (0.5 * (1.0 + r2) + 0.5 * (1.0 - r2) * blend);
  return valueOf(f) > 0.0 ? f : T(0.0);
}

// mu(s)/s for the slip speed s = |v| given as s^2 (no square root at s = 0): the ratio is
// smooth there, mu_s (3 - w^2) / (2 vs) with w = s/vs, the value of -STEP(s, -vs, mu_s, vs,
// -mu_s)/s in closed form.
template <class T>
T frictionPerSpeed(const model::Contact& c, const T& speedSquared) {
  const double vs = c.stictionVelocity, vd = c.frictionVelocity;
  if (valueOf(speedSquared) < vs * vs)
    return c.muStatic * (3.0 - speedSquared * (1.0 / (vs * vs))) * (0.5 / vs);
  const T s = sqrtOf(speedSquared);
  if (valueOf(s) >= vd) return c.muDynamic / s;
  return cubicStep(s, vs, c.muStatic, vd, c.muDynamic) / s;
}

// Friction force on I at a contact point: -mu(|v|) Fn v/|v|, v the slip velocity of I
// relative to J (tangential part of the relative velocity).
template <class T>
V3<T> frictionForce(const model::Contact& c, const T& normal, const V3<T>& slip) {
  const T k = frictionPerSpeed(c, dot(slip, slip)) * normal;
  return slip * (-k);
}

// A value computed outside the duals with its partials da, db in the duals a and b.
template <class T>
T chained(double value, double da, const T& a, double db, const T& b) {
  if constexpr (std::is_same_v<T, double>) {
    (void)da, (void)a, (void)db, (void)b;
    return value;
  } else {
    T out(value);
    out.d = da * a.d + db * b.d;
    return out;
  }
}

// The surface points of I and J at a contact point (midway between them, d apart along n).
template <class T>
void surfacePoints(const ContactPoint<T>& p, double loci[3], double locj[3]) {
  const double d = valueOf(p.depth);
  for (int k = 0; k < 3; ++k) {
    loci[k] = valueOf(p.point[k]) - 0.5 * d * valueOf(p.normal[k]);
    locj[k] = valueOf(p.point[k]) + 0.5 * d * valueOf(p.normal[k]);
  }
}

// The normal force at one contact point, `rate` the penetration's rate: CNFSUB's or the
// built-in law's. `t` NaN asks for the contact points only (analysis/contact_events.cpp): the
// user routine is then not called and the force is 0.
template <class T>
T pointNormalForce(const model::Contact& c, double t, const ContactPoint<T>& p, const T& rate) {
  if (!c.normalRoutine) return normalForce(c, p.depth, rate);
  if (std::isnan(t)) return T(0.0);
  user::ContactNormalInput in{};
  surfacePoints(p, in.loci, in.locj);
  for (int k = 0; k < 3; ++k) {
    in.nj[k] = valueOf(p.normal[k]);
    in.ni[k] = -in.nj[k];
  }
  in.gap = -valueOf(p.depth);
  in.gapdot = -valueOf(rate);
  double v[3];
  c.normalRoutine->evaluate(t, in, !std::is_same_v<T, double>, v);
  return chained(v[0], -v[1], p.depth, -v[2], rate);  // gap = -depth, gapdot = -rate
}

// The friction force on I at one contact point: CFFSUB's value f along the slip direction,
// F = (f / s) v_slip (s = |v_slip|), or the built-in Coulomb law. At s = 0 exactly, f/s is
// taken as its limit df/ds (a friction law vanishes at zero slip). `t` NaN: as above.
template <class T>
V3<T> pointFrictionForce(const model::Contact& c, double t, const ContactPoint<T>& p,
                         const T& normal, const V3<T>& slip) {
  if (!c.frictionRoutine) return frictionForce(c, normal, slip);
  if (std::isnan(t)) return V3<T>();
  user::ContactFrictionInput in{};
  surfacePoints(p, in.loci, in.locj);
  const T speedSquared = dot(slip, slip);
  const double s = std::sqrt(valueOf(speedSquared));
  in.xdot[0] = s;
  in.nforce = valueOf(normal);
  double v[3];
  c.frictionRoutine->evaluate(t, in, !std::is_same_v<T, double>, v);
  if (s == 0.0) return slip * T(v[1]);
  const double g = v[0] / s;
  return slip * chained(g, (v[1] - g) / s, sqrtOf(speedSquared), v[2] / s, normal);
}

}  // namespace openmss::mechanics::contact
