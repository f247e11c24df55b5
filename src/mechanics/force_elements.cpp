#include "mechanics/force_elements.hpp"

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
  add(ForceElementKind::Contact, model.contacts.size());
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
    case ForceElementKind::Contact: return model_->contacts[e.index].jMarker;
  }
  return -1;
}

void ForceElements::action(ForceElementRef e, bool atJ, double t, const double* y,
                           Eigen::Vector3d& force, Eigen::Vector3d& torque,
                           const DynamicReads<double>* reads) const {
  const ElementLoads<double> l = loads(e, t, y, reads);
  force.setZero();
  torque.setZero();
  if (!atJ) {
    if (l.hasForce) force = toEigen(l.force);
    if (l.hasTorque) torque = toEigen(l.torque);
    return;
  }
  if (l.reactionMarker < 0) return;
  const model::Marker& mk = model_->markers[l.reactionMarker];
  // A floating marker sits at the point where the reaction acts.
  const V3<double> origin =
      mk.floating ? l.reactionPoint : markerState(*model_, layout_, l.reactionMarker, y).p;
  if (l.hasForce) {
    force = toEigen(l.reactionForce);
    torque = toEigen(cross(l.reactionPoint - origin, l.reactionForce));
  }
  if (l.hasTorque) torque += toEigen(l.reactionTorque);
}

}  // namespace openmss::mechanics
