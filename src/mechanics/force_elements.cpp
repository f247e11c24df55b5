#include "mechanics/force_elements.hpp"

#include <algorithm>

namespace openmss::mechanics {

namespace {

// A marker's axes in ground at the data set's configuration.
Eigen::Matrix3d initialAxes(const model::Model& m, int marker) {
  const model::Marker& mk = m.markers[marker];
  return m.parts[mk.part].orientation * mk.orientation;
}

}  // namespace

ForceElements::ForceElements(const model::Model& model) : model_(&model) {
  layout_.bodies = model.bodyCount();
  // Functions may read user states (VARVAL, DIF, ...): the user blocks follow the bodies.
  layout_.userDifferential = model.userDifferentialCount();
  layout_.userAlgebraic = model.userAlgebraicCount();
  auto add = [&](ForceElementKind kind, size_t n) {
    for (size_t k = 0; k < n; ++k) elements_.push_back({kind, static_cast<int>(k)});
  };
  add(ForceElementKind::SForce, model.sforces.size());
  add(ForceElementKind::SpringDamper, model.springDampers.size());
  add(ForceElementKind::LinearField, model.linearFields.size());
  add(ForceElementKind::VectorForce, model.vectorForces.size());
  add(ForceElementKind::Friction, model.frictions.size());
  add(ForceElementKind::MultiPoint, model.nforces.size());
  add(ForceElementKind::Contact, model.contacts.size());  // the last: addContactsToResidual
  if (!model.contacts.empty()) broadPhase_ = contact::ContactBroadPhase(model, layout_);
  for (const model::SpringDamper& s : model.springDampers) {
    double reference = 0.0;
    if (s.rotational) {
      const Eigen::Matrix3d ai = initialAxes(model, s.iMarker);
      const Eigen::Matrix3d aj = initialAxes(model, s.jMarker);
      reference = std::atan2(ai.col(0).dot(aj.col(1)), ai.col(0).dot(aj.col(0)));
    }
    angleReference_.push_back(reference);
  }
}

int ForceElements::iMarker(ForceElementRef e) const {
  switch (e.kind) {
    case ForceElementKind::SForce: return model_->sforces[e.index].iMarker;
    case ForceElementKind::SpringDamper: return model_->springDampers[e.index].iMarker;
    case ForceElementKind::LinearField: return model_->linearFields[e.index].iMarker;
    case ForceElementKind::VectorForce: return model_->vectorForces[e.index].iMarker;
    case ForceElementKind::Friction: return model_->joints[model_->frictions[e.index].joint].iMarker;
    case ForceElementKind::MultiPoint: return -1;
    case ForceElementKind::Contact: return model_->contacts[e.index].iMarker;
  }
  return -1;
}

int ForceElements::jMarker(ForceElementRef e) const {
  switch (e.kind) {
    case ForceElementKind::SForce: return model_->sforces[e.index].jMarker;
    case ForceElementKind::SpringDamper: return model_->springDampers[e.index].jMarker;
    case ForceElementKind::LinearField: return model_->linearFields[e.index].jMarker;
    case ForceElementKind::VectorForce: return model_->vectorForces[e.index].jFloat;
    case ForceElementKind::Friction: return model_->joints[model_->frictions[e.index].joint].jMarker;
    case ForceElementKind::MultiPoint: return model_->nforces[e.index].jMarker;
    case ForceElementKind::Contact: return model_->contacts[e.index].jMarker;
  }
  return -1;
}

void ForceElements::action(ForceElementRef e, bool atJ, double t, const double* y,
                           Eigen::Vector3d& force, Eigen::Vector3d& torque,
                           const DynamicReads<double>* reads) const {
  V3<double> f, tq;
  actionOn(e, atJ, t, y, reads, f, tq);
  force = toEigen(f);
  torque = toEigen(tq);
}

namespace {

// True when GCON g's FUNCTION reads `marker` (as i, j or k of a measure).
bool gconReads(const model::GeneralConstraint& g, int marker) {
  for (const model::Measure& m : g.function.measures)
    if (m.i == marker || m.j == marker || m.k == marker) return true;
  return false;
}

}  // namespace

bool ForceElements::netForceTakes(const ConstraintEquation& eq, int marker, int other) const {
  const model::Model& m = *model_;
  auto acts = [&](int a, int b) {
    return (a == marker && (other < 0 || b == other)) || (b == marker && (other < 0 || a == other));
  };
  if (eq.coupler >= 0 || eq.gear >= 0) return false;
  if (eq.joint >= 0) return acts(m.joints[eq.joint].iMarker, m.joints[eq.joint].jMarker);
  if (eq.jprim >= 0) return acts(m.jprims[eq.jprim].iMarker, m.jprims[eq.jprim].jMarker);
  if (eq.motion >= 0) return acts(m.motions[eq.motion].iMarker, m.motions[eq.motion].jMarker);
  if (eq.ptcv >= 0) return acts(m.ptcvs[eq.ptcv].iMarker, m.ptcvs[eq.ptcv].rmMarker);
  if (eq.cvcv >= 0) return acts(m.cvcvs[eq.cvcv].iRm, m.cvcvs[eq.cvcv].jRm);
  if (eq.gcon >= 0)
    return gconReads(m.gcons[eq.gcon], marker) &&
           (other < 0 || gconReads(m.gcons[eq.gcon], other));
  return false;
}

bool ForceElements::isStateLocal(ForceElementRef e) const {
  // A FIELD with FUNCTION=USER calls user code (FIESUB); every other kind reads expressions,
  // user code, the constraints or run state (friction anchors, contact).
  if (e.kind == ForceElementKind::SpringDamper) return true;
  return e.kind == ForceElementKind::LinearField && !model_->linearFields[e.index].user;
}

bool ForceElements::netForceActs(ForceElementRef e, int marker, int other, bool* atJ) const {
  if (e.kind == ForceElementKind::MultiPoint) {
    // On J (between J and any of its I markers) or on an I marker (between it and J).
    const model::MultiPointForce& f = model_->nforces[e.index];
    *atJ = marker == f.jMarker;
    const bool isI = std::find(f.iMarkers.begin(), f.iMarkers.end(), marker) != f.iMarkers.end();
    if (*atJ)
      return other < 0 || std::find(f.iMarkers.begin(), f.iMarkers.end(), other) != f.iMarkers.end();
    return isI && (other < 0 || other == f.jMarker);
  }
  const int i = iMarker(e), j = jMarker(e);
  const bool onI = i == marker && (other < 0 || j == other);
  const bool onJ = j == marker && (other < 0 || i == other);
  *atJ = !onI;
  return onI || onJ;
}

}  // namespace openmss::mechanics
