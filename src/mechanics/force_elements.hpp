#pragma once
// Applied force elements: SFORCE, SPRINGDAMPER, BUSHING / FIELD / BEAM (one linear law) and
// VFORCE / VTORQUE / GFORCE (docs/theory.md §6) and CONTACT (§6c, mechanics/contact/). Each element
// computes, templated on the scalar, the force and torque it applies to the part of its I marker
// and the reaction on the part of its J (or JFLOAT) marker, from the marker frames and velocities.
// The residual subtracts them from the Newton-Euler rows, so the Newton matrix, formed on dual
// numbers, holds their exact derivatives; the read-back functions (SFORCE, SPDP, BUSH, ...) use the
// same code.

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <vector>

#include "mechanics/bound_function.hpp"
#include "mechanics/contact/contact_broad_phase.hpp"
#include "mechanics/contact/contact_loads.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/friction/joint_friction.hpp"
#include "mechanics/pose.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// Friction: FRICTION on a joint (mechanics/friction/joint_friction.hpp), acting between the
// joint's I and J markers. MultiPoint: NFORCE, which loads every one of its I markers and J
// (multiPointLoads); loads() is empty for it. Contact: CONTACT (mechanics/contact/).
enum class ForceElementKind {
  SForce,
  SpringDamper,
  LinearField,
  VectorForce,
  Friction,
  MultiPoint,
  Contact
};

// One element: its kind and its index in the Model's vector of that kind.
struct ForceElementRef {
  ForceElementKind kind = ForceElementKind::SForce;
  int index = -1;
};

// What one element applies, in ground axes.
template <class T>
struct ElementLoads {
  // On the I marker's part: a force through the I origin and a torque.
  V3<T> force, torque;
  bool hasForce = false, hasTorque = false;
  // On the part of reactionMarker (J, or the JFLOAT marker), unless action-only: a force through
  // reactionPoint and a torque.
  int reactionMarker = -1;
  V3<T> reactionForce, reactionTorque, reactionPoint;
};

class ForceElements {
 public:
  // Takes the angle references of rotational SPRINGDAMPERs from the data set's configuration.
  explicit ForceElements(const model::Model& model);

  // Every element in the order the residual applies them (SFORCEs first, in data-set order).
  const std::vector<ForceElementRef>& elements() const { return elements_; }

  // `reads` lends functions y' and the constraints (accelerations, reactions; null: zero).
  template <class T>
  ElementLoads<T> loads(ForceElementRef e, double t, const T* y,
                        const DynamicReads<T>* reads = nullptr) const;

  // Subtracts every element's generalised force from the Newton-Euler rows of g.
  // `derivativesOnly` (the caller reads the derivative parts of g only): the CONTACT elements
  // whose two parts' states carry no derivative are left out; their derivatives are exactly zero.
  // `skip` (one flag per element of elements(), or null): elements left out, whose entries the
  // caller fills otherwise (the element-local Newton matrix, local_newton_forces.cpp).
  template <class T>
  void addToResidual(double t, const T* y, T* g, const DynamicReads<T>* reads = nullptr,
                     bool derivativesOnly = false, const char* skip = nullptr) const;

  // Whether element e's loads are a pure function of its two markers' states and its own
  // constant data (SPRINGDAMPER; BUSHING, FIELD, BEAM without FUNCTION=USER): no expression,
  // user code or run state. Such an element's Newton-matrix entries can be formed by one local
  // forward-AD pass over its two bodies' states (docs/theory.md, "Element-local Newton matrix").
  bool isStateLocal(ForceElementRef e) const;
  // The loads of such an element from its I and J marker states (those of loads()).
  template <class T>
  ElementLoads<T> stateLocalLoads(ForceElementRef e, const MarkerState<T>& mi,
                                  const MarkerState<T>& mj) const {
    if (e.kind == ForceElementKind::SpringDamper) return springDamperLoads(e.index, mi, mj);
    return linearFieldLoads(e.index, 0.0, mi, mj);
  }
  // Subtracts a force through `point` and a torque (ground axes) from the force rows gv and
  // moment rows gw of the body at `pose`: what the residual does for each load it applies.
  template <class T>
  static void applyLoad(const BodyPose<T>& pose, const V3<T>& point, const V3<T>& force,
                        const V3<T>& torque, bool hasForce, bool hasTorque, T* gv, T* gw);

