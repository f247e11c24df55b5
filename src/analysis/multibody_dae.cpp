#include "analysis/multibody_dae.hpp"

namespace openmss::analysis {
namespace {

const char* bodyEntry(int offset, bool equation) {
  using L = mechanics::StateLayout;
  static const char* vars[L::kPerBody] = {"X", "Y", "Z", "E0", "E1", "E2", "E3",
                                          "VX", "VY", "VZ", "WX", "WY", "WZ", "MU"};
  static const char* eqs[L::kPerBody] = {
      "dX/dt = VX", "dY/dt = VY", "dZ/dt = VZ", "dE0/dt", "dE1/dt", "dE2/dt", "dE3/dt",
      "force balance X", "force balance Y", "force balance Z", "moment balance X",
      "moment balance Y", "moment balance Z", "Euler-parameter normalisation"};
  return equation ? eqs[offset] : vars[offset];
}

}  // namespace

std::string MultibodyDae::equationName(int row) const {
  const auto& l = system_.layout();
  const auto& m = system_.model();
  if (row < 0) return "(none)";
  if (row < l.kPerBody * l.bodies) {
    const int b = row / l.kPerBody;
    return std::string(bodyEntry(row % l.kPerBody, true)) + " of PART/" +
           std::to_string(m.parts[m.movingParts[b]].id);
  }
  return system_.constraints().describe(row - l.kPerBody * l.bodies, m);
}

std::string MultibodyDae::variableName(int i) const {
  const auto& l = system_.layout();
  const auto& m = system_.model();
  if (i < 0) return "(none)";
  if (i < l.kPerBody * l.bodies) {
    const int b = i / l.kPerBody;
    return std::string(bodyEntry(i % l.kPerBody, false)) + " of PART/" +
           std::to_string(m.parts[m.movingParts[b]].id);
  }
  return "reaction of " + system_.constraints().describe(i - l.kPerBody * l.bodies, m);
}

}  // namespace openmss::analysis
