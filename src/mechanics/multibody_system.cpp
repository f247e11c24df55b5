#include "mechanics/multibody_system.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

#include "common/rotation.hpp"
#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/motion_profile.hpp"

namespace openmss::mechanics {

MultibodySystem::MultibodySystem(const model::Model& model)
    : model_(&model), constraints_(model), forces_(model), user_(model) {
  layout_.bodies = model.bodyCount();
  layout_.userDifferential = model.userDifferentialCount();
  layout_.userAlgebraic = model.userAlgebraicCount();
  layout_.constraintEquations = constraints_.size();
  user_.setLayout(layout_);
  motionCache_.assign(model.motions.size(),
                      {std::numeric_limits<double>::quiet_NaN(), expr::TimeJet{}});
  for (int p : model.movingParts) {
    mass_.push_back(model.parts[p].mass / model.units.ucf);
    inertia_.push_back(model.parts[p].inertia / model.units.ucf);
  }
}

double MultibodySystem::wrapDelta(double geometryValue, double target) {
  // A rotation angle from atan2 lies in (-pi, pi]; the motion's target grows without bound.
  // The equation compares them modulo 2 pi: this is the whole turns to take off.
  const double twoPi = 2.0 * std::numbers::pi;
  return twoPi * std::round((geometryValue - target) / twoPi);
}

Eigen::VectorXd MultibodySystem::initialState() const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(layout_.size());
  for (int b = 0; b < layout_.bodies; ++b) {
    const model::Part& p = model_->parts[model_->movingParts[b]];
    const int o = layout_.body(b);
    y.segment<3>(o + StateLayout::kR) = p.position;
    y.segment<4>(o + StateLayout::kE) = quaternionFromMatrix(p.orientation);
    for (int c = 0; c < 3; ++c) {
      y(o + StateLayout::kV + c) = p.velocity[c].value_or(0.0);
      y(o + StateLayout::kW + c) = p.angularVelocity[c].value_or(0.0);
    }
  }
  user_.initialValues(y.data());
  return y;
}

void MultibodySystem::newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                   double cj, Eigen::MatrixXd& jac) const {
  using D = Dual<double>;
  const int n = layout_.size();
  jac.resize(n, n);
  std::vector<D> yd(n), ypd(n), g(n);
  for (int i = 0; i < n; ++i) {
    yd[i] = D(y(i), 0.0);
    ypd[i] = D(yp(i), 0.0);
  }
  for (int c = 0; c < n; ++c) {
    // Direction e_c in y and cj e_c in y' (y' = cj y + const during the corrector).
    yd[c].d = 1.0;
    ypd[c].d = layout_.differential(c) ? cj : 0.0;
    for (int i = 0; i < n; ++i) g[i] = D(0.0, 0.0);
    residual(t, yd.data(), ypd.data(), g.data());
    for (int r = 0; r < n; ++r) jac(r, c) = g[r].d;
    yd[c].d = 0.0;
    ypd[c].d = 0.0;
  }
}

namespace {

// Seeds the dual state: values of y and y', zero derivatives.
void seedValues(const Eigen::VectorXd& y, const Eigen::VectorXd& yp, SparseJacobianWork& w) {
  const auto n = static_cast<size_t>(y.size());
  w.y.resize(n);
  w.yp.resize(n);
  w.g.resize(n);
  for (size_t i = 0; i < n; ++i) {
    w.y[i] = Dual<double>(y(static_cast<Eigen::Index>(i)), 0.0);
    w.yp[i] = Dual<double>(yp(static_cast<Eigen::Index>(i)), 0.0);
  }
}

}  // namespace

