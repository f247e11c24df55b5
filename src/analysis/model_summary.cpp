#include "analysis/model_summary.hpp"

#include "analysis/analysis_context.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {

DegreeOfFreedomCount countDegreesOfFreedom(mechanics::MultibodySystem& system,
                                           const Eigen::VectorXd& y) {
  const model::Model& m = system.model();
  DegreeOfFreedomCount c;
  c.gruebler = mechanics::ConstraintSet::grueblerCount(m);
  c.loops = mechanics::countLoops(m);
  const auto redundancy = mechanics::removeRedundantConstraints(system, y);
  c.degreesOfFreedom = 6 * m.bodyCount() - redundancy.rank;
  c.removed = redundancy.removed;
  return c;
}

std::vector<std::string> modelSummaryLines(const mechanics::MultibodySystem& system,
                                           const DegreeOfFreedomCount& count) {
  const model::Model& m = system.model();
  std::vector<std::string> out;
  out.push_back("");
  out.push_back(" Model summary");
  out.push_back("   Units:                " + m.units.description +
                ", UCF = " + formatNumber("%.10g", m.units.ucf));
  out.push_back("   Moving parts:         " + std::to_string(m.bodyCount()) + " (plus ground)");
  out.push_back("   Markers:              " + std::to_string(m.markers.size()));
  out.push_back("   Joints:               " + std::to_string(m.joints.size()));
  out.push_back("   Motions:              " + std::to_string(m.motions.size()));
  out.push_back("   SFORCEs:              " + std::to_string(m.sforces.size()));
  out.push_back(
      "   Other force elements: " +
      std::to_string(m.springDampers.size() + m.linearFields.size() + m.vectorForces.size()) +
      " (SPRINGDAMPER, BUSHING, FIELD, BEAM, VFORCE, VTORQUE, GFORCE)");
  if (!m.frictions.empty())  // docs/theory.md §13
    out.push_back("   Joint frictions:      " + std::to_string(m.frictions.size()));
  if (!m.contacts.empty())  // docs/theory.md §6c
    out.push_back("   Contacts:             " + std::to_string(m.contacts.size()) + " (CONTACT)");
  if (m.userDifferentialCount() + m.userAlgebraicCount() > 0)  // docs/theory.md §4a
    out.push_back("   User equations:       " + std::to_string(m.variables.size()) + " VARIABLE, " +
                  std::to_string(m.diffs.size()) + " DIFF, " +
                  std::to_string(m.linearStates.size()) + " LSE/TFSISO, " +
                  std::to_string(m.generalStates.size()) + " GSE; " +
                  std::to_string(m.userDifferentialCount()) + " user states integrated");
  out.push_back("   Requests:             " + std::to_string(m.requests.size()));
  out.push_back("   Constraint equations: " + std::to_string(system.constraints().size()));
  out.push_back("   Gruebler count:       " + std::to_string(count.gruebler) +
                " degrees of freedom");
  out.push_back("   Degrees of freedom:   " + std::to_string(count.degreesOfFreedom) +
                " (from the rank of the constraint Jacobian)");
  out.push_back(
      "   Loops:                " + std::to_string(count.loops.independent) + " independent, " +
      (count.loops.enumerated ? std::to_string(count.loops.dependent) : "(not enumerated)") +
      " dependent");
  return out;
}

}  // namespace openmss::analysis
