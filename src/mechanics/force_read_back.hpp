#pragma once
// Force read-backs inside functions (docs/theory.md §4d): SFORCE, SPDP, BUSH, FIELD, BEAM,
// VFORCE, VTORQ, GFORCE (id, jflag, comp, rm) and FX FY FZ FM TX TY TZ TM (i [,j] [,k]),
// templated on the scalar so that a force, VARIABLE or DIFF function reading them gets their
// exact partials (the read element's own expression derivatives, through the chain rule) in
// the Newton matrix. They are the same numbers the outputs report (analysis/request_values.cpp):
// one code path, ForceElements::loads, for the residual, the requests and the read-backs.
// Included at the end of force_elements.hpp (these are member templates of ForceElements).

#include <optional>

#include "mechanics/dynamic_measures.hpp"
#include "mechanics/friction/friction_output.hpp"

namespace openmss::mechanics {

// The applied force element a read-back measure names (SFORCE, SPDP, BUSH, ...), if any.
inline std::optional<ForceElementRef> forceElementOfMeasure(model::MeasureKind kind, int element) {
  using K = model::MeasureKind;
  using FK = ForceElementKind;
  switch (kind) {
    case K::SForceForce:
      return ForceElementRef{FK::SForce, element};
    case K::SpringDamperForce:
      return ForceElementRef{FK::SpringDamper, element};
    case K::BushingForce:
    case K::FieldForce:
    case K::BeamForce:
      return ForceElementRef{FK::LinearField, element};
    case K::VForceForce:
    case K::VTorqueForce:
    case K::GForceForce:
      return ForceElementRef{FK::VectorForce, element};
    default:
      return std::nullopt;
  }
}

template <class T>
DynamicReads<T> ForceElements::readsWith(const DynamicReads<T>* reads) const {
  DynamicReads<T> r = reads != nullptr ? *reads : DynamicReads<T>{};
  r.forces = this;
  r.forceReadBack = &ForceElements::readBackThunk<T>;
  return r;
}

template <class T>
bool ForceElements::readBackThunk(const void* forces, const model::Measure& ms, double t,
                                  const T* y, const DynamicReads<T>* reads, T* out) {
  return static_cast<const ForceElements*>(forces)->readBack(ms, t, y, reads, out);
}

template <class T>
void ForceElements::actionOn(ForceElementRef e, bool atJ, double t, const T* y,
                             const DynamicReads<T>* reads, V3<T>& force, V3<T>& torque) const {
  const ElementLoads<T> l = loads(e, t, y, reads);
  const V3<T> zero(T(0.0), T(0.0), T(0.0));
  force = zero;
  torque = zero;
  if (!atJ) {
    if (l.hasForce) force = l.force;
    if (l.hasTorque) torque = l.torque;
    return;
  }
  if (l.reactionMarker < 0) return;
  const model::Marker& mk = model_->markers[l.reactionMarker];
  // A floating marker sits at the point where the reaction acts.
  const V3<T> origin =
      mk.floating ? l.reactionPoint : markerState(*model_, layout_, l.reactionMarker, y).p;
  if (l.hasForce) {
    force = l.reactionForce;
    torque = cross(l.reactionPoint - origin, l.reactionForce);
  }
  if (l.hasTorque) torque = torque + l.reactionTorque;
}

template <class T>
bool ForceElements::readBack(const model::Measure& ms, double t, const T* y,
                             const DynamicReads<T>* reads, T* out) const {
  if (ms.kind == model::MeasureKind::FrictionOutput) {
    // FRICTION(id, index): the friction's loads and kinematics on T, as its force element
    // computes them (the joint's multipliers through `reads`; docs/theory.md §13).
    const friction::FrictionAnchor* anchor =
        run_ != nullptr ? run_->frictionAnchor(ms.element) : nullptr;
    *out = friction::frictionOutputOf(
        friction::frictionLoads(*model_, layout_, reads != nullptr ? reads->constraints : nullptr,
                                ms.element, y, anchor, analysisMode()),
        ms.component);
    return true;
  }
  const std::optional<ForceElementRef> element = forceElementOfMeasure(ms.kind, ms.element);
  if (!element && ms.kind != model::MeasureKind::NetForce &&
      ms.kind != model::MeasureKind::NForceForce)
    return false;
  const DynamicReads<T> r = readsWith(reads);
  V3<T> force, torque;
  if (ms.kind == model::MeasureKind::NForceForce) {
    multiPointAction(ms.element, ms.i, y, force, torque);  // NFORCE(id, marker, comp, rm)
  } else if (element) {
    actionOn(*element, ms.atJ == 1, t, y, &r, force, torque);
  } else {
    // FX..TM (i [,j] [,k]): every constraint reaction and applied force acting on marker i,
    // only those between i and j when j is given (as the request output, request_values.cpp).
    const V3<T> zero(T(0.0), T(0.0), T(0.0));
    force = zero;
    torque = zero;
    if (r.constraints != nullptr)
      constraintReactionOn(
          *model_, layout_, *r.constraints,
          [&](const ConstraintEquation& eq) { return netForceTakes(eq, ms.i, ms.j); }, ms.i, y,
          force, torque);
    V3<T> f, tq;
    for (const ForceElementRef& e : elements_) {
      bool atJ = false;
      if (!netForceActs(e, ms.i, ms.j, &atJ)) continue;
      if (e.kind == ForceElementKind::MultiPoint)
        multiPointAction(e.index, ms.i, y, f, tq);
      else
        actionOn(e, atJ, t, y, &r, f, tq);
      force = force + f;
      torque = torque + tq;
    }
  }
  const M3<T> k = ms.k >= 0 ? markerState(*model_, layout_, ms.k, y).a
                            : M3<T>::from(Eigen::Matrix3d::Identity().eval());
  switch (ms.component) {
    case 1:
      *out = magnitudeOf(force);
      break;
    case 2:
    case 3:
    case 4:
      *out = dot(force, k.c[ms.component - 2]);
      break;
    case 5:
      *out = magnitudeOf(torque);
      break;
    default:
      *out = dot(torque, k.c[ms.component - 6]);
      break;
  }
  return true;
}

}  // namespace openmss::mechanics
