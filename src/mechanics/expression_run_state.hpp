#pragma once
// History that function expressions need beyond the current state (docs/theory.md §11a): the
// reference angle of each cumulative AX/AY/AZ and the recorded past of each DELAY argument.
// The run state (analysis/run_state.hpp) owns one, next to the accepted state, and updates it only
// after accepted steps (accept), so rejected steps and corrector iterations never change it and
// a run repeated gives bit-identical results. The Model stays immutable: evaluation receives
// the run state through MultibodySystem::setRunState, never through the Model.

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/dual.hpp"
#include "expr/delay_history.hpp"
#include "expr/run_context.hpp"
#include "mechanics/friction/friction_anchor.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

class MultibodySystem;

class ExpressionRunState final : public expr::RunContext {
 public:
  ExpressionRunState() = default;
  // Finds the cumulative angles (AX, AY, AZ outside GCON) and DELAY calls of every function the
  // run evaluates: SFORCE, VFORCE/VTORQUE/GFORCE, VARIABLE, DIFF, REQUEST and SENSOR functions.
  explicit ExpressionRunState(const model::Model& m);

  // Forgets all history (a new run): angles read as principal values, DELAY as its e_history.
  void reset();
  // Records an accepted state: each angle's reference becomes its cumulative value at y, each
  // DELAY argument's value at (t, y, yp) is appended to its history (records at or after t are
  // dropped first, so a restart at an earlier event time rewrites the tail).
  void accept(const MultibodySystem& system, double t, const Eigen::VectorXd& y,
              const Eigen::VectorXd& yp);

  // The last accepted value of the cumulative angle `ms`, or nullptr before the first accept.
  const double* angleReference(const model::Measure& ms) const;
  const expr::DelayHistory* delayHistory(const void* key) const override;

  // The stiction anchor of FRICTION k (mechanics/friction/friction_anchor.hpp), or nullptr
  // when the run state was not built for this model's frictions.
  const friction::FrictionAnchor* frictionAnchor(int k) const {
    return k < static_cast<int>(frictionAnchors_.size()) ? &frictionAnchors_[k] : nullptr;
  }

  std::size_t angleCount() const { return angles_.size(); }
  std::size_t delayCount() const { return delays_.size(); }

 private:
  struct Angle {
    model::Measure measure;
    double reference = 0.0;
    bool set = false;
  };
  struct Delay {
    const model::BoundExpression* function = nullptr;
    std::size_t call = 0;
    const void* key = nullptr;
    expr::DelayHistory history;
  };
  void addFunction(const model::BoundExpression& f);

  std::vector<Angle> angles_;
  std::vector<Delay> delays_;
  std::vector<friction::FrictionAnchor> frictionAnchors_;  // one per FRICTION
};

// The cumulative angle from its principal value: the principal value plus the whole turns
// that bring it within pi of the last accepted value. The turns are constant near any state,
// so the derivative is the principal angle's; the value is continuous through +-pi as long as
// one step turns the angle by less than pi.
template <class T>
T cumulativeAngle(const T& principal, const double* reference) {
  if (reference == nullptr) return principal;
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const double turns = std::round((*reference - valueOf(principal)) / kTurn);
  return principal + kTurn * turns;
}

}  // namespace openmss::mechanics
