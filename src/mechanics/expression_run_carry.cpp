// ExpressionRunState::carryFrom: the run state of a reprocessed model (ACTIVATE, DEACTIVATE, a
// redefining command) takes over the history of the model before it, element by element, by
// ids, never by position: deactivating one element renumbers the others' entries
// (docs/theory.md §11c). An entry is taken over only when it means the same thing in both
// models: the same markers for an angle, the same element, argument and function text for a
// DELAY history, the same sizes for a GSE.

#include <map>
#include <string>
#include <tuple>

#include "mechanics/expression_run_state.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

long markerId(const model::Model& m, int index) {
  return index < 0 ? 0 : m.markers[static_cast<std::size_t>(index)].id;
}

// (kind, COUPLER or GEAR id, term) of a coupled rotation term's equation.
std::tuple<int, long, int> coupledKey(const model::Model& m, const ConstraintEquation& eq,
                                      int term) {
  if (eq.coupler >= 0) return {0, m.couplers[static_cast<std::size_t>(eq.coupler)].id, term};
  if (eq.gear >= 0) return {1, m.gears[static_cast<std::size_t>(eq.gear)].id, term};
  return {2, 0, term};
}

template <class Element>
std::map<long, int> indexById(const std::vector<Element>& elements) {
  std::map<long, int> m;
  for (int k = 0; k < static_cast<int>(elements.size()); ++k) m[elements[k].id] = k;
  return m;
}

}  // namespace

int ExpressionRunState::carryFrom(const ExpressionRunState& from, const MultibodySystem& fromSystem,
                                  const MultibodySystem& toSystem) {
  const model::Model& fm = fromSystem.model();
  const model::Model& tm = toSystem.model();
  int carried = 0;
  // Cumulative AX/AY/AZ: the same markers measure the same angle, whichever function reads it.
  for (Angle& a : angles_)
    for (const Angle& o : from.angles_)
      if (o.set && o.measure.kind == a.measure.kind &&
          markerId(fm, o.measure.i) == markerId(tm, a.measure.i) &&
          markerId(fm, o.measure.j) == markerId(tm, a.measure.j)) {
        a.reference = o.reference;
        a.set = true;
        ++carried;
        break;
      }
  // DELAY: the recorded past of the same call of the same, unchanged function.
  for (Delay& d : delays_)
    for (const Delay& o : from.delays_)
      if (o.owner == d.owner && o.call == d.call &&
          o.function->expression.text() == d.function->expression.text()) {
        d.history = o.history;
        ++carried;
        break;
      }
  // COUPLER/GEAR turn counts.
  std::map<std::tuple<int, long, int>, double> oldCoupled;
  const auto& feqs = fromSystem.constraints().equations();
  for (std::size_t s = 0; s < from.coupledSlots_.size(); ++s) {
    const CoupledSlot& slot = from.coupledSlots_[s];
    oldCoupled[coupledKey(fm, feqs[static_cast<std::size_t>(slot.equation)], slot.term)] =
        from.coupled_[s];
  }
  const auto& teqs = toSystem.constraints().equations();
  for (std::size_t s = 0; s < coupledSlots_.size(); ++s) {
    const auto it = oldCoupled.find(coupledKey(
        tm, teqs[static_cast<std::size_t>(coupledSlots_[s].equation)], coupledSlots_[s].term));
    if (it == oldCoupled.end()) continue;
    coupled_[s] = it->second;  // in place: the equations hold pointers into coupled_
    ++carried;
  }
  // SENVAL of each SENSOR, the GSE discrete states, the FRICTION stiction anchors.
  const auto oldSensors = indexById(fm.sensors);
  for (std::size_t k = 0; k < tm.sensors.size(); ++k)
    if (const auto it = oldSensors.find(tm.sensors[k].id); it != oldSensors.end()) {
      sensorValues_[k] = from.sensorValues_[static_cast<std::size_t>(it->second)];
      ++carried;
    }
  const auto oldGses = indexById(fm.generalStates);
  for (std::size_t k = 0; k < tm.generalStates.size(); ++k) {
    const auto it = oldGses.find(tm.generalStates[k].id);
    if (it == oldGses.end()) continue;
    const auto o = static_cast<std::size_t>(it->second);
    if (from.gseDiscrete_[o].size() != gseDiscrete_[k].size()) continue;
    gseDiscrete_[k] = from.gseDiscrete_[o];
    gseLastSample_[k] = from.gseLastSample_[o];
    ++carried;
  }
  const auto oldFrictions = indexById(fm.frictions);
  for (std::size_t k = 0; k < tm.frictions.size() && k < frictionAnchors_.size(); ++k)
    if (const auto it = oldFrictions.find(tm.frictions[k].id);
        it != oldFrictions.end() &&
        static_cast<std::size_t>(it->second) < from.frictionAnchors_.size()) {
      frictionAnchors_[k] = from.frictionAnchors_[static_cast<std::size_t>(it->second)];
      ++carried;
    }
  // PTCV (one slot each, first) and CVCV (two each) warm starts (constraint_set.cpp numbers
  // them so).
  const auto oldPtcvs = indexById(fm.ptcvs);
  for (std::size_t k = 0; k < tm.ptcvs.size() && k < curveParameters_.size(); ++k)
    if (const auto it = oldPtcvs.find(tm.ptcvs[k].id);
        it != oldPtcvs.end() && static_cast<std::size_t>(it->second) < from.curveParameters_.size())
      curveParameters_[k] = from.curveParameters_[static_cast<std::size_t>(it->second)];
  const auto oldCvcvs = indexById(fm.cvcvs);
  for (std::size_t k = 0; k < tm.cvcvs.size(); ++k) {
    const auto it = oldCvcvs.find(tm.cvcvs[k].id);
    const std::size_t to = tm.ptcvs.size() + 2 * k;
    if (it == oldCvcvs.end()) continue;
    const std::size_t o = fm.ptcvs.size() + 2 * static_cast<std::size_t>(it->second);
    if (o + 1 >= from.curveParameters_.size() || to + 1 >= curveParameters_.size()) continue;
    curveParameters_[to] = from.curveParameters_[o];
    curveParameters_[to + 1] = from.curveParameters_[o + 1];
  }
  status_ = from.status_;
  return carried;
}

}  // namespace openmss::mechanics