void MultibodySystem::newtonMatrixSparse(double t, const Eigen::VectorXd& y,
                                         const Eigen::VectorXd& yp, double cj,
                                         const JacobianPattern& pattern,
                                         Eigen::SparseMatrix<double>& jac,
                                         SparseJacobianWork& work) const {
  using D = Dual<double>;
  const int n = layout_.size();
  double* values = jac.valuePtr();
  if (work.elementLocal) {
    // Element by element (local_newton_matrix.hpp), planned once per pattern.
    if (!work.local || work.local->patternStamp() != pattern.stamp)
      work.local = std::make_shared<LocalNewtonMatrix>(*this, pattern, work.forceElementsLocal);
    if (work.local->usable()) {
      work.local->assemble(t, y, yp, cj, values, work);
      return;
    }
  }
  seedValues(y, yp, work);
  for (int colour = 0; colour < pattern.colours(); ++colour) {
    const int first = pattern.colourStart[colour], last = pattern.colourStart[colour + 1];
    // Direction: the sum of e_c over the colour's columns (and cj e_c in y'). No row reads two
    // of them, so row r's derivative is the entry of the one column of the colour it reads.
    for (int k = first; k < last; ++k) {
      const int c = pattern.colourColumns[k];
      work.y[c].d = 1.0;
      work.yp[c].d = layout_.differential(c) ? cj : 0.0;
    }
    for (int i = 0; i < n; ++i) work.g[i] = D(0.0, 0.0);
    residual(t, work.y.data(), work.yp.data(), work.g.data());
    for (int k = first; k < last; ++k) {
      const int c = pattern.colourColumns[k];
      for (int e = pattern.columnStart[c]; e < pattern.columnStart[c + 1]; ++e)
        values[e] = work.g[pattern.rowIndex[e]].d;
      work.y[c].d = 0.0;
      work.yp[c].d = 0.0;
    }
  }
}

std::vector<int> MultibodySystem::rowsOutsidePattern(double t, const Eigen::VectorXd& y,
                                                     const Eigen::VectorXd& yp, double cj,
                                                     const Eigen::SparseMatrix<double>& jac,
                                                     SparseJacobianWork& work) const {
  using D = Dual<double>;
  const int n = layout_.size();
  seedValues(y, yp, work);
  work.direction.resize(n);
  work.product.assign(n, 0.0);
  // A fixed direction with entries of both signs in [0.5, 1.5] (a linear congruential sequence:
  // deterministic, and no entry zero, so no column escapes the check).
  unsigned state = 12345u;
  for (int c = 0; c < n; ++c) {
    state = state * 1664525u + 1013904223u;
    const double u = static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
    work.direction[c] = (u < 0.5 ? -1.0 : 1.0) * (0.5 + 2.0 * std::abs(u - 0.5));
    work.y[c].d = work.direction[c];
    work.yp[c].d = layout_.differential(c) ? cj * work.direction[c] : 0.0;
  }
  for (int i = 0; i < n; ++i) work.g[i] = D(0.0, 0.0);
  residual(t, work.y.data(), work.yp.data(), work.g.data());
  // |J| |v| per row: the scale of round-off in both products.
  std::vector<double>& sparseProduct = work.product;
  std::vector<double>& magnitude = work.magnitude;
  magnitude.assign(n, 0.0);
  for (int c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(jac, c); it; ++it) {
      sparseProduct[it.row()] += it.value() * work.direction[c];
      magnitude[it.row()] += std::abs(it.value() * work.direction[c]);
    }
  std::vector<int> rows;
  for (int r = 0; r < n; ++r) {
    const double exact = work.g[r].d;
    // A state where the residual is not finite says nothing about the pattern.
    if (!std::isfinite(exact) || !std::isfinite(sparseProduct[r])) continue;
    if (!(std::abs(exact - sparseProduct[r]) <= 1e-8 * (magnitude[r] + std::abs(exact))))
      rows.push_back(r);
  }
  return rows;
}

expr::TimeJet MultibodySystem::motionJet(int k, double t) const {
  const ConstraintEquation& eq = constraints_.equations()[k];
  auto& cached = motionCache_[eq.motion];
  if (cached.first != t || std::isnan(cached.second.value))
    cached = {t, motionProfile(model_->motions[eq.motion], t)};
  return cached.second;
}

double MultibodySystem::constraintValue(int k, double t, const double* y) const {
  Frame<double> frames[ConstraintEquation::kMaxMarkers];
  equationFrames(constraints_.equations()[k], y, frames);
  return constraintValue(k, t, frames);
}

double MultibodySystem::constraintValue(int k, double t, const Frame<double>* frames) const {
  const ConstraintEquation& eq = constraints_.equations()[k];
  double value = ConstraintSet::geometry(eq, frames);
  if (eq.motion >= 0) {
    const double target = motionJet(k, t).value;
    value -= target;
    if (ConstraintSet::wrapsAngle(eq)) value -= wrapDelta(value + target, target);
  }
  return value;
}

void MultibodySystem::constraintRow(int k, const double* y, double* row) const {
  constraintRow(constraints_.equations()[k], y, row);
}

