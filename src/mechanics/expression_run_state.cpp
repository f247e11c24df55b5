#include "mechanics/expression_run_state.hpp"

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
    : frictionAnchors_(m.frictions.size()) {
  for (const auto& f : m.sforces) addFunction(f.function);
  for (const auto& f : m.vectorForces)
    for (const auto& c : f.components)
      if (c) addFunction(*c);
  for (const auto& v : m.variables) addFunction(v.function);
  for (const auto& d : m.diffs) addFunction(d.function);
  for (const auto& r : m.requests)
    for (const auto& c : r.columns)
      if (c) addFunction(*c);
  for (const auto& s : m.sensors) {
    addFunction(s.function);
    if (s.evaluate) addFunction(*s.evaluate);
  }
}

void ExpressionRunState::addFunction(const model::BoundExpression& f) {
  // One reference per distinct angle: equal calls measure the same function of the state.
  for (const model::Measure& ms : f.measures) {
    if (!isCumulativeAngle(ms.kind)) continue;
    bool known = false;
    for (const Angle& a : angles_) known = known || sameAngle(a.measure, ms);
    if (!known) angles_.push_back({ms, 0.0, false});
  }
  for (std::size_t k = 0; k < f.expression.delayCount(); ++k)
    delays_.push_back({&f, k, f.expression.delayKey(k), {}});
}

void ExpressionRunState::reset() {
  for (Angle& a : angles_) a.set = false;
  for (Delay& d : delays_) d.history.clear();
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
  for (std::size_t k = 0; k < frictionAnchors_.size(); ++k)
    friction::updateAnchor(m, l, static_cast<int>(k), y.data(), frictionAnchors_[k]);
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