  // Force and torque of element e on the part of its I marker (atJ false) or of its J / JFLOAT
  // marker (atJ true), in ground; the torque is about that marker's origin (a JFLOAT marker
  // sits at I). Zero at J for action-only elements.
  void action(ForceElementRef e, bool atJ, double t, const double* y, Eigen::Vector3d& force,
              Eigen::Vector3d& torque, const DynamicReads<double>* reads = nullptr) const;

  // NFORCE k (docs/theory.md §6b): the force and torque (ground) on the part of each I marker,
  // through that marker's origin, and the reaction on J's part, torque about J's origin.
  template <class T>
  void multiPointLoads(int k, const T* y, std::vector<V3<T>>& force, std::vector<V3<T>>& torque,
                       V3<T>& jForce, V3<T>& jTorque) const;
  // NFORCE k's force on `marker` (an I marker or J; zero for another), torque about its origin.
  template <class T>
  void multiPointAction(int k, int marker, const T* y, V3<T>& force, V3<T>& torque) const;

  // The CONTACT elements (ascending) whose solids' bounding spheres overlap at y: every other
  // CONTACT's loads are exactly zero there (contactLoads' own broad phase, the same test).
  const std::vector<int>& nearContacts(const double* y) const { return broadPhase_.near(y); }

  // The element's I marker and its J marker as the data set names it (JFLOAT for VFORCE,
  // VTORQUE, GFORCE; the J of an action-only SFORCE, which takes no reaction). NFORCE: -1 and
  // its J (its I markers are Model::nforces[k].iMarkers).
  int iMarker(ForceElementRef e) const;
  int jMarker(ForceElementRef e) const;

  // Value of SFORCE k's function (exposed for diagnostics).
  template <class T>
  T sforceValue(int k, double t, const T* y, const DynamicReads<T>* reads = nullptr) const {
    const DynamicReads<T> r = readsWith(reads);
    return evaluateFunction(*model_, layout_, model_->sforces[k].function, t, y, scratchValues_,
                            scratchGrad_, &r, run_);
  }

  // Force read-backs in functions (force_read_back.hpp, docs/theory.md §4d). `reads` with
  // these elements as its force evaluator (every function evaluation that may read a force
  // goes through it).
  template <class T>
  DynamicReads<T> readsWith(const DynamicReads<T>* reads) const;
  // SFORCE, SPDP, BUSH, FIELD, BEAM, VFORCE, VTORQ, GFORCE (id, jflag, comp, rm) and FX..TM:
  // the value on T; false for any other measure kind.
  template <class T>
  bool readBack(const model::Measure& ms, double t, const T* y, const DynamicReads<T>* reads,
                T* out) const;
  // `action` on any scalar.
  template <class T>
  void actionOn(ForceElementRef e, bool atJ, double t, const T* y, const DynamicReads<T>* reads,
                V3<T>& force, V3<T>& torque) const;
  // FX..TM(i, j): whether constraint equation eq acts between marker i and j (any marker when
  // j < 0), as the request output selects them: joints, joint primitives and motions by their
  // I and J markers, GCONs whose FUNCTION reads the markers; couplers and gears never.
  bool netForceTakes(const ConstraintEquation& eq, int marker, int other) const;
  // Whether force element e acts on `marker` (between it and `other` when other >= 0), and at
  // which of its ends (*atJ).
  bool netForceActs(ForceElementRef e, int marker, int other, bool* atJ) const;

  // The relative rotation about zJ of a rotational SPRINGDAMPER's markers, unwrapped about the
  // value at the data set's configuration: in (ref - pi, ref + pi].
  template <class T>
  T springDamperAngle(int k, const MarkerState<T>& mi, const MarkerState<T>& mj) const;

  // The displacement q = (x, y, z, a, b, c) of I relative to J in J axes and its rate
  // (translational velocity seen from J, relative angular velocity), BUSHING/FIELD/BEAM.
  template <class T>
  static void fieldDisplacement(const MarkerState<T>& mi, const MarkerState<T>& mj, T q[6],
                                T qdot[6]);