double MultibodySystem::coupledAngle(const ConstraintEquation& eq, int term,
                                     const double* y) const {
  // The equation reduced to this one term with unit scale and zero reference is its angle.
  ConstraintEquation one = eq;
  one.terms = {eq.terms[static_cast<std::size_t>(term)]};
  one.terms[0].scale = 1.0;
  one.terms[0].reference = 0.0;
  one.userCoupler = nullptr;  // the angle itself, not a user coupler's phi of it
  return geometryValue(one, y);
}

double MultibodySystem::geometryValue(const ConstraintEquation& eq, const double* y) const {
  Frame<double> frames[ConstraintEquation::kMaxMarkers];
  equationFrames(eq, y, frames);
  return ConstraintSet::geometry(eq, frames);
}

void MultibodySystem::constraintRow(const ConstraintEquation& eq, const double* y,
                                    double* row) const {
  // The dense row is the scattered sparse one (one code path for the numbers).
  std::vector<int> cols;
  std::vector<double> vals;
  constraintRowEntries(eq, y, cols, vals);
  std::fill(row, row + 6 * layout_.bodies, 0.0);
  for (size_t i = 0; i < cols.size(); ++i) row[cols[i]] = vals[i];
}

void MultibodySystem::constraintRowEntries(int k, const double* y, std::vector<int>& cols,
                                           std::vector<double>& vals) const {
  constraintRowEntries(constraints_.equations()[k], y, cols, vals);
}

void MultibodySystem::constraintRowEntries(const ConstraintEquation& eq, const double* y,
                                           std::vector<int>& cols,
                                           std::vector<double>& vals) const {
  cols.clear();
  vals.clear();
  Frame<double> frames[ConstraintEquation::kMaxMarkers];
  equationFrames(eq, y, frames);
  // The bodies in increasing order, each once (two markers of one equation may share a body:
  // their derivatives add, in marker order, as addConstraintForce adds them).
  int bodies[ConstraintEquation::kMaxMarkers];
  int count = 0;
  for (int side = 0; side < eq.markerCount(); ++side) {
    const int body = model_->parts[model_->markers[eq.marker(side)].part].body;
    if (body >= 0 && std::find(bodies, bodies + count, body) == bodies + count)
      bodies[count++] = body;
  }
  // Insertion sort of at most kMaxMarkers entries (std::sort trips GCC 12's -Warray-bounds).
  for (int i = 1; i < count; ++i)
    for (int j = i; j > 0 && bodies[j - 1] > bodies[j]; --j) std::swap(bodies[j - 1], bodies[j]);
  for (int i = 0; i < count; ++i)
    for (int dir = 0; dir < 6; ++dir) {
      cols.push_back(6 * bodies[i] + dir);
      vals.push_back(0.0);
    }
  for (int side = 0; side < eq.markerCount(); ++side) {
    const int body = model_->parts[model_->markers[eq.marker(side)].part].body;
    if (body < 0) continue;
    const int slot = 6 * static_cast<int>(std::find(bodies, bodies + count, body) - bodies);
    const BodyPose<double> pose = bodyPose(layout_, body, y);
    double d[6];
    sideGradient(eq, frames, side, pose.r, pose.a, d);
    for (int dir = 0; dir < 6; ++dir) vals[slot + dir] = vals[slot + dir] + d[dir];
  }
}

void MultibodySystem::constraintRates(int k, const double* y, double* first,
                                      double* second) const {
  // Evaluate the geometry along the path the markers follow with the current velocities and
  // zero accelerations, with second-order jets: r(s) = r + s v, A(s) = A exp(s [w]).
  using J = Dual<Dual<double>>;
  const ConstraintEquation& eq = constraints_.equations()[k];
  Frame<J> f[ConstraintEquation::kMaxMarkers];
  for (int side = 0; side < eq.markerCount(); ++side) {
    const model::Marker& mk = model_->markers[eq.marker(side)];
    const int body = model_->parts[mk.part].body;
    const Frame<double> base = frame(eq.marker(side), y);
    V3<double> dp(0, 0, 0), ddp(0, 0, 0);
    M3<double> da, dda;
    for (int r = 0; r < 3; ++r) da.c[r] = dda.c[r] = V3<double>(0, 0, 0);
    if (body >= 0) {
      const BodyPose<double> pose = bodyPose(layout_, body, y);
      const V3<double> wb{y[layout_.body(body) + StateLayout::kW],
                          y[layout_.body(body) + StateLayout::kW + 1],
                          y[layout_.body(body) + StateLayout::kW + 2]};
      const V3<double> sb = V3<double>::from(mk.position);
      dp = pose.v + pose.a * cross(wb, sb);
      ddp = pose.a * cross(wb, cross(wb, sb));
      const M3<double> ab = M3<double>::from(mk.orientation);
      for (int r = 0; r < 3; ++r) {
        da.c[r] = pose.a * cross(wb, ab.c[r]);
        dda.c[r] = pose.a * cross(wb, cross(wb, ab.c[r]));
      }
    }
    for (int c = 0; c < 3; ++c) {
      f[side].p[c] = J(Dual<double>(base.p[c], dp[c]), Dual<double>(dp[c], ddp[c]));
      for (int r = 0; r < 3; ++r)
        f[side].a.c[r][c] = J(Dual<double>(base.a.c[r][c], da.c[r][c]),
                              Dual<double>(da.c[r][c], dda.c[r][c]));
    }
  }
  const J v = ConstraintSet::geometry(eq, f);
  *first = v.v.d;
  *second = v.d.d;
}

