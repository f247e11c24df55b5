#pragma once
// Everything the equations read beyond the current state (docs/theory.md §11a, "Run state"):
// the reference angle of each cumulative AX/AY/AZ, the recorded past of each DELAY argument,
// the committed cumulative angle of each COUPLER/GEAR rotation term (whole turns), the SENVAL
// value of each SENSOR, the GSE discrete states and their last sample times, and the analysis
// status MODE/HSIZE/ORDER/NJAC/NRHS read. The run state (analysis/run_state.hpp) owns one,
// next to the accepted state. The angles and DELAY histories change only after accepted steps
// (accept), so rejected steps and corrector iterations never change them and a run repeated
// gives bit-identical results; the others are written by the analysis drivers only (sensor
// events, GSE samples, the start of an analysis). The Model stays immutable: evaluation
// receives the run state through MultibodySystem::setRunState, never through the Model.

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "common/dual.hpp"
#include "expr/delay_history.hpp"
#include "expr/run_context.hpp"
#include "model/analysis_status.hpp"
#include "mechanics/friction/friction_anchor.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

class MultibodySystem;
class ConstraintSet;

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

  // COUPLER/GEAR rotation terms (ConstraintEquation::CoupledTerm::slot numbers them): the
  // cumulative angle committed at the last accepted state, against which the residual counts
  // whole turns. Starts at each term's data-set angle; accept() commits, reset() restores.
  void trackCoupledAngles(const ConstraintSet& constraints);
  const std::vector<double>& coupledAngles() const { return coupled_; }
  // Commits the coupled angles and the curve parameters at y only (statics and kinematics
  // call accept, which does too); t (NaN: unknown) dates a curve run-off.
  void commitCoupledAngles(const MultibodySystem& system, const Eigen::VectorXd& y,
                           double t = std::numeric_limits<double>::quiet_NaN());

  // PTCV and CVCV curve parameters (ConstraintEquation::curveSlot numbers them): those of the
  // last accepted state, the warm start of the next searches (docs/theory.md §5d). NaN (global
  // search) until the first commit; committed with the coupled angles, reset() forgets them.
  void trackCurveParameters(const ConstraintSet& constraints);
  const std::vector<double>& curveParameters() const { return curveParameters_; }
  // Set when a committed state has a PTCV point or a CVCV contact past the end of an OPEN
  // curve (ADAMS stops the run there): what happened, naming the element and the time.
  const std::string& curveRunOff() const { return curveRunOff_; }

  // SENVAL(id): the EVALUATE value of SENSOR k's last event (0 before any).
  double sensorValue(int k) const { return sensorValues_[static_cast<std::size_t>(k)]; }
  void setSensorValue(int k, double v) { sensorValues_[static_cast<std::size_t>(k)] = v; }
  // GSE k's discrete states xd and the time of its last sample (analysis/discrete_sampler).
  const std::vector<double>& gseDiscrete(int k) const {
    return gseDiscrete_[static_cast<std::size_t>(k)];
  }
  double gseLastSample(int k) const { return gseLastSample_[static_cast<std::size_t>(k)]; }
  void setGseSample(int k, std::vector<double> xd, double t) {
    gseDiscrete_[static_cast<std::size_t>(k)] = std::move(xd);
    gseLastSample_[static_cast<std::size_t>(k)] = t;
  }
  // MODE, HSIZE, ORDER, NJAC, NRHS (model/analysis_status.hpp): set by the analysis drivers.
  const model::AnalysisStatus& status() const { return status_; }
  model::AnalysisStatus& status() { return status_; }

  // The whole history as flat numbers, in a fixed order (analysis/save_file.hpp writes and
  // reads it): restore() refuses (returns false, nothing changed) a list of other sizes.
  struct Snapshot {
    std::vector<double> angleReferences;  // NaN: not set
    std::vector<std::vector<std::pair<double, double>>> delays;
    std::vector<double> coupled, sensorValues, gseLastSample;
    std::vector<std::vector<double>> gseDiscrete;
    model::AnalysisStatus status;
    // Per FRICTION, 13 numbers: set (0/1), displacement (3), rotation (9, column-major).
    std::vector<double> frictionAnchors;
    std::vector<double> curveParameters;  // NaN: not set (save format 5)
  };
  Snapshot snapshot() const;
  bool restore(const Snapshot& s);

  // After ACTIVATE, DEACTIVATE or a redefinition (expression_run_carry.cpp; docs/theory.md
  // §11c): takes over from the run state of the model before, element by element, what the
  // reprocessed model still has: the cumulative angles of the same markers, the DELAY histories
  // of functions whose element and text are unchanged, the COUPLER/GEAR committed angles, SENVAL
  // values, GSE discrete states, FRICTION anchors, PTCV/CVCV parameters and the analysis status.
  // Returns how many entries were taken over (tests count them).
  int carryFrom(const ExpressionRunState& from, const MultibodySystem& fromSystem,
                const MultibodySystem& toSystem);

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
    std::string owner;  // "VARIABLE/5#0": element and argument (REQUEST column, SENSOR 0/1)
  };
  void addFunction(const model::BoundExpression& f, std::string owner);
  void commitCurveParameters(const MultibodySystem& system, double t, const Eigen::VectorXd& y);

  std::vector<Angle> angles_;
  std::vector<Delay> delays_;
  // Coupled rotation terms: (equation index, term index) in the constraint set, the committed
  // cumulative angle and its data-set value.
  struct CoupledSlot {
    int equation = 0, term = 0;
  };
  std::vector<CoupledSlot> coupledSlots_;
  std::vector<double> coupled_, coupledStart_;
  std::vector<double> sensorValues_, gseLastSample_;
  std::vector<std::vector<double>> gseDiscrete_;
  model::AnalysisStatus status_;
  std::vector<friction::FrictionAnchor> frictionAnchors_;  // one per FRICTION
  std::vector<double> curveParameters_;
  std::string curveRunOff_;
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
