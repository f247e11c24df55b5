#include "commands/state_carry_over.hpp"

#include <map>
#include <utility>

#include "common/rotation.hpp"

namespace openmss::commands {
namespace {

using mechanics::StateLayout;

// The pose and velocity of body `fb` of `from` moved onto the body frame of the same part in
// the new model. The new body frame is fixed in the old one at the offset the two data-set
// configurations give (identity unless PART/CM= was redefined).
void carryBody(const model::Part& oldPart, const model::Part& newPart, const double* y, int fo,
               double* out, int to) {
  if (oldPart.position == newPart.position && oldPart.orientation == newPart.orientation) {
    for (int k = 0; k < StateLayout::kMu; ++k) out[to + k] = y[fo + k];  // bit for bit
    return;
  }
  const Eigen::Matrix3d relative = oldPart.orientation.transpose() * newPart.orientation;
  const Eigen::Vector3d offset =
      oldPart.orientation.transpose() * (newPart.position - oldPart.position);
  const Eigen::Vector4d e(y[fo + StateLayout::kE], y[fo + StateLayout::kE + 1],
                          y[fo + StateLayout::kE + 2], y[fo + StateLayout::kE + 3]);
  const Eigen::Matrix3d a =
      Eigen::Quaterniond(e(0), e(1), e(2), e(3)).normalized().toRotationMatrix();
  const Eigen::Vector3d r(y[fo], y[fo + 1], y[fo + 2]);
  const Eigen::Vector3d v(y[fo + StateLayout::kV], y[fo + StateLayout::kV + 1],
                          y[fo + StateLayout::kV + 2]);
  const Eigen::Vector3d w(y[fo + StateLayout::kW], y[fo + StateLayout::kW + 1],
                          y[fo + StateLayout::kW + 2]);  // body axes
  const Eigen::Vector3d rNew = r + a * offset;
  const Eigen::Vector4d eNew = quaternionFromMatrix(a * relative);
  // A point fixed in the body: v + omega x d, with omega and d in body axes.
  const Eigen::Vector3d vNew = v + a * w.cross(offset);
  const Eigen::Vector3d wNew = relative.transpose() * w;
  for (int c = 0; c < 3; ++c) {
    out[to + StateLayout::kR + c] = rNew(c);
    out[to + StateLayout::kV + c] = vNew(c);
    out[to + StateLayout::kW + c] = wNew(c);
  }
  for (int c = 0; c < 4; ++c) out[to + StateLayout::kE + c] = eNew(c);
}

template <class Element>
std::map<long, int> indexById(const std::vector<Element>& elements) {
  std::map<long, int> m;
  for (int k = 0; k < static_cast<int>(elements.size()); ++k) m[elements[k].id] = k;
  return m;
}

void carryUserStates(const mechanics::MultibodySystem& fs, const Eigen::VectorXd& y,
                     const mechanics::MultibodySystem& ts, Eigen::VectorXd& out) {
  const model::Model& fm = fs.model();
  const model::Model& tm = ts.model();
  const StateLayout& fl = fs.layout();
  const StateLayout& tl = ts.layout();
  const auto oldVariables = indexById(fm.variables);
  for (int k = 0; k < static_cast<int>(tm.variables.size()); ++k)
    if (auto it = oldVariables.find(tm.variables[k].id); it != oldVariables.end())
      out(tl.userAlg(k)) = y(fl.userAlg(it->second));
  const int fnv = static_cast<int>(fm.variables.size());
  const int tnv = static_cast<int>(tm.variables.size());
  const auto oldDiffs = indexById(fm.diffs);
  for (int k = 0; k < static_cast<int>(tm.diffs.size()); ++k)
    if (auto it = oldDiffs.find(tm.diffs[k].id); it != oldDiffs.end()) {
      out(tl.userDiff(k)) = y(fl.userDiff(it->second));
      out(tl.userAlg(tnv + k)) = y(fl.userAlg(fnv + it->second));
    }
  std::map<std::pair<int, long>, int> oldLinear;
  for (int k = 0; k < static_cast<int>(fm.linearStates.size()); ++k)
    oldLinear[{static_cast<int>(fm.linearStates[k].kind), fm.linearStates[k].id}] = k;
  for (const auto& e : tm.linearStates) {
    auto it = oldLinear.find({static_cast<int>(e.kind), e.id});
    if (it == oldLinear.end()) continue;
    const auto& o = fm.linearStates[it->second];
    if (o.a.rows() != e.a.rows()) continue;  // redefined with another order: starts at its IC
    for (int i = 0; i < e.a.rows(); ++i)
      out(tl.userDiff(e.firstState + i)) = y(fl.userDiff(o.firstState + i));
  }
  const auto oldGses = indexById(fm.generalStates);
  for (const auto& e : tm.generalStates) {
    auto it = oldGses.find(e.id);
    if (it == oldGses.end()) continue;
    const auto& o = fm.generalStates[it->second];
    if (o.ns != e.ns || o.no != e.no) continue;
    for (int i = 0; i < e.ns; ++i)
      out(tl.userDiff(e.firstState + i)) = y(fl.userDiff(o.firstState + i));
    for (int j = 0; j < e.no; ++j)
      out(tl.userAlg(e.firstOutput + j)) = y(fl.userAlg(o.firstOutput + j));
  }
}

}  // namespace

void carryOverState(const mechanics::MultibodySystem& fromSystem, const analysis::RunState& from,
                    const mechanics::MultibodySystem& toSystem, analysis::RunState& to) {
  const model::Model& fm = fromSystem.model();
  const model::Model& tm = toSystem.model();
  to.t = from.t;
  to.summary = from.summary;
  to.outputPrefix = from.outputPrefix;
  to.halted = from.halted;
  to.initialized = false;  // the initial conditions are solved again (docs/commands.md)
  for (int b = 0; b < toSystem.layout().bodies; ++b) {
    const model::Part& part = tm.parts[tm.movingParts[b]];
    const auto it = fm.partIndex.find(part.id);
    if (it == fm.partIndex.end()) continue;
    const model::Part& old = fm.parts[it->second];
    if (old.body < 0) continue;
    carryBody(old, part, from.y.data(), fromSystem.layout().body(old.body), to.y.data(),
              toSystem.layout().body(b));
  }
  carryUserStates(fromSystem, from.y, toSystem, to.y);
  // Turn counts, DELAY histories, SENVAL, GSE samples of the elements that remain (§11c).
  to.expressions->carryFrom(*from.expressions, fromSystem, toSystem);
  to.historyCarried = true;
}

}  // namespace openmss::commands
