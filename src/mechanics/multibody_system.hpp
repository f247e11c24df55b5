#pragma once
// The equations of motion of a Model over the state layout of state_layout.hpp
// (docs/theory.md): kinematic equations, Newton-Euler equations with constraint forces
// -C^T lambda, Euler-parameter normalisation, and the constraint equations (index 3).
// Everything is templated on the scalar; exact Jacobians come from forward-mode AD.

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "common/dual.hpp"
#include "mechanics/bound_function.hpp"
#include "mechanics/constraint_set.hpp"
#include "mechanics/dynamic_measures.hpp"
#include "mechanics/force_elements.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/measures.hpp"
#include "mechanics/state_layout.hpp"
#include "mechanics/user_equations.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

class MultibodySystem {
 public:
  explicit MultibodySystem(const model::Model& model);

  const model::Model& model() const { return *model_; }
  const StateLayout& layout() const { return layout_; }
  // The history expressions read (cumulative AX/AY/AZ, DELAY): owned by the analysis, which
  // updates it after accepted steps (expression_run_state.hpp). nullptr: none (principal
  // angles, DELAY reads its e_history).
  void setRunState(const ExpressionRunState* run) {
    runState_ = run;
    forces_.setRunState(run);
    user_.setRunState(run);
    constraints_.bindCoupledAngles(run ? run->coupledAngles().data() : nullptr);
    constraints_.bindCurveParameters(run ? run->curveParameters().data() : nullptr);
  }
  // PTCV (CVCV) equation eq's curve parameter alpha* ((alpha*, beta*)) at y, into out[0]
  // (out[0..1]), found as the equations find them (docs/theory.md §5d, §5e).
  void curveParameters(const ConstraintEquation& eq, const double* y, double* out) const;
  // The cumulative angle of rotation term `term` of coupled equation `eq` at y, its whole
  // turns counted against the committed angle (ExpressionRunState::commitCoupledAngles).
  double coupledAngle(const ConstraintEquation& eq, int term, const double* y) const;
  const ExpressionRunState* runState() const { return runState_; }
  const ConstraintSet& constraints() const { return constraints_; }
  ConstraintSet& constraints() { return constraints_; }

  // The state at the data set's configuration with the given initial velocities (unset = 0).
  Eigen::VectorXd initialState() const;

  // G(t, y, y') of the DAE. g has layout().size() entries.
  template <class T>
  void residual(double t, const T* y, const T* yp, T* g) const;

