#pragma once
// FRICTION on a joint (docs/theory.md, "Joint friction"): the friction force and torque the
// joint's I marker receives, templated on the scalar like every force element, so that the
// residual's Newton matrix holds their exact partials — with respect to the positions and
// velocities (slip, creep) and to the joint's multipliers (the reaction that makes the normal
// force). The reaction on the J marker's part is equal and opposite at the I origin.
//
// Channels. Slip and creep are written in J axes as six components, three translational
// (length) and three rotational (the relative angular velocity or rotation times the
// joint's radius, so also lengths): a joint kind frees some of them (jointChannels). The
// friction law acts on the vector of the free components.

#include <Eigen/Dense>
#include <cmath>

#include "common/dual.hpp"
#include "common/vec3.hpp"
#include "mechanics/dynamic_measures.hpp"
#include "mechanics/friction/friction_anchor.hpp"
#include "mechanics/pose.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics::friction {

// Which of the six slip components a joint kind frees, and the radius that turns its
// rotations into surface lengths (PIN_RADIUS, or BALL_RADIUS for a spherical joint).
struct JointChannels {
  bool free[6] = {false, false, false, false, false, false};
  double radius = 1.0;
};

inline JointChannels jointChannels(const model::Friction& f, model::JointType type) {
  using JT = model::JointType;
  JointChannels c;
  c.radius = f.pinRadius;
  switch (type) {
    case JT::Translational:
      c.free[2] = true;
      break;
    case JT::Revolute:
      c.free[5] = true;
      break;
    case JT::Cylindrical:
      c.free[2] = c.free[5] = true;
      break;
    case JT::Spherical:
      c.radius = f.ballRadius;
      c.free[3] = c.free[4] = c.free[5] = true;
      break;
    case JT::Hooke:
    case JT::Universal:
      c.free[3] = c.free[4] = c.free[5] = true;
      break;
    default:
      break;  // the builder refuses the other kinds
  }
  return c;
}

// Joint kinds FRICTION applies to (ADAMS: translational, revolute, cylindrical, Hooke,
// universal, spherical).
inline bool frictionAllowed(model::JointType type) {
  using JT = model::JointType;
  return type == JT::Translational || type == JT::Revolute || type == JT::Cylindrical ||
         type == JT::Spherical || type == JT::Hooke || type == JT::Universal;
}

// ADAMS's STEP: h0 below x0, h1 above x1, the cubic 3u^2 - 2u^3 between.
template <class T>
T stepOf(const T& x, double x0, double h0, double x1, double h1) {
  if (valueOf(x) <= x0) return T(h0);
  if (valueOf(x) >= x1) return T(h1);
  const T u = (x - x0) / (x1 - x0);
  return h0 + (h1 - h0) * u * u * (3.0 - 2.0 * u);
}

// Relative kinematics of one friction: the six slip components (velocity of I relative to J
// seen in J axes; angular velocity times the radius) and the creep since the anchor, J axes.
template <class T>
struct FrictionKinematics {
  T slip[6];
  T creep[6];
  JointChannels channels;
};

// The relative rotation R = A_J^T A_I and displacement A_J^T (p_I - p_J) of a friction's
// joint in double precision (the anchor records them at accepted states).
inline void relativePose(const MarkerState<double>& mi, const MarkerState<double>& mj,
                         Eigen::Vector3d& displacement, Eigen::Matrix3d& rotation) {
  const V3<double> d = mj.a.tmul(mi.p - mj.p);
  displacement = toEigen(d);
  for (int c = 0; c < 3; ++c) rotation.col(c) = toEigen(mj.a.tmul(mi.a.c[c]));
}

template <class T>
FrictionKinematics<T> frictionKinematics(const model::Model& m, const StateLayout& l,
                                         const model::Friction& f, const T* y,
                                         const FrictionAnchor* anchor) {
  const model::Joint& joint = m.joints[f.joint];
  const MarkerState<T> mi = markerState(m, l, joint.iMarker, y);
  const MarkerState<T> mj = markerState(m, l, joint.jMarker, y);
  FrictionKinematics<T> k;
  k.channels = jointChannels(f, joint.type);
  const double r = k.channels.radius;
  const V3<T> d = mi.p - mj.p;
  const V3<T> v = mj.a.tmul(mi.pdot - mj.pdot - cross(mj.w, d));
  const V3<T> w = mj.a.tmul(mi.w - mj.w);
  for (int c = 0; c < 3; ++c) {
    k.slip[c] = v[c];
    k.slip[3 + c] = w[c] * r;
    k.creep[c] = T(0.0);
    k.creep[3 + c] = T(0.0);
  }
  if (anchor == nullptr || !anchor->set) return k;
  // Translational creep: the displacement in J axes since the anchor. Rotational creep: the
  // rotation from the anchored relative orientation to the current one, expressed in J axes
  // (dR = R Ra^T), as the vector part of its skew-symmetric half (sin of the angle times the
  // axis; the creep never exceeds MAX_STICTION_DEFORMATION / radius, a small angle) times r.
  const V3<T> dj = mj.a.tmul(d);
  M3<T> rel;
  for (int c = 0; c < 3; ++c) rel.c[c] = mj.a.tmul(mi.a.c[c]);
  const M3<T> ra = M3<T>::from(anchor->rotation);
  const M3<T> dr = rel * ra.transpose();
  const T sx = 0.5 * (dr.c[1][2] - dr.c[2][1]);
  const T sy = 0.5 * (dr.c[2][0] - dr.c[0][2]);
  const T sz = 0.5 * (dr.c[0][1] - dr.c[1][0]);
  for (int c = 0; c < 3; ++c) k.creep[c] = dj[c] - anchor->displacement(c);
  k.creep[3] = sx * r;
  k.creep[4] = sy * r;
  k.creep[5] = sz * r;
  return k;
}

