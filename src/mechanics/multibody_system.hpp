#pragma once
// The equations of motion of a Model over the state layout of state_layout.hpp
// (docs/theory.md): kinematic equations, Newton-Euler equations with constraint forces
// -C^T lambda, Euler-parameter normalisation, and the constraint equations (index 3).
// Everything is templated on the scalar; exact Jacobians come from forward-mode AD.

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "common/dual.hpp"
#include "mechanics/bound_function.hpp"
#include "mechanics/constraint_set.hpp"
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
  enum class ConstraintElement { Joint, Motion, JPrim, Coupler, Gear, Gcon };
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
  template <class T>
  void addConstraintForce(const ConstraintEquation& eq, const T* y, const T& lambda,
                          T* g) const;
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
  // The reaction of equations selected by `take(eq)` on `marker`'s part.
  template <class Pick>
  void reactionOf(Pick take, int marker, const double* y, Eigen::Vector3d& force,
                  Eigen::Vector3d& torque) const;

  const model::Model* model_;
  StateLayout layout_;
  ConstraintSet constraints_;
  std::vector<double> mass_;               // per body, divided by UCF
  std::vector<Eigen::Matrix3d> inertia_;   // per body, divided by UCF
  mutable std::vector<double> scratchValues_, scratchGrad_;
  ForceElements forces_;  // applied force elements (one code path for residual and read-back)
  UserEquations user_;    // VARIABLE, DIFF, LSE, TFSISO rows (docs/theory.md §4a)
  // Last motion target per motion (VELOCITY/ACCELERATION motions integrate f by quadrature;
  // the residual asks for the same time many times per Newton matrix).
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
  using S = Dual<T>;
  Frame<S> f[ConstraintEquation::kMaxMarkers];
  for (int s = 0; s < eq.markerCount(); ++s)
    for (int c = 0; c < 3; ++c) {
      f[s].p[c] = S(frames[s].p[c], T(0.0));
      for (int r = 0; r < 3; ++r) f[s].a.c[r][c] = S(frames[s].a.c[r][c], T(0.0));
    }
  if (dir < 3) {
    f[side].p[dir].d = T(1.0);
  } else {
    // A <- A (I + [e_k] x): points and axes of the part turn about its k-th body axis.
    V3<T> ek(T(0.0), T(0.0), T(0.0));
    ek[dir - 3] = T(1.0);
    const V3<T> dp = axes * cross(ek, axes.tmul(frames[side].p - origin));
    for (int c = 0; c < 3; ++c) f[side].p[c].d = dp[c];
    for (int r = 0; r < 3; ++r) {
      const V3<T> da = axes * cross(ek, axes.tmul(frames[side].a.c[r]));
      for (int c = 0; c < 3; ++c) f[side].a.c[r][c].d = da[c];
    }
  }
  return ConstraintSet::geometry(eq, f).d;
}

template <class T>
void MultibodySystem::addConstraintForce(const ConstraintEquation& eq, const T* y,
                                         const T& lambda, T* g) const {
  Frame<T> frames[ConstraintEquation::kMaxMarkers];
  equationFrames(eq, y, frames);
  for (int side = 0; side < eq.markerCount(); ++side) {
    const int body = model_->parts[model_->markers[eq.marker(side)].part].body;
    if (body < 0) continue;
    const BodyPose<T> pose = bodyPose(layout_, body, y);
    for (int dir = 0; dir < 6; ++dir) {
      const T d = virtualDerivative(eq, frames, side, dir, pose.r, pose.a);
      const int row = layout_.body(body) +
                      (dir < 3 ? StateLayout::kV + dir : StateLayout::kW + dir - 3);
      g[row] = g[row] + d * lambda;
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
  addSForces(t, y, g);
  user_.addToResidual(t, y, yp, g);
  const auto& eqs = constraints_.equations();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    const ConstraintEquation& eq = eqs[k];
    const T& lambda = y[layout_.lambda(k)];
    T& row = g[layout_.lambda(k)];
    if (!eq.active) {
      row = lambda;
      continue;
    }
    addConstraintForce(eq, y, lambda, g);
    Frame<T> frames[ConstraintEquation::kMaxMarkers];
    equationFrames(eq, y, frames);
    T value = ConstraintSet::geometry(eq, frames);
    if (eq.motion >= 0) {
      const double target = motionJet(k, t).value;
      value = value - target;
      if (ConstraintSet::wrapsAngle(eq))
        value = value - wrapDelta(valueOf(value) + target, target);
    }
    row = value;
  }
}

}  // namespace openmss::mechanics