  // Newton matrix dG/dy + cj dG/dy', exact (forward-mode AD, one column per pass).
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) const;
  // The same matrix on the fixed structural pattern (jacobian_pattern.hpp) by compressed
  // forward AD, one residual pass per colour: overwrites the values of jac, which must have
  // been made by pattern.matrix() (no allocation once `work` has been sized).
  void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                          double cj, const JacobianPattern& pattern,
                          Eigen::SparseMatrix<double>& jac, SparseJacobianWork& work) const;
  // The rows where jac (on its pattern) times a fixed pseudo-random direction v differs from
  // the exact directional derivative (dG/dy + cj dG/dy') v by more than round-off: entries the
  // pattern misses. Costs one residual pass.
  std::vector<int> rowsOutsidePattern(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                      double cj, const Eigen::SparseMatrix<double>& jac,
                                      SparseJacobianWork& work) const;

  // Constraint k's value Phi_k(q, t) (motions wrapped to +-pi for rotations).
  double constraintValue(int k, double t, const double* y) const;
  // The same from the frames of its markers (frames[s] of eq.marker(s)), computed by the
  // caller (ConstraintRows shares one marker's frame among the equations that read it).
  double constraintValue(int k, double t, const Frame<double>* frames) const;
  // Row k of C = dPhi/d(delta r, delta pi) over the moving bodies (6 columns per body).
  void constraintRow(int k, const double* y, double* row) const;
  // The same for an equation outside the DAE (a joint initial condition), and its geometry.
  void constraintRow(const ConstraintEquation& eq, const double* y, double* row) const;
  double geometryValue(const ConstraintEquation& eq, const double* y) const;
  // The nonzeros of the same row (identical numbers): columns 6 b + dir of the moving bodies
  // the equation's markers sit on, increasing, at most 6 * markerCount() of them. Costs
  // O(markers), not O(bodies): the sparse set-up solves (docs/theory.md §7) build C from these.
  void constraintRowEntries(int k, const double* y, std::vector<int>& cols,
                            std::vector<double>& vals) const;
  void constraintRowEntries(const ConstraintEquation& eq, const double* y,
                            std::vector<int>& cols, std::vector<double>& vals) const;
  // dPhi_k/dt at velocity u (= C u) and second derivative along u with zero acceleration.
  void constraintRates(int k, const double* y, double* first, double* second) const;
  // Motion function value and time derivatives (equation k must be a motion equation).
  expr::TimeJet motionJet(int k, double t) const;

  // Generalised applied force (6 per body: force in ground, torque in body axes about the CM)
  // including gravity and the gyroscopic term -w x Jw, and the mass matrix diagonal blocks.
  void appliedForces(double t, const double* y, Eigen::VectorXd& q) const;
  void massMatrix(Eigen::MatrixXd& m) const;
  // Its diagonal blocks of body b (the sparse set-up solves assemble M from these).
  double bodyMass(int b) const { return mass_[b]; }
  const Eigen::Matrix3d& bodyInertia(int b) const { return inertia_[b]; }

  // Force on the part of `marker` and torque about the marker's origin, both in ground,
  // exerted by the equations of element (joint or motion), from the multipliers in y.
  void elementReaction(bool motion, int element, int marker, const double* y,
                       Eigen::Vector3d& force, Eigen::Vector3d& torque) const {
    elementReaction(motion ? ConstraintElement::Motion : ConstraintElement::Joint, element,
                    marker, y, force, torque);
  }
  // Coupler and Gear: their one equation's reaction on the part of any marker it reads (ADAMS
  // has no function for them; JOINT(...) and FORCE requests of the coupled joints leave it out).
  // Gcon: the reaction of a GCON's equation on the part of its I marker (zero when the FUNCTION
  // does not read I, as ADAMS documents).
  enum class ConstraintElement {
    Joint, Motion, JPrim, Coupler, Gear, Gcon, PointCurve, CurveCurve
  };
  void elementReaction(ConstraintElement kind, int element, int marker, const double* y,
                       Eigen::Vector3d& force, Eigen::Vector3d& torque) const;
  // The I and J markers of a constraint element.
  std::pair<int, int> elementMarkers(ConstraintElement kind, int element) const;
  // Sum of the reactions on `marker` of every constraint equation acting between `marker` and
  // `other` (any marker when other < 0): joints, joint primitives and motions.
  void constraintReactionBetween(int marker, int other, const double* y, Eigen::Vector3d& force,
                                 Eigen::Vector3d& torque) const;
  // Force and torque of SFORCE `index` on the part of `marker` (its I or J marker), in ground,
  // torque about the marker's origin.
  void sforceAction(int index, bool atJ, double t, const double* y, Eigen::Vector3d& force,
                    Eigen::Vector3d& torque) const;
  // Every applied force element (SFORCE, SPRINGDAMPER, BUSHING, FIELD, BEAM, VFORCE, VTORQUE,
  // GFORCE): their loads and read-back (mechanics/force_elements.hpp).
  const ForceElements& forceElements() const { return forces_; }
  // The residual rows of the force elements and the user equations alone (everything the
  // element-local Newton matrix, local_newton_matrix.hpp, leaves to compressed AD); g must be
  // zero on entry. `derivativesOnly`: the caller reads the derivative parts of g only, so
  // elements whose inputs carry no derivative may be left out (ForceElements::addToResidual).
  // `skip`: force elements left out (ForceElements::addToResidual).
  template <class T>
  void forceAndUserResidual(double t, const T* y, const T* yp, T* g, bool derivativesOnly = false,
                            const char* skip = nullptr) const {
    // As residual(): functions may read accelerations and reactions (dynamic_measures.hpp).
    const DynamicReads<T> base{yp, &constraints_};
    const DynamicReads<T> reads = forces_.readsWith(&base);  // and force read-backs (§4d)
    forces_.addToResidual(t, y, g, &reads, derivativesOnly, skip);
    user_.addToResidual(t, y, yp, g, &reads);
  }
  // True for the equation kinds whose constraint force has an analytic gradient here (Point,
  // Dot, Along, MotionTranslation); the others differentiate their geometry per direction.
  static bool hasAnalyticGradient(const ConstraintEquation& eq) {
    using K = ConstraintEquation::Kind;
    return eq.kind == K::Point || eq.kind == K::Dot || eq.kind == K::Along ||
           eq.kind == K::MotionTranslation;
  }
  // The geometry of an equation of those kinds (ConstraintSet::geometry, written again only so
  // that it instantiates on any scalar, e.g. the multi-direction duals of the local Newton
  // matrix).
  template <class T>
  static T analyticGeometry(const ConstraintEquation& eq, const Frame<T>* frames);
  // dPhi/d(virtual displacement of the part carrying eq.marker(side)): out[0..2] translation
  // along ground axes, out[3..5] rotation about the part's own axes (origin, axes: the part's
  // frame). Analytic for those kinds: with g_p = dPhi/dp and g_a[r] = dPhi/d(axis r) of the
  // marker, out = (g_p, (A^T (p - o)) x (A^T g_p) + sum_r (A^T a_r) x (A^T g_a[r])), which is the
  // virtual-displacement derivative below written out (equal for any A, orthogonal or not).
  template <class T>
  static void analyticSideGradient(const ConstraintEquation& eq, const Frame<T>* frames, int side,
                                   const V3<T>& origin, const M3<T>& axes, T* out);
  // Its Point case with the side's arm A^T (p - o) given: the three Point equations of a joint
  // share the arm, so the residual's serial rows and the element-local Newton matrix form it
  // once per joint side (docs/performance.md, "GSTIFF's cost per step, cheaper").
  template <class T>
  static void pointSideGradient(const ConstraintEquation& eq, int side, const V3<T>& arm,
                                const M3<T>& axes, T* out) {
    // g_p = +-e_axis: A^T g_p is +- row `axis` of A.
    const int c = eq.axisJ;
    const double sign = side == 0 ? 1.0 : -1.0;
    const V3<T> gpBody(sign * axes.c[0][c], sign * axes.c[1][c], sign * axes.c[2][c]);
    for (int d = 0; d < 3; ++d) out[d] = T(d == c ? sign : 0.0);
    const V3<T> torque = cross(arm, gpBody);
    for (int d = 0; d < 3; ++d) out[3 + d] = torque[d];
  }
  // The same for every kind (the others through virtualDerivative); T = double or Dual<double>.
  template <class T>
  static void sideGradient(const ConstraintEquation& eq, const Frame<T>* frames, int side,
                           const V3<T>& origin, const M3<T>& axes, T* out) {
    if (hasAnalyticGradient(eq)) {
      analyticSideGradient(eq, frames, side, origin, axes, out);
      return;
    }
    for (int dir = 0; dir < 6; ++dir)
      out[dir] = virtualDerivative(eq, frames, side, dir, origin, axes);
  }
  // The user equations (VARIABLE, DIFF, LSE, TFSISO): STATIC_HOLD flags, initial values.
  const UserEquations& userEquations() const { return user_; }
  // Sum of the force elements acting on `marker` (as I, or as J / JFLOAT), restricted to those
  // between `marker` and `other` when other >= 0: force on the marker's part and torque about
  // the marker's origin, ground axes.
  void forceElementsOnMarker(int marker, int other, double t, const double* y,
                             Eigen::Vector3d& force, Eigen::Vector3d& torque) const;

 private:
  template <class T>
  Frame<T> frame(int marker, const T* y) const;
  // The frames of every marker the equation reads (eq.markerCount() of them).
  template <class T>
  void equationFrames(const ConstraintEquation& eq, const T* y, Frame<T>* out) const {
    for (int s = 0; s < eq.markerCount(); ++s) out[s] = frame(eq.marker(s), y);
  }
  // Body poses and marker frames of one residual evaluation, each computed at most once per
  // call (stamped with the call's number): one scratch per scalar type and thread, so nothing
  // is allocated after the first call and the residual stays re-entrant across threads.
  template <class T>
  struct KinematicsScratch {
    std::uint64_t stamp = 0;
    std::vector<std::uint64_t> bodyStamp, markerStamp;
    std::vector<V3<T>> origin;
    std::vector<M3<T>> axes;
    std::vector<Frame<T>> frames;
  };
  template <class T>
  KinematicsScratch<T>& beginKinematics() const;
  template <class T>
  void cachedBody(KinematicsScratch<T>& k, int body, const T* y) const;
  template <class T>
  const Frame<T>& cachedFrame(KinematicsScratch<T>& k, int marker, const T* y) const;
  template <class T>
  void addConstraintForce(const ConstraintEquation& eq, const Frame<T>* frames,
                          KinematicsScratch<T>& k, const T* y, const T& lambda, T* g) const;
  // d(geometry of eq)/d(virtual displacement `dir` of the part that carries marker `side`
  // (eq.marker(side); 0 = I, 1 = J)): dir 0-2 translate along ground axes, 3-5 turn about the
  // part's own axes. `origin` and `axes` are that part's frame; `frames` the marker frames.
  template <class T>
  static T virtualDerivative(const ConstraintEquation& eq, const Frame<T>* frames, int side,
                             int dir, const V3<T>& origin, const M3<T>& axes);
  template <class T>
  void addSForces(double t, const T* y, T* g) const;
  template <class T>
  T sforceValue(int index, double t, const T* y) const;
  static double wrapDelta(double geometryValue, double target);
  // The constraint part of residual<double> in two phases (multibody_residual_parallel.cpp):
  // per equation, on the thread pool, its geometry and its force terms into the calling
  // thread's slots; then, on this thread in equation order, the same additions into g as the
  // serial loop makes. False (nothing done) when it does not apply: one thread, few equations,
  // or an equation kind whose evaluation reads shared state (the serial loop then runs).
  bool parallelConstraintRows(double t, const double* y, double* g) const;
  // The constraint part of residual<double> on one thread (multibody_residual_rows.cpp): the
  // rows of constraintRow in equation order with the marker frames, bodies and Point arms of
  // consecutive equations on the same markers (a joint's) taken once; bit-identical to it.
  void serialConstraintRows(double t, const double* y, double* g) const;
  // Equation k's row of G and its constraint forces -C^T lambda added into g (the serial loop).
  template <class T>
  void constraintRow(int k, double t, KinematicsScratch<T>& kin, const T* y, T* g) const;
  // Equation k's row from its geometry value: less its MOTION's target at t, an angle wrapped
  // to the target's turn (constraintRow and serialConstraintRows).
  template <class T>
  T rowValue(int k, double t, T value) const {
    const ConstraintEquation& eq = constraints_.equations()[k];
    if (eq.motion >= 0) {
      const double target = motionJet(k, t).value;
      value = value - target;
      if (ConstraintSet::wrapsAngle(eq)) value = value - wrapDelta(valueOf(value) + target, target);
    }
    return value;
  }
  // The reaction of equations selected by `take(eq)` on `marker`'s part.
  template <class Pick>
  void reactionOf(Pick take, int marker, const double* y, Eigen::Vector3d& force,
                  Eigen::Vector3d& torque) const;

  const model::Model* model_;
  const ExpressionRunState* runState_ = nullptr;
  StateLayout layout_;
  ConstraintSet constraints_;
  std::vector<double> mass_;               // per body, divided by UCF
  std::vector<Eigen::Matrix3d> inertia_;   // per body, divided by UCF
  ForceElements forces_;  // applied force elements (one code path for residual and read-back)
  UserEquations user_;    // VARIABLE, DIFF, LSE, TFSISO rows (docs/theory.md §4a)
  // Last motion target per motion (VELOCITY/ACCELERATION motions integrate f by quadrature;
  // the residual asks for the same time many times per Newton matrix). A pure cache: a hit
  // returns exactly what recomputation would.
  mutable std::vector<std::pair<double, expr::TimeJet>> motionCache_;
};

