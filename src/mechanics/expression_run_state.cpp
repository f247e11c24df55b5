#include "mechanics/expression_run_state.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

namespace {
bool isCumulativeAngle(model::MeasureKind kind) {
  return kind == model::MeasureKind::AX || kind == model::MeasureKind::AY ||
         kind == model::MeasureKind::AZ;
}
bool sameAngle(const model::Measure& a, const model::Measure& b) {
  return a.kind == b.kind && a.i == b.i && a.j == b.j;
}
}  // namespace

ExpressionRunState::ExpressionRunState(const model::Model& m)
    : frictionAnchors_(m.frictions.size()),
      // One per PTCV, two per CVCV (ConstraintSet numbers them the same way), so that a run
      // state bound without trackCurveParameters still matches the equations' slots.
      curveParameters_(m.ptcvs.size() + 2 * m.cvcvs.size(),
                       std::numeric_limits<double>::quiet_NaN()) {
  // Each function is named by its element and argument, so that a reprocessed model's run
  // state can take over the DELAY histories of the functions it keeps (carryFrom).
  const auto name = [](const char* kind, long id, int part) {
    return std::string(kind) + "/" + std::to_string(id) + "#" + std::to_string(part);
  };
  for (const auto& f : m.sforces) addFunction(f.function, name("SFORCE", f.id, 0));
  static const char* kVectorKinds[] = {"VFORCE", "VTORQUE", "GFORCE"};
  for (const auto& f : m.vectorForces)
    for (std::size_t c = 0; c < f.components.size(); ++c)
      if (f.components[c])
        addFunction(*f.components[c],
                    name(kVectorKinds[static_cast<int>(f.kind)], f.id, static_cast<int>(c)));
  for (const auto& v : m.variables) addFunction(v.function, name("VARIABLE", v.id, 0));
  for (const auto& d : m.diffs) addFunction(d.function, name("DIFF", d.id, 0));
  for (const auto& r : m.requests)
    for (std::size_t c = 0; c < r.columns.size(); ++c)
      if (r.columns[c]) addFunction(*r.columns[c], name("REQUEST", r.id, static_cast<int>(c)));
  for (const auto& s : m.sensors) {
    addFunction(s.function, name("SENSOR", s.id, 0));
    if (s.evaluate) addFunction(*s.evaluate, name("SENSOR", s.id, 1));
  }
  sensorValues_.assign(m.sensors.size(), 0.0);
  for (const auto& e : m.generalStates) {
    gseDiscrete_.emplace_back(e.icd.data(), e.icd.data() + e.icd.size());
    gseLastSample_.push_back(0.0);
  }
}

void ExpressionRunState::trackCoupledAngles(const ConstraintSet& constraints) {
  coupledSlots_.clear();
  coupledStart_.clear();
  const auto& eqs = constraints.equations();
  for (std::size_t k = 0; k < eqs.size(); ++k)
    for (std::size_t n = 0; n < eqs[k].terms.size(); ++n) {
      const ConstraintEquation::CoupledTerm& term = eqs[k].terms[n];
      if (term.slot < 0) continue;
      if (static_cast<std::size_t>(term.slot) != coupledSlots_.size())
        continue;  // numbered in order
      coupledSlots_.push_back({static_cast<int>(k), static_cast<int>(n)});
      coupledStart_.push_back(term.reference);
    }
  coupled_ = coupledStart_;
}

void ExpressionRunState::trackCurveParameters(const ConstraintSet& constraints) {
  curveParameters_.assign(static_cast<std::size_t>(constraints.curveParameterCount()),
                          std::numeric_limits<double>::quiet_NaN());
  curveRunOff_.clear();
}