// The friction coefficient vector over the free channels (docs/theory.md, "Joint friction"):
// its direction opposes the slip (or the creep), its size is the coefficient of the regime.
// Returns the regime: 0 static (creep), 1 transition, 2 dynamic.
template <class T>
int frictionCoefficients(const model::Friction& f, const FrictionKinematics<T>& k, T mu[6]) {
  using E = model::Friction::Effect;
  const double vs = f.stictionVelocity;
  T s2 = T(0.0);
  for (int c = 0; c < 6; ++c) {
    mu[c] = T(0.0);
    if (k.channels.free[c]) s2 = s2 + k.slip[c] * k.slip[c];
  }
  const T sn = valueOf(s2) > 0.0 ? sqrtOf(s2) : T(0.0);
  const double snv = valueOf(sn);
  if (f.effect == E::Sliding) {
    // No stiction: mu_d times a STEP from 0 at rest to 1 at the transition velocity,
    // mu_d (3u^2 - 2u^3) slip/|slip| = mu_d (3 - 2u) u slip / Vs with u = |slip| / Vs, which
    // is smooth through zero slip.
    const T scale =
        snv >= vs ? f.muDynamic / sn : f.muDynamic * (3.0 - 2.0 * (sn / vs)) * (sn / vs) / vs;
    for (int c = 0; c < 6; ++c)
      if (k.channels.free[c]) mu[c] = k.slip[c] * scale;
    return snv >= vs ? 2 : 1;
  }
  if (snv >= vs) {
    // Transition (Vs..1.5 Vs, STEP from mu_s to mu_d) and dynamic regimes; STICTION only:
    // from mu_s down to zero over the same band.
    const T coefficient = f.effect == E::Stiction
                              ? stepOf(sn, vs, f.muStatic, 1.5 * vs, 0.0)
                              : stepOf(sn, vs, f.muStatic, 1.5 * vs, f.muDynamic);
    const T scale = coefficient / sn;
    for (int c = 0; c < 6; ++c)
      if (k.channels.free[c]) mu[c] = k.slip[c] * scale;
    return snv > 1.5 * vs ? 2 : 1;
  }
  // Static regime (creep): x = creep / MAX_STICTION_DEFORMATION + slip / Vs, mu = mu_s x,
  // saturated at |x| = 1 — a stiff spring and damper that hold the joint within the creep
  // limit while the demand stays below mu_s N; continuous with the transition regime when
  // the creep points along the slip (it does when sliding slows into stiction).
  T x[6];
  T x2 = T(0.0);
  for (int c = 0; c < 6; ++c) {
    x[c] = T(0.0);
    if (!k.channels.free[c]) continue;
    x[c] = k.creep[c] / f.maxStictionDeformation + k.slip[c] / vs;
    x2 = x2 + x[c] * x[c];
  }
  const T scale = valueOf(x2) > 1.0 ? f.muStatic / sqrtOf(x2) : T(f.muStatic);
  for (int c = 0; c < 6; ++c)
    if (k.channels.free[c]) mu[c] = x[c] * scale;
  return 0;
}

// Rounding of the normal force's magnitudes (force units; docs/theory.md §13, "Normal force").
// |v| has no derivative at v = 0, and a reaction component that vanishes in exact arithmetic is
// round-off in the multipliers (1e-44 on the sliding block's torques): the Newton matrix then
// took the slope sign(round-off) = +-1 in those multiplier columns while the residual,
// symmetric about zero, has none. sqrt(|v|^2 + eps^2) - eps is smooth, has slope 0 at v = 0 and
// differs from |v| by less than eps; eps = 1e-6 force units (at most 1e-6 N of normal force in
// any UNITS, the dyne being the smallest force unit) is far below any physical load and far
// above the multipliers' round-off at rest.
inline constexpr double kNormalForceRounding = 1e-6;

// sqrt(a^2 + b^2 + eps^2) - eps: |(a, b)| rounded at the origin by eps.
template <class T>
T roundedMagnitude(const T& squared, double eps) {
  return sqrtOf(squared + eps * eps) - eps;
}
template <class T>
T planarMagnitude(const T& a, const T& b, double eps) {
  return roundedMagnitude(a * a + b * b, eps);
}