// ---- implementation of the templates ----

template <class T>
Frame<T> MultibodySystem::frame(int marker, const T* y) const {
  MarkerState<T> s = markerState(*model_, layout_, marker, y);
  return {s.p, s.a};
}

template <class T>
T MultibodySystem::virtualDerivative(const ConstraintEquation& eq, const Frame<T>* frames,
                                     int side, int dir, const V3<T>& origin, const M3<T>& axes) {
  // One definition for the residual and the reaction read-backs of force functions.
  return virtualGeometryDerivative(eq, frames, side, dir, origin, axes);
}

template <class T>
MultibodySystem::KinematicsScratch<T>& MultibodySystem::beginKinematics() const {
  thread_local KinematicsScratch<T> k;
  k.bodyStamp.resize(static_cast<size_t>(layout_.bodies), 0);
  k.markerStamp.resize(model_->markers.size(), 0);
  k.origin.resize(static_cast<size_t>(layout_.bodies));
  k.axes.resize(static_cast<size_t>(layout_.bodies));
  k.frames.resize(model_->markers.size());
  ++k.stamp;
  return k;
}

template <class T>
void MultibodySystem::cachedBody(KinematicsScratch<T>& k, int body, const T* y) const {
  if (k.bodyStamp[body] == k.stamp) return;
  const T* q = y + layout_.body(body);
  k.origin[body] = {q[StateLayout::kR], q[StateLayout::kR + 1], q[StateLayout::kR + 2]};
  k.axes[body] = rotationOf(Quat<T>{q[StateLayout::kE], q[StateLayout::kE + 1],
                                    q[StateLayout::kE + 2], q[StateLayout::kE + 3]});
  k.bodyStamp[body] = k.stamp;
}