 private:
  template <class T>
  ElementLoads<T> sforceLoads(int k, double t, const T* y, const DynamicReads<T>* reads) const;
  template <class T>
  ElementLoads<T> springDamperLoads(int k, const T* y) const {
    const model::SpringDamper& s = model_->springDampers[k];
    return springDamperLoads(k, markerState(*model_, layout_, s.iMarker, y),
                             markerState(*model_, layout_, s.jMarker, y));
  }
  template <class T>
  ElementLoads<T> springDamperLoads(int k, const MarkerState<T>& mi,
                                    const MarkerState<T>& mj) const;
  template <class T>
  ElementLoads<T> linearFieldLoads(int k, double t, const T* y) const {
    const model::LinearField& f = model_->linearFields[k];
    return linearFieldLoads(k, t, markerState(*model_, layout_, f.iMarker, y),
                            markerState(*model_, layout_, f.jMarker, y));
  }
  template <class T>
  ElementLoads<T> linearFieldLoads(int k, double t, const MarkerState<T>& mi,
                                   const MarkerState<T>& mj) const;
  template <class T>
  ElementLoads<T> vectorForceLoads(int k, double t, const T* y, const DynamicReads<T>* reads) const;
  template <class T>
  ElementLoads<T> frictionLoads(int k, const T* y, const DynamicReads<T>* reads) const;
  template <class T>
  ElementLoads<T> contactElementLoads(int k, double t, const T* y) const {
    contact::ContactKinematics<T> kin(*model_, layout_, y);
    return contactElementLoads(k, t, kin);
  }
  template <class T>
  ElementLoads<T> contactElementLoads(int k, double t, contact::ContactKinematics<T>& kin) const;
  // The CONTACT elements of a residual evaluation (they are the last elements): only those the
  // shared broad phase finds near, with the marker states and poses they read computed once
  // (theory §6c, "Shared kinematics"). The others add exactly zero.
  template <class T>
  void addContactsToResidual(double t, const T* y, T* g, bool derivativesOnly) const;
  // The analysis under way (the run state's; the default before any).
  model::AnalysisMode analysisMode() const {
    return run_ != nullptr ? run_->status().mode : model::AnalysisStatus{}.mode;
  }
  template <class T>
  void applyToBody(int marker, const V3<T>& point, const V3<T>& force, const V3<T>& torque,
                   bool hasForce, bool hasTorque, const T* y, T* g) const {
    const int body = model_->parts[model_->markers[marker].part].body;
    if (body >= 0)
      applyAtPose(body, bodyPose(layout_, body, y), point, force, torque, hasForce, hasTorque, g);
  }
  template <class T>
  void applyAtPose(int body, const BodyPose<T>& pose, const V3<T>& point, const V3<T>& force,
                   const V3<T>& torque, bool hasForce, bool hasTorque, T* g) const;

  template <class T>
  static bool readBackThunk(const void* forces, const model::Measure& ms, double t, const T* y,
                            const DynamicReads<T>* reads, T* out);

  const model::Model* model_;
  StateLayout layout_;  // own copy (only body offsets are read): the owner may be moved
  std::vector<ForceElementRef> elements_;
  std::vector<double> angleReference_;  // per SPRINGDAMPER (rotational ones only)
  // Pure scratch, overwritten by every evaluation: no result depends on earlier contents.
  mutable std::vector<double> scratchValues_, scratchGrad_;
  const ExpressionRunState* run_ = nullptr;  // cumulative angles, DELAY history (the session's)
  // The CONTACT elements' shared broad phase, with its cache of the last positions (scratch:
  // its answer is a pure function of the state, contact_broad_phase.hpp).
  mutable contact::ContactBroadPhase broadPhase_;

 public:
  void setRunState(const ExpressionRunState* run) { run_ = run; }
};

// ---- implementation of the templates ----

template <class T>
T ForceElements::springDamperAngle(int k, const MarkerState<T>& mi,
                                   const MarkerState<T>& mj) const {
  // The angle from x_J to x_I about z_J, from x_I projected on the x_J-y_J plane.
  const T raw = atan2Of(dot(mi.a.c[0], mj.a.c[1]), dot(mi.a.c[0], mj.a.c[0]));
  const double twoPi = 2.0 * std::numbers::pi;
  return raw - twoPi * std::round((valueOf(raw) - angleReference_[k]) / twoPi);
}

