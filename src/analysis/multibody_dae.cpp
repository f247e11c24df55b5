#include "analysis/multibody_dae.hpp"

#include <algorithm>

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

// The user state at index i (docs/theory.md §4a): "DIFF/3 state", "VARIABLE/2", ...
std::string userEntry(const mechanics::StateLayout& l, const model::Model& m, int i,
                      bool equation) {
  const int nv = static_cast<int>(m.variables.size());
  const int nd = static_cast<int>(m.diffs.size());
  if (l.isUserDifferential(i)) {
    const int k = i - l.userDiff(0);
    if (k < nd)
      return (equation ? "dDIF/dt = DIF1 of DIFF/" : "DIF of DIFF/") + std::to_string(m.diffs[k].id);
    for (const auto& e : m.linearStates)
      if (k >= e.firstState && k < e.firstState + e.a.rows())
        return std::string(equation ? "state equation " : "state ") +
               std::to_string(k - e.firstState + 1) + " of " +
               (e.kind == model::LinearStateElement::Kind::Lse ? "LSE/" : "TFSISO/") +
               std::to_string(e.id);
    for (const auto& e : m.generalStates)
      if (k >= e.firstState && k < e.firstState + e.ns)
        return std::string(equation ? "state equation " : "state ") +
               std::to_string(k - e.firstState + 1) + " of GSE/" + std::to_string(e.id);
    return "user state";
  }
  const int k = i - l.userAlg(0);
  if (k < nv) return "VARIABLE/" + std::to_string(m.variables[k].id) + (equation ? " function" : "");
  for (const auto& e : m.generalStates)  // GSE outputs, after the DIFF derivatives
    if (k >= e.firstOutput && k < e.firstOutput + e.no)
      return std::string(equation ? "output equation " : "output ") +
             std::to_string(k - e.firstOutput + 1) + " of GSE/" + std::to_string(e.id);
  return std::string(equation ? "FUNCTION of DIFF/" : "DIF1 of DIFF/") +
         std::to_string(m.diffs[k - nv].id);
}

}  // namespace

void MultibodyDae::addRateTerm(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
  // The y' part of MultibodySystem::residual's body rows, in its operation order.
  using L = mechanics::StateLayout;
  for (int b = 0; b < system_.layout().bodies; ++b) {
    const int o = system_.layout().body(b);
    const double m = system_.bodyMass(b);
    for (int c = 0; c < 3; ++c) out(o + L::kV + c) += m * d(o + L::kV + c);
    const Eigen::Matrix3d& jm = system_.bodyInertia(b);
    for (int r = 0; r < 3; ++r)
      out(o + L::kW + r) +=
          jm(r, 0) * d(o + L::kW) + jm(r, 1) * d(o + L::kW + 1) + jm(r, 2) * d(o + L::kW + 2);
  }
}

std::string MultibodyDae::equationName(int row) const {
  const auto& l = system_.layout();
  const auto& m = system_.model();
  if (row < 0) return "(none)";
  if (row < l.kPerBody * l.bodies) {
    const int b = row / l.kPerBody;
    return std::string(bodyEntry(row % l.kPerBody, true)) + " of PART/" +
           std::to_string(m.parts[m.movingParts[b]].id);
  }
  if (l.isUser(row)) return userEntry(l, m, row, true);
  return system_.constraints().describe(row - l.lambda(0), m);
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
  if (l.isUser(i)) return userEntry(l, m, i, false);
  return "reaction of " + system_.constraints().describe(i - l.lambda(0), m);
}

const Eigen::SparseMatrix<double>* MultibodyDae::pattern() {
  if (!havePattern_) {
    // Near-pair pattern: before any state is known, no CONTACT couples (the first evaluation
    // rebuilds it at its state).
    std::vector<char> contacts;
    if (nearContacts_) contacts.assign(system_.model().contacts.size(), 0);
    pattern_ = mechanics::newtonMatrixPattern(system_, contacts);
    patternMatrix_ = pattern_.matrix();
    havePattern_ = true;
  }
  return &patternMatrix_;
}

void MultibodyDae::updateNearPattern(const Eigen::VectorXd& y) {
  // docs/theory.md §6c, "Near-pair pattern": every element near at y (bounding spheres
  // overlap: the only ones with a nonzero load or partial there) must be in the pattern; an
  // element in it that is apart even at kLeave is dropped at the next rebuild, which takes the
  // elements near at kEnter (a margin, so that the pattern is not rebuilt at every matrix).
  bool rebuild = false;
  for (int e : broadPhase_.near(y.data())) rebuild = rebuild || !pattern_.contacts[e];
  if (!rebuild) {
    size_t held = 0, kept = 0;
    for (char c : pattern_.contacts) held += c != 0;
    for (int e : broadPhase_.nearWithin(y.data(), kLeave)) kept += pattern_.contacts[e] != 0;
    rebuild = kept != held;
  }
  if (!rebuild) return;
  std::vector<char> contacts(system_.model().contacts.size(), 0);
  for (int e : broadPhase_.nearWithin(y.data(), kEnter)) contacts[e] = 1;
  pattern_ = mechanics::newtonMatrixPattern(system_, contacts);
  patternMatrix_ = pattern_.matrix();
  guard_.patternChanged();
  ++rebuilds_;
}

void MultibodyDae::newtonMatrixSparse(double t, const Eigen::VectorXd& y,
                                      const Eigen::VectorXd& yp, double cj,
                                      Eigen::SparseMatrix<double>& jac) {
  pattern();
  if (nearContacts_) updateNearPattern(y);
  // The caller's matrix takes the current pattern when its structure differs (a near-pair
  // rebuild may keep the count of nonzeros).
  const bool same =
      jac.isCompressed() && jac.rows() == pattern_.size && jac.nonZeros() == pattern_.nonZeros() &&
      std::equal(pattern_.columnStart.begin(), pattern_.columnStart.end(), jac.outerIndexPtr()) &&
      std::equal(pattern_.rowIndex.begin(), pattern_.rowIndex.end(), jac.innerIndexPtr());
  if (!same) jac = patternMatrix_;
  system_.newtonMatrixSparse(t, y, yp, cj, pattern_, jac, work_);
  if (!guard_.due()) return;
  const std::vector<int> outside = system_.rowsOutsidePattern(t, y, yp, cj, jac, work_);
  if (outside.empty()) return;
  ++repairs_;
  guard_.patternChanged();
  mechanics::makeRowsDense(pattern_, outside);
  patternMatrix_ = pattern_.matrix();
  jac = patternMatrix_;
  system_.newtonMatrixSparse(t, y, yp, cj, pattern_, jac, work_);
}

}  // namespace openmss::analysis
