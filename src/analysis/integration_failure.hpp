#pragma once
// The diagnosis of a failed dynamic analysis: where and why the integrator gave up, the
// equation with the largest error, the variable changing most, and the applied force that
// dominates at the last accepted state (a force that blows up is the usual cause).

#include <string>

#include "analysis/multibody_dae.hpp"
#include "model/model.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

// One sentence for the error diagnostic of `integrator`'s failure.
std::string describeIntegrationFailure(const model::Model& model,
                                       const mechanics::MultibodySystem& system,
                                       const MultibodyDae& dae,
                                       const solvers::Integrator& integrator);

// "SFORCE/104", "BUSHING/3", ... for diagnostics.
std::string forceElementName(const model::Model& model, const mechanics::ForceElementRef& e);

}  // namespace openmss::analysis