template <class T>
void ForceElements::fieldDisplacement(const MarkerState<T>& mi, const MarkerState<T>& mj, T q[6],
                                      T qdot[6]) {
  const V3<T> d = mi.p - mj.p;
  const V3<T> dj = mj.a.tmul(d);
  // Projected rotations (AX, AY, AZ of I relative to J, not unwrapped): exact for a rotation
  // about one J axis, the usual small-angle measures otherwise.
  const V3<T>& xi = mi.a.c[0];
  const V3<T>& zi = mi.a.c[2];
  q[0] = dj.x;
  q[1] = dj.y;
  q[2] = dj.z;
  q[3] = atan2Of(-dot(zi, mj.a.c[1]), dot(zi, mj.a.c[2]));
  q[4] = atan2Of(dot(zi, mj.a.c[0]), dot(zi, mj.a.c[2]));
  q[5] = atan2Of(dot(xi, mj.a.c[1]), dot(xi, mj.a.c[0]));
  // d/dt of d as seen from J, and the angular velocity of I relative to J, in J axes.
  const V3<T> vj = mj.a.tmul(mi.pdot - mj.pdot - cross(mj.w, d));
  const V3<T> wj = mj.a.tmul(mi.w - mj.w);
  for (int c = 0; c < 3; ++c) {
    qdot[c] = vj[c];
    qdot[3 + c] = wj[c];
  }
}

template <class T>
ElementLoads<T> ForceElements::sforceLoads(int k, double t, const T* y,
                                           const DynamicReads<T>* reads) const {
  const model::SForce& f = model_->sforces[k];
  const T value = sforceValue(k, t, y, reads);
  const MarkerState<T> fi = markerState(*model_, layout_, f.iMarker, y);
  const MarkerState<T> fj = markerState(*model_, layout_, f.jMarker, y);
  ElementLoads<T> l;
  V3<T> onI;
  if (f.rotation || f.actionOnly) {
    onI = fj.a.c[2] * value;  // about or along z_J
  } else {
    const V3<T> d = fi.p - fj.p;
    onI = d * (value / norm(d));  // positive values push I and J apart
  }
  if (f.rotation) {
    l.torque = onI;
    l.hasTorque = true;
    l.reactionTorque = -onI;
  } else {
    l.force = onI;
    l.hasForce = true;
    l.reactionForce = -onI;
  }
  if (!f.actionOnly) {
    l.reactionMarker = f.jMarker;
    l.reactionPoint = fj.p;
  }
  return l;
}

template <class T>
ElementLoads<T> ForceElements::springDamperLoads(int k, const MarkerState<T>& mi,
                                                 const MarkerState<T>& mj) const {
  const model::SpringDamper& s = model_->springDampers[k];
  ElementLoads<T> l;
  l.reactionMarker = s.jMarker;
  l.reactionPoint = mj.p;
  if (s.rotational) {
    const T angle = springDamperAngle(k, mi, mj);
    const T rate = dot(mi.w - mj.w, mj.a.c[2]);
    const T value = -s.damping * rate - s.stiffness * (angle - s.freeValue) + s.preload;
    l.torque = mj.a.c[2] * value;
    l.hasTorque = true;
    l.reactionTorque = -l.torque;
  } else {
    const V3<T> d = mi.p - mj.p;
    const T length = norm(d);
    const T rate = dot(d, mi.pdot - mj.pdot) / length;
    const T value = -s.damping * rate - s.stiffness * (length - s.freeValue) + s.preload;
    l.force = d * (value / length);  // positive values push I and J apart
    l.hasForce = true;
    l.reactionForce = -l.force;
  }
  return l;
}

// FIELD with FUNCTION=USER (FIESUB): the routine's load at the values of (q, qdot); on duals
// its 6x6 partials chain the derivatives of q and qdot (docs/user-subroutines.md).
template <class T>
void userFieldLoad(const user::FieldRoutine& routine, double t, const T q[6], const T qdot[6],
                   T load[6]) {
  double d[6], v[6], field[6], kd[36], cd[36];
  for (int c = 0; c < 6; ++c) {
    d[c] = valueOf(q[c]);
    v[c] = valueOf(qdot[c]);
  }
  constexpr bool plain = std::is_same_v<T, double>;
  routine.evaluate(t, d, v, !plain, field, kd, cd);
  for (int r = 0; r < 6; ++r) {
    if constexpr (plain) {
      load[r] = field[r];
    } else {
      T out(field[r]);
      out.d = 0.0 * q[0].d;  // zero of the derivative's type
      for (int c = 0; c < 6; ++c)
        out.d = out.d + kd[r + 6 * c] * q[c].d + cd[r + 6 * c] * qdot[c].d;
      load[r] = out;
    }
  }
}