void MultibodySystem::appliedForces(double t, const double* y, Eigen::VectorXd& q) const {
  const int nb = layout_.bodies;
  // One scratch per thread: explicit integrators call this several times per step
  // (index_one_dynamics.cpp), so it allocates only on the first call.
  thread_local std::vector<double> g;
  g.assign(static_cast<size_t>(layout_.size()), 0.0);
  addSForces(t, y, g.data());
  q.resize(6 * nb);
  for (int b = 0; b < nb; ++b) {
    const int o = layout_.body(b);
    const Eigen::Vector3d w(y[o + StateLayout::kW], y[o + StateLayout::kW + 1],
                            y[o + StateLayout::kW + 2]);
    const Eigen::Vector3d gyro = w.cross(inertia_[b] * w);
    for (int c = 0; c < 3; ++c) {
      q(6 * b + c) = -g[o + StateLayout::kV + c] + mass_[b] * model_->gravity(c);
      q(6 * b + 3 + c) = -g[o + StateLayout::kW + c] - gyro(c);
    }
  }
}

void MultibodySystem::massMatrix(Eigen::MatrixXd& m) const {
  const int nb = layout_.bodies;
  m = Eigen::MatrixXd::Zero(6 * nb, 6 * nb);
  for (int b = 0; b < nb; ++b) {
    m.block<3, 3>(6 * b, 6 * b) = mass_[b] * Eigen::Matrix3d::Identity();
    m.block<3, 3>(6 * b + 3, 6 * b + 3) = inertia_[b];
  }
}

template <class Pick>
void MultibodySystem::reactionOf(Pick take, int marker, const double* y, Eigen::Vector3d& force,
                                 Eigen::Vector3d& torque) const {
  // Generalised constraint force on the marker's part, computed for the part's own frame even
  // when it is ground (its pose is fixed, but the virtual displacement is well defined).
  force.setZero();
  torque.setZero();
  const model::Marker& mk = model_->markers[marker];
  const int body = model_->parts[mk.part].body;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  if (body >= 0) {
    const BodyPose<double> pose = bodyPose(layout_, body, y);
    origin = toEigen(pose.r);
    a = toEigen(pose.a);
  }
  const auto& eqs = constraints_.equations();
  const V3<double> o = V3<double>::from(origin);
  const M3<double> am = M3<double>::from(a);
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    const ConstraintEquation& eq = eqs[k];
    if (!eq.active || !take(eq)) continue;
    const double lambda = y[layout_.lambda(k)];
    Frame<double> frames[ConstraintEquation::kMaxMarkers];
    equationFrames(eq, y, frames);
    for (int side = 0; side < eq.markerCount(); ++side) {
      if (eq.marker(side) != marker) continue;
      double dphi[6];
      sideGradient(eq, frames, side, o, am, dphi);
      for (int dir = 0; dir < 6; ++dir) {
        // The constraint force on the part is -C^T lambda; torques in part axes about its
        // origin.
        if (dir < 3) force(dir) -= dphi[dir] * lambda;
        else torque(dir - 3) -= dphi[dir] * lambda;
      }
    }
  }
  // Torque about the marker origin, in ground.
  const Frame<double> fm = frame(marker, y);
  const Eigen::Vector3d pm(fm.p.x, fm.p.y, fm.p.z);
  torque = a * torque - (pm - origin).cross(force);
}