template <class T>
const Frame<T>& MultibodySystem::cachedFrame(KinematicsScratch<T>& k, int marker,
                                             const T* y) const {
  Frame<T>& f = k.frames[marker];
  if (k.markerStamp[marker] == k.stamp) return f;
  const model::Marker& mk = model_->markers[marker];
  const int body = model_->parts[mk.part].body;
  const V3<T> sb = V3<T>::from(mk.position);
  const M3<T> ab = M3<T>::from(mk.orientation);
  if (body < 0) {
    f = {sb, ab};
  } else {
    // As markerState (pose.hpp), operation for operation.
    cachedBody(k, body, y);
    f.p = k.origin[body] + k.axes[body] * sb;
    f.a = k.axes[body] * ab;
  }
  k.markerStamp[marker] = k.stamp;
  return f;
}

template <class T>
T MultibodySystem::analyticGeometry(const ConstraintEquation& eq, const Frame<T>* frames) {
  using K = ConstraintEquation::Kind;
  const Frame<T>& i = frames[0];
  const Frame<T>& j = frames[1];
  if (eq.kind == K::Point) return (i.p - j.p)[eq.axisJ];
  if (eq.kind == K::Dot) return dot(i.a.c[eq.axisI], j.a.c[eq.axisJ]);
  return dot(j.a.c[eq.axisJ], i.p - j.p);  // Along, MotionTranslation
}