template <class T>
ElementLoads<T> ForceElements::linearFieldLoads(int k, double t, const MarkerState<T>& mi,
                                                const MarkerState<T>& mj) const {
  const model::LinearField& f = model_->linearFields[k];
  T q[6], qdot[6];
  fieldDisplacement(mi, mj, q, qdot);
  T load[6];
  // Multi-direction duals (the element-local Newton matrix) never reach a USER field
  // (isStateLocal): userFieldLoad is instantiated for double and Dual only.
  constexpr bool userCapable = std::is_same_v<T, double> || requires(T x) { x.d = x.d * 1.0; };
  if (f.user) {
    if constexpr (userCapable) userFieldLoad(*f.user, t, q, qdot, load);
  } else {
    for (int r = 0; r < 6; ++r) {
      T sum = T(f.preload(r));
      for (int c = 0; c < 6; ++c) {
        if (f.stiffness(r, c) != 0.0) sum = sum - f.stiffness(r, c) * (q[c] - f.reference(c));
        if (f.damping(r, c) != 0.0) sum = sum - f.damping(r, c) * qdot[c];
      }
      load[r] = sum;
    }
  }
  ElementLoads<T> l;
  l.force = mj.a * V3<T>(load[0], load[1], load[2]);
  l.torque = mj.a * V3<T>(load[3], load[4], load[5]);
  l.hasForce = l.hasTorque = true;
  // The reaction acts on J's part through I's origin: equal and opposite force, and a torque
  // on J that includes the moment of the force about J (the element is in equilibrium).
  l.reactionMarker = f.jMarker;
  l.reactionPoint = mi.p;
  l.reactionForce = -l.force;
  l.reactionTorque = -l.torque;
  return l;
}

template <class T>
ElementLoads<T> ForceElements::vectorForceLoads(int k, double t, const T* y,
                                                const DynamicReads<T>* reads) const {
  const model::VectorForce& f = model_->vectorForces[k];
  const MarkerState<T> mi = markerState(*model_, layout_, f.iMarker, y);
  const M3<T> rm = markerState(*model_, layout_, f.rmMarker, y).a;
  const DynamicReads<T> r = readsWith(reads);
  T c[6];
  for (int n = 0; n < 6; ++n)
    c[n] = f.components[n] ? evaluateFunction(*model_, layout_, *f.components[n], t, y,
                                              scratchValues_, scratchGrad_, &r, run_)
                           : T(0.0);
  ElementLoads<T> l;
  l.hasForce = f.kind != model::VectorForce::Kind::VTorque;
  l.hasTorque = f.kind != model::VectorForce::Kind::VForce;
  l.force = rm * V3<T>(c[0], c[1], c[2]);
  l.torque = rm * V3<T>(c[3], c[4], c[5]);
  // The floating J marker is kept at I: the reaction acts on its part at I's location.
  l.reactionMarker = f.jFloat;
  l.reactionPoint = mi.p;
  l.reactionForce = -l.force;
  l.reactionTorque = -l.torque;
  return l;
}

template <class T>
ElementLoads<T> ForceElements::contactElementLoads(int k, double t,
                                                   contact::ContactKinematics<T>& kin) const {
  const model::Contact& c = model_->contacts[k];
  // DYNAMICS_ONLY: friction in dynamic analyses only (ADAMS); the mode is the session's.
  const bool friction = c.friction == model::Contact::Friction::On ||
                        (c.friction == model::Contact::Friction::DynamicsOnly &&
                         analysisMode() == model::AnalysisMode::Dynamics);
  const contact::ContactLoads<T> cl = contact::contactLoads(*model_, layout_, c, kin, friction, t);
  ElementLoads<T> l;
  l.force = cl.force;
  l.torque = cl.torqueAtI;
  l.hasForce = l.hasTorque = true;
  l.reactionMarker = c.jMarker;
  l.reactionPoint = cl.jOrigin;
  l.reactionForce = -cl.force;
  l.reactionTorque = cl.torqueAtJ;
  return l;
}