void MultibodySystem::curveParameters(const ConstraintEquation& eq, const double* y,
                                      double* out) const {
  Frame<double> f[ConstraintEquation::kMaxMarkers];
  equationFrames(eq, y, f);
  if (eq.kind == ConstraintEquation::Kind::PointCurve) {
    const V3<double> q = f[1].a.tmul(f[0].p - f[1].p);
    out[0] = nearestCurveParameter(*eq.curve, q, eq.curveSamples, eq.warm);
  } else if (eq.kind == ConstraintEquation::Kind::CurveCurve) {
    std::array<double, 2> ab{};
    curveCurveResiduals(*eq.curve, eq.curveSamples, *eq.curveJ, eq.curveSamplesJ, f[0].p, f[0].a,
                        f[1].p, f[1].a, eq.warm, &ab);
    out[0] = ab[0];
    out[1] = ab[1];
  }
}

std::pair<int, int> MultibodySystem::elementMarkers(ConstraintElement kind, int element) const {
  switch (kind) {
    case ConstraintElement::Joint:
      return {model_->joints[element].iMarker, model_->joints[element].jMarker};
    case ConstraintElement::Motion:
      return {model_->motions[element].iMarker, model_->motions[element].jMarker};
    case ConstraintElement::JPrim:
      return {model_->jprims[element].iMarker, model_->jprims[element].jMarker};
    case ConstraintElement::Coupler: {
      const model::Joint& j = model_->joints[model_->couplers[element].joints[0]];
      return {j.iMarker, j.jMarker};
    }
    case ConstraintElement::Gear: {
      const model::Joint& j = model_->joints[model_->gears[element].joints[0]];
      return {j.iMarker, j.jMarker};
    }
    case ConstraintElement::Gcon:
      return {model_->gcons[element].iMarker, -1};
    case ConstraintElement::PointCurve:
      return {model_->ptcvs[element].iMarker, model_->ptcvs[element].rmMarker};
    case ConstraintElement::CurveCurve:
      return {model_->cvcvs[element].iRm, model_->cvcvs[element].jRm};
  }
  return {-1, -1};
}

void MultibodySystem::elementReaction(ConstraintElement kind, int element, int marker,
                                      const double* y, Eigen::Vector3d& force,
                                      Eigen::Vector3d& torque) const {
  reactionOf(
      [&](const ConstraintEquation& eq) {
        switch (kind) {
          case ConstraintElement::Joint: return eq.joint == element;
          case ConstraintElement::Motion: return eq.motion == element;
          case ConstraintElement::JPrim: return eq.jprim == element;
          case ConstraintElement::Coupler: return eq.coupler == element;
          case ConstraintElement::Gear: return eq.gear == element;
          case ConstraintElement::Gcon: return eq.gcon == element;
          case ConstraintElement::PointCurve: return eq.ptcv == element;
          case ConstraintElement::CurveCurve: return eq.cvcv == element;
        }
        return false;
      },
      marker, y, force, torque);
}

void MultibodySystem::constraintReactionBetween(int marker, int other, const double* y,
                                                Eigen::Vector3d& force,
                                                Eigen::Vector3d& torque) const {
  reactionOf(
      [&](const ConstraintEquation& eq) {
        // A coupling's reaction is not the joints' (ADAMS reports joint reactions only).
        if (eq.coupler >= 0 || eq.gear >= 0) return false;
        return other < 0 || eq.iMarker == other || eq.jMarker == other;
      },
      marker, y, force, torque);
}

void MultibodySystem::sforceAction(int index, bool atJ, double t, const double* y,
                                   Eigen::Vector3d& force, Eigen::Vector3d& torque) const {
  forces_.action({ForceElementKind::SForce, index}, atJ, t, y, force, torque);
}

void MultibodySystem::forceElementsOnMarker(int marker, int other, double t, const double* y,
                                            Eigen::Vector3d& force,
                                            Eigen::Vector3d& torque) const {
  force.setZero();
  torque.setZero();
  Eigen::Vector3d f, tq;
  for (const ForceElementRef& e : forces_.elements()) {
    const int i = forces_.iMarker(e), j = forces_.jMarker(e);
    const bool atI = i == marker && (other < 0 || j == other);
    const bool atJ = j == marker && (other < 0 || i == other);
    if (!atI && !atJ) continue;
    forces_.action(e, !atI, t, y, f, tq);
    force += f;
    torque += tq;
  }
}

}  // namespace openmss::mechanics