template <class T>
void MultibodySystem::analyticSideGradient(const ConstraintEquation& eq, const Frame<T>* frames,
                                           int side, const V3<T>& origin, const M3<T>& axes,
                                           T* out) {
  using K = ConstraintEquation::Kind;
  const Frame<T>& f = frames[side];
  V3<T> torque;
  switch (eq.kind) {
    case K::Point:
      pointSideGradient(eq, side, axes.tmul(f.p - origin), axes, out);
      return;
    case K::Dot: {
      // g_a[axisI] of I = axis axisJ of J and the other way round; no g_p.
      const V3<T>& own = side == 0 ? f.a.c[eq.axisI] : f.a.c[eq.axisJ];
      const V3<T>& other = side == 0 ? frames[1].a.c[eq.axisJ] : frames[0].a.c[eq.axisI];
      for (int d = 0; d < 3; ++d) out[d] = T(0.0);
      torque = cross(axes.tmul(own), axes.tmul(other));
      break;
    }
    default: {  // Along, MotionTranslation: z . (P_I - P_J), z = axis axisJ of J
      const V3<T>& z = frames[1].a.c[eq.axisJ];
      const V3<T> zBody = axes.tmul(z);
      const V3<T> arm = axes.tmul(f.p - origin);
      if (side == 0) {
        for (int d = 0; d < 3; ++d) out[d] = z[d];
        torque = cross(arm, zBody);
      } else {
        // g_p = -z; g_a[axisJ] = P_I - P_J.
        for (int d = 0; d < 3; ++d) out[d] = -z[d];
        torque = cross(zBody, arm) + cross(zBody, axes.tmul(frames[0].p - f.p));
      }
      break;
    }
  }
  for (int d = 0; d < 3; ++d) out[3 + d] = torque[d];
}