template <class T>
ElementLoads<T> ForceElements::loads(ForceElementRef e, double t, const T* y,
                                     const DynamicReads<T>* reads) const {
  switch (e.kind) {
    case ForceElementKind::SForce:
      return sforceLoads(e.index, t, y, reads);
    case ForceElementKind::SpringDamper:
      return springDamperLoads(e.index, y);
    case ForceElementKind::LinearField:
      return linearFieldLoads(e.index, t, y);
    case ForceElementKind::VectorForce:
      return vectorForceLoads(e.index, t, y, reads);
    case ForceElementKind::Friction:
      return frictionLoads(e.index, y, reads);
    case ForceElementKind::MultiPoint:
      return {};  // multiPointLoads
    case ForceElementKind::Contact:
      return contactElementLoads(e.index, t, y);
  }
  return {};
}

template <class T>
ElementLoads<T> ForceElements::frictionLoads(int k, const T* y,
                                             const DynamicReads<T>* reads) const {
  const friction::FrictionAnchor* anchor = run_ != nullptr ? run_->frictionAnchor(k) : nullptr;
  const friction::FrictionResult<T> r =
      friction::frictionLoads(*model_, layout_, reads != nullptr ? reads->constraints : nullptr, k,
                              y, anchor, analysisMode());
  const model::Joint& joint = model_->joints[model_->frictions[k].joint];
  ElementLoads<T> l;
  l.force = r.force;
  l.torque = r.torque;
  l.hasForce = l.hasTorque = true;
  // Equal and opposite on J's part, at the I origin (the contact the joint makes).
  l.reactionMarker = joint.jMarker;
  l.reactionPoint = markerState(*model_, layout_, joint.iMarker, y).p;
  l.reactionForce = -l.force;
  l.reactionTorque = -l.torque;
  return l;
}

template <class T>
void ForceElements::multiPointLoads(int k, const T* y, std::vector<V3<T>>& force,
                                    std::vector<V3<T>>& torque, V3<T>& jForce,
                                    V3<T>& jTorque) const {
  const model::MultiPointForce& f = model_->nforces[k];
  const int n = static_cast<int>(f.iMarkers.size());
  const MarkerState<T> mj = markerState(*model_, layout_, f.jMarker, y);
  std::vector<T> q(static_cast<size_t>(6 * n)), qdot(static_cast<size_t>(6 * n));
  std::vector<V3<T>> points(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const MarkerState<T> mi = markerState(*model_, layout_, f.iMarkers[i], y);
    fieldDisplacement(mi, mj, &q[6 * i], &qdot[6 * i]);
    points[i] = mi.p;
  }
  force.resize(static_cast<size_t>(n));
  torque.resize(static_cast<size_t>(n));
  jForce = V3<T>(T(0.0), T(0.0), T(0.0));
  jTorque = jForce;
  for (int i = 0; i < n; ++i) {
    T load[6];
    for (int r = 0; r < 6; ++r) {
      const int row = 6 * i + r;
      T sum = T(f.preload(row));
      for (int c = 0; c < 6 * n; ++c) {
        if (f.stiffness(row, c) != 0.0) sum = sum - f.stiffness(row, c) * (q[c] - f.length(c));
        if (f.damping(row, c) != 0.0) sum = sum - f.damping(row, c) * qdot[c];
      }
      load[r] = sum;
    }
    force[i] = mj.a * V3<T>(load[0], load[1], load[2]);
    torque[i] = mj.a * V3<T>(load[3], load[4], load[5]);
    // J balances every I load: equal and opposite forces, and their moments about J.
    jForce = jForce - force[i];
    jTorque = jTorque - torque[i] - cross(points[i] - mj.p, force[i]);
  }
}

template <class T>
void ForceElements::multiPointAction(int k, int marker, const T* y, V3<T>& force,
                                     V3<T>& torque) const {
  std::vector<V3<T>> f, tq;
  V3<T> fj, tj;
  multiPointLoads(k, y, f, tq, fj, tj);
  const model::MultiPointForce& nf = model_->nforces[k];
  force = V3<T>(T(0.0), T(0.0), T(0.0));
  torque = force;
  if (marker == nf.jMarker) {
    force = fj;
    torque = tj;
  }
  for (size_t i = 0; i < nf.iMarkers.size(); ++i)
    if (nf.iMarkers[i] == marker) {
      force = force + f[i];
      torque = torque + tq[i];
    }
}