// Commits the PTCV and CVCV curve parameters at y (each found from the previous committed
// value, docs/theory.md §5d), all computed before any is written (the equations read the
// buffer in place), and records the first point or contact past an OPEN curve's end.
void ExpressionRunState::commitCurveParameters(const MultibodySystem& system, double t,
                                               const Eigen::VectorXd& y) {
  if (curveParameters_.empty()) return;
  const model::Model& m = system.model();
  std::vector<double> next(curveParameters_.size());
  for (const ConstraintEquation& eq : system.constraints().equations()) {
    if (eq.curveSlot < 0 || eq.axisI != 0) continue;  // once per element
    double* out = next.data() + eq.curveSlot;
    system.curveParameters(eq, y.data(), out);
    if (!curveRunOff_.empty()) continue;
    // 1e-9: the end itself is on the curve; round-off past it is not a run-off.
    auto off = [](const BSplineCurve& c, double a) {
      const double lo = c.minParameter(), hi = c.maxParameter(), slack = 1e-9 * 0.5 * (hi - lo);
      return !c.closed() && (a < lo - slack || a > hi + slack);
    };
    std::string what;
    int curve = -1;
    if (eq.ptcv >= 0 && off(*eq.curve, out[0])) {
      const model::PointCurve& p = m.ptcvs[static_cast<std::size_t>(eq.ptcv)];
      what = "PTCV/" + std::to_string(p.id) + ": marker I ran off the end of OPEN CURVE/";
      curve = p.curve;
    } else if (eq.cvcv >= 0 && (off(*eq.curve, out[0]) || off(*eq.curveJ, out[1]))) {
      const model::CurveCurve& c = m.cvcvs[static_cast<std::size_t>(eq.cvcv)];
      what = "CVCV/" + std::to_string(c.id) + ": the contact point ran off the end of OPEN CURVE/";
      curve = off(*eq.curve, out[0]) ? c.iCurve : c.jCurve;
    }
    if (curve < 0) continue;
    char at[64] = "";
    if (std::isfinite(t)) std::snprintf(at, sizeof at, " at time %.6E", t);
    curveRunOff_ = what + std::to_string(m.curves[static_cast<std::size_t>(curve)].id) + at +
                   " (ADAMS stops the run there too; docs/theory.md §5d)";
  }
  std::copy(next.begin(), next.end(), curveParameters_.begin());
}

void ExpressionRunState::commitCoupledAngles(const MultibodySystem& system,
                                             const Eigen::VectorXd& y, double t) {
  const auto& eqs = system.constraints().equations();
  // Each term's cumulative angle at y, unwrapped against the committed value (geometry of the
  // term alone); the buffer is written in place (the equations hold a pointer into it).
  for (std::size_t s = 0; s < coupledSlots_.size(); ++s)
    coupled_[s] = system.coupledAngle(eqs[static_cast<std::size_t>(coupledSlots_[s].equation)],
                                      coupledSlots_[s].term, y.data());
  // Statics and kinematics commit here: the curve parameters are committed with the angles.
  commitCurveParameters(system, t, y);
}

void ExpressionRunState::addFunction(const model::BoundExpression& f, std::string owner) {
  // One reference per distinct angle: equal calls measure the same function of the state.
  for (const model::Measure& ms : f.measures) {
    if (!isCumulativeAngle(ms.kind)) continue;
    bool known = false;
    for (const Angle& a : angles_) known = known || sameAngle(a.measure, ms);
    if (!known) angles_.push_back({ms, 0.0, false});
  }
  for (std::size_t k = 0; k < f.expression.delayCount(); ++k)
    delays_.push_back({&f, k, f.expression.delayKey(k), {}, owner});
}

void ExpressionRunState::reset() {
  for (Angle& a : angles_) a.set = false;
  for (Delay& d : delays_) d.history.clear();
  std::copy(coupledStart_.begin(), coupledStart_.end(), coupled_.begin());
  std::fill(curveParameters_.begin(), curveParameters_.end(),
            std::numeric_limits<double>::quiet_NaN());
  curveRunOff_.clear();
  for (friction::FrictionAnchor& a : frictionAnchors_) a = {};
}

void ExpressionRunState::accept(const MultibodySystem& system, double t, const Eigen::VectorXd& y,
                                const Eigen::VectorXd& yp) {
  const model::Model& m = system.model();
  const StateLayout& l = system.layout();
  // Every value below is computed against the references of the previous accepted state
  // before any reference changes.
  std::vector<double> angles(angles_.size());
  for (std::size_t k = 0; k < angles_.size(); ++k)
    kinematicMeasure(m, l, angles_[k].measure, y.data(), &angles[k], this);
  const DynamicReads<double> reads{yp.data(), &system.constraints()};
  std::vector<double> delayed(delays_.size());
  std::vector<double> host;
  for (std::size_t k = 0; k < delays_.size(); ++k) {
    const model::BoundExpression& f = *delays_[k].function;
    host.assign(f.measures.size(), 0.0);
    for (std::size_t h = 0; h < host.size(); ++h)
      if (!kinematicMeasure(m, l, f.measures[h], y.data(), &host[h], this))
        dynamicMeasure(m, l, f.measures[h], y.data(), &reads, &host[h]);
    delayed[k] =
        f.expression.delayArgument(delays_[k].call, host.empty() ? nullptr : host.data(), t);
  }
  for (std::size_t k = 0; k < angles_.size(); ++k) {
    angles_[k].reference = angles[k];
    angles_[k].set = true;
  }
  for (std::size_t k = 0; k < delays_.size(); ++k) delays_[k].history.record(t, delayed[k]);
  commitCoupledAngles(system, y, t);
  for (std::size_t k = 0; k < frictionAnchors_.size(); ++k)
    friction::updateAnchor(m, l, static_cast<int>(k), y.data(), frictionAnchors_[k]);
}

