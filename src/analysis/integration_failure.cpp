#include "analysis/integration_failure.hpp"

#include <cmath>

#include "analysis/analysis_context.hpp"

namespace openmss::analysis {

std::string forceElementName(const model::Model& m, const mechanics::ForceElementRef& e) {
  using K = mechanics::ForceElementKind;
  switch (e.kind) {
    case K::SForce:
      return "SFORCE/" + std::to_string(m.sforces[e.index].id);
    case K::SpringDamper:
      return "SPRINGDAMPER/" + std::to_string(m.springDampers[e.index].id);
    case K::LinearField: {
      const auto& f = m.linearFields[e.index];
      const char* name = f.kind == model::LinearField::Kind::Bushing ? "BUSHING"
                         : f.kind == model::LinearField::Kind::Beam  ? "BEAM"
                                                                     : "FIELD";
      return std::string(name) + "/" + std::to_string(f.id);
    }
    case K::VectorForce: {
      const auto& f = m.vectorForces[e.index];
      const char* name = f.kind == model::VectorForce::Kind::VTorque  ? "VTORQUE"
                         : f.kind == model::VectorForce::Kind::GForce ? "GFORCE"
                                                                      : "VFORCE";
      return std::string(name) + "/" + std::to_string(f.id);
    }
    case K::Friction:
      return "FRICTION/" + std::to_string(m.frictions[e.index].id);
    case K::MultiPoint:
      return "NFORCE/" + std::to_string(m.nforces[e.index].id);
    case K::Contact:
      return "CONTACT/" + std::to_string(m.contacts[e.index].id);
  }
  return "?";
}

std::string describeIntegrationFailure(const model::Model& m,
                                       const mechanics::MultibodySystem& system,
                                       const MultibodyDae& dae,
                                       const solvers::Integrator& integrator) {
  const auto& f = integrator.failure();
  std::string text =
      "the dynamic analysis failed at time " + formatNumber("%.6E", f.time) + " (step size " +
      formatNumber("%.3E", f.stepSize) + "): " + f.reason +
      ". The equation with the largest error is " + dae.equationName(f.worstEquation) + " (" +
      formatNumber("%.3E", f.worstResidual) + "); the variable changing most is " +
      dae.variableName(f.worstVariable) + " (" + formatNumber("%.3E", f.worstChange) + ")";
  // Name the applied force that dominates at the last accepted state: a force that blows up
  // or jumps (an IF in its function) is the usual cause of a failed step.
  std::string forces;
  double biggest = -1.0;
  const double t = integrator.t();
  for (const auto& e : system.forceElements().elements()) {
    Eigen::Vector3d fk, tk;
    system.forceElements().action(e, false, t, integrator.y().data(), fk, tk);
    const double size = std::max(fk.norm(), tk.norm());
    if (!std::isfinite(size) || size > biggest) {
      biggest = size;
      forces = "; the largest applied force at t = " + formatNumber("%.6E", t) + " is " +
               forceElementName(m, e) + " (" + formatNumber("%.3E", size) + ")";
      if (!std::isfinite(size)) break;
    }
  }
  return text + forces;
}

}  // namespace openmss::analysis