template <class T>
void ForceElements::applyAtPose(int body, const BodyPose<T>& pose, const V3<T>& point,
                                const V3<T>& force, const V3<T>& torque, bool hasForce,
                                bool hasTorque, T* g) const {
  applyLoad(pose, point, force, torque, hasForce, hasTorque,
            g + layout_.body(body) + StateLayout::kV, g + layout_.body(body) + StateLayout::kW);
}

template <class T>
void ForceElements::applyLoad(const BodyPose<T>& pose, const V3<T>& point, const V3<T>& force,
                              const V3<T>& torque, bool hasForce, bool hasTorque, T* gv, T* gw) {
  // Force in ground; torque about the CM in body axes (the rows' convention, theory.md §4).
  if (hasForce) {
    const V3<T> nb = pose.a.tmul(cross(point - pose.r, force));
    for (int c = 0; c < 3; ++c) {
      gv[c] = gv[c] - force[c];
      gw[c] = gw[c] - nb[c];
    }
  }
  if (hasTorque) {
    const V3<T> nb = pose.a.tmul(torque);
    for (int c = 0; c < 3; ++c) gw[c] = gw[c] - nb[c];
  }
}

template <class T>
void ForceElements::addToResidual(double t, const T* y, T* g, const DynamicReads<T>* reads,
                                  bool derivativesOnly, const char* skip) const {
  for (size_t k = 0; k < elements_.size(); ++k) {
    const ForceElementRef& e = elements_[k];
    if (skip != nullptr && skip[k] != 0) continue;
    if (e.kind == ForceElementKind::MultiPoint) {
      std::vector<V3<T>> f, tq;
      V3<T> fj, tj;
      multiPointLoads(e.index, y, f, tq, fj, tj);
      const model::MultiPointForce& nf = model_->nforces[e.index];
      for (size_t i = 0; i < nf.iMarkers.size(); ++i)
        applyToBody(nf.iMarkers[i], markerState(*model_, layout_, nf.iMarkers[i], y).p, f[i], tq[i],
                    true, true, y, g);
      applyToBody(nf.jMarker, markerState(*model_, layout_, nf.jMarker, y).p, fj, tj, true, true, y,
                  g);
      continue;
    }
    if (e.kind == ForceElementKind::Contact) break;  // the last ones: addContactsToResidual
    const ElementLoads<T> l = loads(e, t, y, reads);
    const int im = iMarker(e);
    const MarkerState<T> mi = markerState(*model_, layout_, im, y);
    applyToBody(im, mi.p, l.force, l.torque, l.hasForce, l.hasTorque, y, g);
    if (l.reactionMarker >= 0)
      applyToBody(l.reactionMarker, l.reactionPoint, l.reactionForce, l.reactionTorque, l.hasForce,
                  l.hasTorque, y, g);
  }
  if (!model_->contacts.empty()) addContactsToResidual(t, y, g, derivativesOnly);
}

template <class T>
void ForceElements::addContactsToResidual(double t, const T* y, T* g, bool derivativesOnly) const {
  const std::vector<int>& near = broadPhase_.near(y);
  contact::ContactKinematics<T> kin(*model_, layout_, y, &broadPhase_.slots());
  // Which bodies' states carry a derivative (all, unless derivativesOnly on dual numbers).
  const std::vector<char>& seeded = broadPhase_.seeded(y, derivativesOnly);
  // In element order, as the loop over every element applied them: each body row receives the
  // same sums in the same order, less the exact zeros of the elements apart.
  for (const int k : near) {
    const model::Contact& c = model_->contacts[k];
    if (!c.active) continue;  // zero loads (contactLoads)
    const int bi = model_->parts[model_->markers[c.iMarker].part].body;
    const int bj = model_->parts[model_->markers[c.jMarker].part].body;
    if (!broadPhase_.eitherSeeded(seeded, bi, bj)) continue;
    const ElementLoads<T> l = contactElementLoads(k, t, kin);
    if (bi >= 0)
      applyAtPose(bi, kin.pose(bi), kin.marker(c.iMarker).p, l.force, l.torque, true, true, g);
    if (bj >= 0)
      applyAtPose(bj, kin.pose(bj), l.reactionPoint, l.reactionForce, l.reactionTorque, true, true,
                  g);
  }
}

}  // namespace openmss::mechanics

#include "mechanics/force_read_back.hpp"  // IWYU pragma: export