// The equivalent normal force N (force units) from the joint's reaction on I (force F and
// torque T about the I origin, J axes) and the preload, switched by INPUTS:
//   translational: |F_xy| + |T_xy| / Xs0 + |T_z| / Rn + Fpre
//   cylindrical:   |F_xy| + |T_xy| / Xs0 + Fpre
//   revolute, Hooke, universal: |F_xy| + |F_z| Rn / Rp + |T_xy| / Rb + Fpre
//   spherical:     |F| + Fpre
// The friction force is mu N on translations and mu N radius on rotations.
template <class T>
T normalForce(const model::Friction& f, model::JointType type, const V3<T>& force,
              const V3<T>& torque) {
  using JT = model::JointType;
  const double rf = f.useReactionForce ? 1.0 : 0.0, bm = f.useBendingMoment ? 1.0 : 0.0,
               tm = f.useTorsionalMoment ? 1.0 : 0.0, pl = f.usePreload ? 1.0 : 0.0;
  // Each term rounded by kNormalForceRounding in force units (a torque term by eps times its
  // arm), so that N is smooth where a reaction component vanishes.
  const double eps = kNormalForceRounding;
  const T fxy = planarMagnitude(force.x, force.y, eps);
  T n = T(pl * f.preload);
  switch (type) {
    case JT::Translational:
      n = n + rf * fxy +
          bm * planarMagnitude(torque.x, torque.y, eps * f.initialOverlap) / f.initialOverlap +
          tm * planarMagnitude(torque.z, T(0.0), eps * f.frictionArm) / f.frictionArm;
      break;
    case JT::Cylindrical:
      n = n + rf * fxy +
          bm * planarMagnitude(torque.x, torque.y, eps * f.initialOverlap) / f.initialOverlap;
      break;
    case JT::Spherical:
      n = n + rf * roundedMagnitude(dot(force, force), eps);
      break;
    default:  // revolute, Hooke, universal
      n = n +
          rf * (fxy + planarMagnitude(force.z, T(0.0), eps * f.pinRadius / f.frictionArm) *
                          (f.frictionArm / f.pinRadius)) +
          bm * planarMagnitude(torque.x, torque.y, eps * f.bendingArm) / f.bendingArm;
      break;
  }
  return n;
}

// Everything one friction computes at a state: the loads on I (ground axes, torque about
// the I origin) and the quantities the FRICTION read-back reports.
template <class T>
struct FrictionResult {
  V3<T> force, torque;      // on the I marker's part, ground axes
  T forceJ[3], torqueJ[3];  // the same in J axes
  T mu[6];                  // coefficient vector (channels)
  FrictionKinematics<T> kinematics;
  T normal;
  int regime = 0;
  bool active = false;
};

// `reads` lends the multipliers (null: no reaction, only the preload acts); `mode` is the
// analysis under way (the run state's, INACTIVE=STATIC).
template <class T>
FrictionResult<T> frictionLoads(const model::Model& m, const StateLayout& l,
                                const ConstraintSet* constraints, int index, const T* y,
                                const FrictionAnchor* anchor, model::AnalysisMode mode) {
  const model::Friction& f = m.frictions[index];
  const model::Joint& joint = m.joints[f.joint];
  FrictionResult<T> r;
  const V3<T> zero(T(0.0), T(0.0), T(0.0));
  r.force = r.torque = zero;
  r.normal = T(0.0);
  for (int c = 0; c < 3; ++c) r.forceJ[c] = r.torqueJ[c] = T(0.0);
  r.kinematics = frictionKinematics(m, l, f, y, anchor);
  for (int c = 0; c < 6; ++c) r.mu[c] = T(0.0);
  if (f.inactiveStatic &&
      (mode == model::AnalysisMode::Statics || mode == model::AnalysisMode::QuasiStatics))
    return r;
  r.active = true;
  const MarkerState<T> mj = markerState(m, l, joint.jMarker, y);
  V3<T> reactionForce = zero, reactionTorque = zero;
  if (constraints != nullptr)
    constraintElementReaction(m, l, *constraints, model::MeasureKind::JointForce, f.joint,
                              joint.iMarker, y, reactionForce, reactionTorque);
  r.normal = normalForce(f, joint.type, mj.a.tmul(reactionForce), mj.a.tmul(reactionTorque));
  r.regime = frictionCoefficients(f, r.kinematics, r.mu);
  const double radius = r.kinematics.channels.radius;
  for (int c = 0; c < 3; ++c) {
    r.forceJ[c] = -(r.mu[c] * r.normal);
    r.torqueJ[c] = -(r.mu[3 + c] * r.normal) * radius;
  }
  r.force = mj.a * V3<T>(r.forceJ[0], r.forceJ[1], r.forceJ[2]);
  r.torque = mj.a * V3<T>(r.torqueJ[0], r.torqueJ[1], r.torqueJ[2]);
  return r;
}

}  // namespace openmss::mechanics::friction