template <class T>
void MultibodySystem::addConstraintForce(const ConstraintEquation& eq, const Frame<T>* frames,
                                         KinematicsScratch<T>& k, const T* y, const T& lambda,
                                         T* g) const {
  for (int side = 0; side < eq.markerCount(); ++side) {
    const int body = model_->parts[model_->markers[eq.marker(side)].part].body;
    if (body < 0) continue;
    cachedBody(k, body, y);
    T d[6];
    sideGradient(eq, frames, side, k.origin[body], k.axes[body], d);
    const int o = layout_.body(body);
    for (int dir = 0; dir < 3; ++dir) {
      g[o + StateLayout::kV + dir] = g[o + StateLayout::kV + dir] + d[dir] * lambda;
      g[o + StateLayout::kW + dir] = g[o + StateLayout::kW + dir] + d[3 + dir] * lambda;
    }
  }
}

template <class T>
T MultibodySystem::sforceValue(int index, double t, const T* y) const {
  return forces_.sforceValue(index, t, y);
}

// Every applied force element, SFORCEs first (one code path: force_elements.hpp).
template <class T>
void MultibodySystem::addSForces(double t, const T* y, T* g) const {
  forces_.addToResidual(t, y, g);
}

template <class T>
void MultibodySystem::residual(double t, const T* y, const T* yp, T* g) const {
  userCouplerClock().store(t, std::memory_order_relaxed);  // COUSUB's TIME argument
  const int nb = layout_.bodies;
  const Eigen::Vector3d& grav = model_->gravity;
  for (int b = 0; b < nb; ++b) {
    const int o = layout_.body(b);
    const T* q = y + o;
    const T* qp = yp + o;
    T* r = g + o;
    for (int c = 0; c < 3; ++c) r[StateLayout::kR + c] = qp[StateLayout::kR + c] - q[StateLayout::kV + c];
    const T& e0 = q[StateLayout::kE];
    const T& e1 = q[StateLayout::kE + 1];
    const T& e2 = q[StateLayout::kE + 2];
    const T& e3 = q[StateLayout::kE + 3];
    const T& w1 = q[StateLayout::kW];
    const T& w2 = q[StateLayout::kW + 1];
    const T& w3 = q[StateLayout::kW + 2];
    const T& mu = q[StateLayout::kMu];
    // e' = 1/2 e (x) (0, w_body) + mu e; mu is zero on the exact solution and absorbs the
    // normalisation equation |e|^2 = 1 (index-2 pair, no drift of |e|).
    r[StateLayout::kE + 0] = qp[StateLayout::kE + 0] - 0.5 * (-e1 * w1 - e2 * w2 - e3 * w3) - mu * e0;
    r[StateLayout::kE + 1] = qp[StateLayout::kE + 1] - 0.5 * (e0 * w1 + e2 * w3 - e3 * w2) - mu * e1;
    r[StateLayout::kE + 2] = qp[StateLayout::kE + 2] - 0.5 * (e0 * w2 + e3 * w1 - e1 * w3) - mu * e2;
    r[StateLayout::kE + 3] = qp[StateLayout::kE + 3] - 0.5 * (e0 * w3 + e1 * w2 - e2 * w1) - mu * e3;
    const double m = mass_[b];
    for (int c = 0; c < 3; ++c)
      r[StateLayout::kV + c] = m * qp[StateLayout::kV + c] - m * grav(c);
    const Eigen::Matrix3d& jm = inertia_[b];
    const V3<T> w{w1, w2, w3};
    const V3<T> wdot{qp[StateLayout::kW], qp[StateLayout::kW + 1], qp[StateLayout::kW + 2]};
    V3<T> jw, jwdot;
    for (int rr = 0; rr < 3; ++rr) {
      jw[rr] = jm(rr, 0) * w.x + jm(rr, 1) * w.y + jm(rr, 2) * w.z;
      jwdot[rr] = jm(rr, 0) * wdot.x + jm(rr, 1) * wdot.y + jm(rr, 2) * wdot.z;
    }
    const V3<T> gyro = cross(w, jw);
    for (int c = 0; c < 3; ++c) r[StateLayout::kW + c] = jwdot[c] + gyro[c];
    r[StateLayout::kMu] = e0 * e0 + e1 * e1 + e2 * e2 + e3 * e3 - 1.0;
  }
  // Functions may read accelerations (y') and reactions (multipliers): dynamic_measures.hpp.
  const DynamicReads<T> base{yp, &constraints_};
  const DynamicReads<T> reads = forces_.readsWith(&base);  // and force read-backs (§4d)
  forces_.addToResidual(t, y, g, &reads);
  user_.addToResidual(t, y, yp, g, &reads);
  if constexpr (std::is_same_v<T, double>) {
    // Large models: the constraint rows and forces on the thread pool, same bits
    // (multibody_residual_parallel.cpp).
    if (parallelConstraintRows(t, y, g)) return;
    // Otherwise the serial loop below with a joint's shared work done once, same bits
    // (multibody_residual_rows.cpp).
    serialConstraintRows(t, y, g);
    return;
  }
  const auto& eqs = constraints_.equations();
  KinematicsScratch<T>& kin = beginKinematics<T>();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) constraintRow(k, t, kin, y, g);
}

template <class T>
void MultibodySystem::constraintRow(int k, double t, KinematicsScratch<T>& kin, const T* y,
                                    T* g) const {
  const ConstraintEquation& eq = constraints_.equations()[k];
  const T& lambda = y[layout_.lambda(k)];
  T& row = g[layout_.lambda(k)];
  if (!eq.active) {
    row = lambda;
    return;
  }
  Frame<T> frames[ConstraintEquation::kMaxMarkers];
  for (int s = 0; s < eq.markerCount(); ++s) frames[s] = cachedFrame(kin, eq.marker(s), y);
  addConstraintForce(eq, frames, kin, y, lambda, g);
  row = rowValue(k, t, ConstraintSet::geometry(eq, frames));
}

}  // namespace openmss::mechanics