ExpressionRunState::Snapshot ExpressionRunState::snapshot() const {
  Snapshot s;
  for (const Angle& a : angles_)
    s.angleReferences.push_back(a.set ? a.reference : std::numeric_limits<double>::quiet_NaN());
  for (const Delay& d : delays_) {
    std::vector<std::pair<double, double>> records;
    for (std::size_t k = 0; k < d.history.size(); ++k)
      records.emplace_back(d.history.times()[k], d.history.values()[k]);
    s.delays.push_back(std::move(records));
  }
  s.coupled = coupled_;
  s.sensorValues = sensorValues_;
  s.gseLastSample = gseLastSample_;
  s.gseDiscrete = gseDiscrete_;
  s.status = status_;
  for (const friction::FrictionAnchor& a : frictionAnchors_) {
    s.frictionAnchors.push_back(a.set ? 1.0 : 0.0);
    for (int k = 0; k < 3; ++k) s.frictionAnchors.push_back(a.displacement[k]);
    for (int k = 0; k < 9; ++k) s.frictionAnchors.push_back(a.rotation.data()[k]);
  }
  s.curveParameters = curveParameters_;
  return s;
}

bool ExpressionRunState::restore(const Snapshot& s) {
  if (s.angleReferences.size() != angles_.size() || s.delays.size() != delays_.size() ||
      s.coupled.size() != coupled_.size() || s.sensorValues.size() != sensorValues_.size() ||
      s.gseLastSample.size() != gseLastSample_.size() ||
      s.gseDiscrete.size() != gseDiscrete_.size() ||
      s.frictionAnchors.size() != 13 * frictionAnchors_.size() ||
      s.curveParameters.size() != curveParameters_.size())
    return false;
  for (std::size_t k = 0; k < gseDiscrete_.size(); ++k)
    if (s.gseDiscrete[k].size() != gseDiscrete_[k].size()) return false;
  for (std::size_t k = 0; k < angles_.size(); ++k) {
    angles_[k].set = !std::isnan(s.angleReferences[k]);
    angles_[k].reference = angles_[k].set ? s.angleReferences[k] : 0.0;
  }
  for (std::size_t k = 0; k < delays_.size(); ++k) {
    delays_[k].history.clear();
    for (const auto& [t, v] : s.delays[k]) delays_[k].history.record(t, v);
  }
  std::copy(s.coupled.begin(), s.coupled.end(), coupled_.begin());  // in place: see above
  std::copy(s.curveParameters.begin(), s.curveParameters.end(), curveParameters_.begin());
  sensorValues_ = s.sensorValues;
  gseLastSample_ = s.gseLastSample;
  gseDiscrete_ = s.gseDiscrete;
  status_ = s.status;
  for (std::size_t k = 0; k < frictionAnchors_.size(); ++k) {
    const double* a = s.frictionAnchors.data() + 13 * k;
    frictionAnchors_[k].set = a[0] != 0.0;
    for (int i = 0; i < 3; ++i) frictionAnchors_[k].displacement[i] = a[1 + i];
    for (int i = 0; i < 9; ++i) frictionAnchors_[k].rotation.data()[i] = a[4 + i];
  }
  return true;
}

const double* ExpressionRunState::angleReference(const model::Measure& ms) const {
  for (const Angle& a : angles_)
    if (sameAngle(a.measure, ms)) return a.set ? &a.reference : nullptr;
  return nullptr;
}

const expr::DelayHistory* ExpressionRunState::delayHistory(const void* key) const {
  for (const Delay& d : delays_)
    if (d.key == key) return d.history.empty() ? nullptr : &d.history;
  return nullptr;
}

}  // namespace openmss::mechanics
