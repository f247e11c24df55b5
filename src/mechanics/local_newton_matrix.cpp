#include "mechanics/local_newton_matrix.hpp"

#include <algorithm>
#include <type_traits>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

// The equations with analytic gradients go through all the 7 positions of up to two bodies in
// one pass; the others one direction at a time with Dual<double> (their geometry is written
// for double, Dual and Dual<Dual> only).
using Multi = DualVec<LocalNewtonMatrix::kChunk>;

template <class S>
struct Seeds;
template <int N>
struct Seeds<DualVec<N>> {
  static constexpr int count = N;
  static double& at(DualVec<N>& x, int k) { return x.d[k]; }
  static double get(const DualVec<N>& x, int k) { return x.d[k]; }
  static double value(const DualVec<N>& x) { return x.v; }
};
template <>
struct Seeds<Dual<double>> {
  static constexpr int count = 1;
  static double& at(Dual<double>& x, int) { return x.d; }
  static double get(const Dual<double>& x, int) { return x.d; }
  static double value(const Dual<double>& x) { return x.v; }
};

// The body entries in a fixed order (row offset, column offset within the body's 14): the
// kinematic rows (r' - v), the Euler-parameter rows (e, w, mu), the mass and inertia rows,
// the normalisation row.
template <class Visit>
void forEachBodyEntry(Visit visit) {
  for (int c = 0; c < 3; ++c) {
    visit(L::kR + c, L::kR + c);
    visit(L::kR + c, L::kV + c);
  }
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) visit(L::kE + r, L::kE + c);
    for (int c = 0; c < 3; ++c) visit(L::kE + r, L::kW + c);
    visit(L::kE + r, L::kMu);
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) visit(L::kV + r, L::kV + c);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) visit(L::kW + r, L::kW + c);
  for (int c = 0; c < 4; ++c) visit(L::kMu, L::kE + c);
}

}  // namespace

LocalNewtonMatrix::LocalNewtonMatrix(const MultibodySystem& system, const JacobianPattern& pattern,
                                     bool localForces)
    : system_(system), patternStamp_(pattern.stamp), nonZeros_(pattern.nonZeros()) {
  // Dense rows (a repair, or a dependency the pattern rules could not resolve) mean some
  // contribution is not known element by element: colour the whole residual instead.
  // A pattern larger by one row and column per constraint equation carries the SI2 terms.
  const StateLayout& l = system.layout();
  stabilised_ = l.constraintEquations > 0 && pattern.size == l.size() + l.constraintEquations;
  usable_ = pattern.denseRows == 0 && (pattern.size == l.size() || stabilised_);
  if (usable_) planBodies(pattern);
  if (usable_) planEquations(pattern);
  forceSkip_.assign(system.forceElements().elements().size(), 0);
  if (usable_ && localForces) planForceElements(pattern);
  if (usable_) planForceAndUser(pattern);
  if (usable_) parallelColours_ = coloursMayRunInParallel();
}

int LocalNewtonMatrix::find(const JacobianPattern& p, int row, int column) {
  const auto first = p.rowIndex.begin() + p.columnStart[column];
  const auto last = p.rowIndex.begin() + p.columnStart[column + 1];
  const auto it = std::lower_bound(first, last, row);
  if (it == last || *it != row) return -1;
  return static_cast<int>(it - p.rowIndex.begin());
}

void LocalNewtonMatrix::planBodies(const JacobianPattern& p) {
  const StateLayout& l = system_.layout();
  bodyIndex_.reserve(static_cast<size_t>(kBodyEntries * l.bodies));
  for (int b = 0; b < l.bodies; ++b)
    forEachBodyEntry([&](int r, int c) {
      const int k = find(p, l.body(b) + r, l.body(b) + c);
      if (k < 0) usable_ = false;
      bodyIndex_.push_back(k);
    });
}

void LocalNewtonMatrix::planEquations(const JacobianPattern& p) {
  const StateLayout& l = system_.layout();
  const model::Model& m = system_.model();
  const auto& eqs = system_.constraints().equations();
  for (int k = 0; k < static_cast<int>(eqs.size()) && usable_; ++k) {
    const ConstraintEquation& eq = eqs[k];
    if (eq.kind == ConstraintEquation::Kind::General ||
        eq.kind == ConstraintEquation::Kind::User || eq.markerCount() > 6) {
      // Reads marker measures through an expression or user code: not planned here.
      usable_ = false;
      return;
    }
    EquationPlan plan;
    for (int side = 0; side < eq.markerCount(); ++side) {
      const int body = m.parts[m.markers[eq.marker(side)].part].body;
      if (body >= 0 && std::find(plan.bodies, plan.bodies + plan.bodyCount, body) ==
                           plan.bodies + plan.bodyCount)
        plan.bodies[plan.bodyCount++] = body;
    }
    for (int i = 1; i < plan.bodyCount; ++i)
      for (int j = i; j > 0 && plan.bodies[j - 1] > plan.bodies[j]; --j)
        std::swap(plan.bodies[j - 1], plan.bodies[j]);
    for (int side = 0; side < eq.markerCount(); ++side) {
      const int body = m.parts[m.markers[eq.marker(side)].part].body;
      plan.slot[side] = body < 0 ? -1
                                 : static_cast<int>(std::find(plan.bodies,
                                                              plan.bodies + plan.bodyCount, body) -
                                                    plan.bodies);
    }
    plan.index = static_cast<int>(index_.size());
    const int lambda = l.lambda(k);
    const int n = plan.bodyCount;
    auto column = [&](int j) { return l.body(plan.bodies[j / 7]) + j % 7; };  // r then e
    auto add = [&](int row, int col) {
      const int v = find(p, row, col);
      if (v < 0) usable_ = false;
      index_.push_back(v);
    };
    add(lambda, lambda);
    for (int j = 0; j < 7 * n; ++j) add(lambda, column(j));
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 6; ++r) {
        const int row = l.body(plan.bodies[i]) + (r < 3 ? L::kV + r : L::kW + r - 3);
        for (int j = 0; j < 7 * n; ++j) add(row, column(j));
        add(row, lambda);
      }
    if (stabilised_) planStabilisation(p, k, plan);
    equations_.push_back(plan);
  }
}

void LocalNewtonMatrix::planStabilisation(const JacobianPattern& p, int equation,
                                          EquationPlan& plan) {
  const StateLayout& l = system_.layout();
  const int velocityRow = l.size() + equation;  // also eta's column
  const int n = plan.bodyCount;
  plan.stabilisedIndex = static_cast<int>(stabilisedIndex_.size());
  auto column = [&](int j) { return l.body(plan.bodies[j / 7]) + j % 7; };  // r then e
  auto add = [&](int row, int col) {
    const int v = find(p, row, col);
    if (v < 0) usable_ = false;
    stabilisedIndex_.push_back(v);
  };
  add(velocityRow, velocityRow);
  for (int j = 0; j < 7 * n; ++j) add(velocityRow, column(j));
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 6; ++r)
      add(velocityRow, l.body(plan.bodies[i]) + (r < 3 ? L::kV + r : L::kW + r - 3));
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 7; ++r) {
      const int row = l.body(plan.bodies[i]) + L::kR + r;  // r rows, then e rows
      for (int j = 0; j < 7 * n; ++j) add(row, column(j));
      add(row, velocityRow);
    }
}

template <class S>
void LocalNewtonMatrix::stabilisationChunk(const EquationPlan& plan, int slot, const S* out,
                                           int base, int last, bool first,
                                           double* values) const {
  const int n = plan.bodyCount, directions = 7 * n;
  const int* index = &stabilisedIndex_[static_cast<size_t>(plan.stabilisedIndex)];
  const int* velocityRow = index + 1;  // positions, then velocities
  const int* kinematicRows = index + 1 + directions + 6 * n;
  const int stride = directions + 1;
  const double* q = state_ + system_.layout().body(plan.bodies[slot]);
  const double u[6] = {q[L::kV], q[L::kV + 1], q[L::kV + 2],
                       q[L::kW], q[L::kW + 1], q[L::kW + 2]};
  // Velocity form C u: its position derivatives u . dC/dq, and C itself in the velocity columns.
  for (int j = base; j < last; ++j) {
    double sum = 0.0;
    for (int r = 0; r < 6; ++r) sum += u[r] * Seeds<S>::get(out[r], j - base);
    values[velocityRow[j]] += sum;
  }
  if (first)
    for (int r = 0; r < 6; ++r)
      values[velocityRow[directions + 6 * slot + r]] += Seeds<S>::value(out[r]);
  // r' = v - C_r^T eta: the kinematic row r - v + C_r^T eta.
  for (int r = 0; r < 3; ++r) {
    const int* row = kinematicRows + (7 * slot + r) * stride;
    for (int j = base; j < last; ++j) values[row[j]] += eta_ * Seeds<S>::get(out[r], j - base);
    if (first) values[row[directions]] += Seeds<S>::value(out[r]);
  }
  // e' = E(e) (w - C_pi^T eta) / 2 + mu e: the row gains E(e) C_pi^T eta / 2, which depends on
  // the body's own e as well (seeded where the chunk holds its directions).
  S e[4];
  for (int k = 0; k < 4; ++k) {
    e[k] = S(q[L::kE + k]);
    const int j = 7 * slot + 3 + k;
    if (j >= base && j < last) Seeds<S>::at(e[k], j - base) = 1.0;
  }
  const S* o = out + 3;
  const S g[4] = {-(e[1] * o[0]) - e[2] * o[1] - e[3] * o[2],
                  e[0] * o[0] - e[3] * o[1] + e[2] * o[2],
                  e[3] * o[0] + e[0] * o[1] - e[1] * o[2],
                  -(e[2] * o[0]) + e[1] * o[1] + e[0] * o[2]};
  for (int r = 0; r < 4; ++r) {
    const int* row = kinematicRows + (7 * slot + 3 + r) * stride;
    for (int j = base; j < last; ++j)
      values[row[j]] += 0.5 * eta_ * Seeds<S>::get(g[r], j - base);
    if (first) values[row[directions]] += 0.5 * Seeds<S>::value(g[r]);
  }
}

void LocalNewtonMatrix::planForceAndUser(const JacobianPattern& p) {
  forceAndUser_ = forceAndUserPattern(system_, p.contacts, forceSkip_);
  if (forceAndUser_.denseRows > 0) {
    usable_ = false;
    return;
  }
  const int n = forceAndUser_.size;
  std::vector<bool> written(static_cast<size_t>(n), false);
  forceAndUserIndex_.resize(forceAndUser_.rowIndex.size());
  for (int c = 0; c < n; ++c)
    for (int e = forceAndUser_.columnStart[c]; e < forceAndUser_.columnStart[c + 1]; ++e) {
      const int row = forceAndUser_.rowIndex[e];
      forceAndUserIndex_[e] = find(p, row, c);
      if (forceAndUserIndex_[e] < 0) usable_ = false;
      written[row] = true;
    }
  for (int r = 0; r < n; ++r)
    if (written[r]) forceAndUserRows_.push_back(r);
}

void LocalNewtonMatrix::bodyBlocks(const Eigen::VectorXd& y, double cj, double* values) const {
  const StateLayout& l = system_.layout();
  for (int b = 0; b < l.bodies; ++b) {
    const double* q = y.data() + l.body(b);
    double blk[L::kPerBody][L::kPerBody] = {};
    for (int c = 0; c < 3; ++c) {
      blk[L::kR + c][L::kR + c] = cj;
      blk[L::kR + c][L::kV + c] = -1.0;
    }
    // e' - E(e) w / 2 - mu e (multibody_system.hpp): its partials in e, w and mu.
    const double e0 = q[L::kE], e1 = q[L::kE + 1], e2 = q[L::kE + 2], e3 = q[L::kE + 3];
    const double w1 = q[L::kW], w2 = q[L::kW + 1], w3 = q[L::kW + 2], mu = q[L::kMu];
    const double dfde[4][4] = {{0.0, -w1, -w2, -w3},
                               {w1, 0.0, w3, -w2},
                               {w2, -w3, 0.0, w1},
                               {w3, w2, -w1, 0.0}};
    const double dfdw[4][3] = {{-e1, -e2, -e3}, {e0, -e3, e2}, {e3, e0, -e1}, {-e2, e1, e0}};
    const double e[4] = {e0, e1, e2, e3};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c)
        blk[L::kE + r][L::kE + c] = (r == c ? cj - mu : 0.0) - 0.5 * dfde[r][c];
      for (int c = 0; c < 3; ++c) blk[L::kE + r][L::kW + c] = -0.5 * dfdw[r][c];
      blk[L::kE + r][L::kMu] = -e[r];
      blk[L::kMu][L::kE + r] = 2.0 * e[r];
    }
    const double mass = system_.bodyMass(b);
    for (int c = 0; c < 3; ++c) blk[L::kV + c][L::kV + c] = mass * cj;
    // J w' + w x J w: cj J + [w]x J - [J w]x.
    const Eigen::Matrix3d& jm = system_.bodyInertia(b);
    const Eigen::Vector3d w(w1, w2, w3);
    const Eigen::Vector3d jw = jm * w;
    Eigen::Matrix3d skewW, skewJw;
    skewW << 0.0, -w3, w2, w3, 0.0, -w1, -w2, w1, 0.0;
    skewJw << 0.0, -jw(2), jw(1), jw(2), 0.0, -jw(0), -jw(1), jw(0), 0.0;
    const Eigen::Matrix3d dw = cj * jm + skewW * jm - skewJw;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) blk[L::kW + r][L::kW + c] = dw(r, c);
    const int* index = &bodyIndex_[static_cast<size_t>(kBodyEntries * b)];
    int k = 0;
    forEachBodyEntry([&](int r, int c) { values[index[k++]] += blk[r][c]; });
  }
}

void LocalNewtonMatrix::kinematics(const Eigen::VectorXd& y) {
  const StateLayout& l = system_.layout();
  origin_.resize(static_cast<size_t>(l.bodies));
  axes_.resize(static_cast<size_t>(l.bodies));
  axesDerivative_.resize(static_cast<size_t>(4 * l.bodies));
  using D = Dual<double>;
  for (int b = 0; b < l.bodies; ++b) {
    const double* q = y.data() + l.body(b);
    origin_[b] = {q[L::kR], q[L::kR + 1], q[L::kR + 2]};
    Quat<D> e{D(q[L::kE], 0.0), D(q[L::kE + 1], 0.0), D(q[L::kE + 2], 0.0),
              D(q[L::kE + 3], 0.0)};
    D* parts[4] = {&e.e0, &e.e1, &e.e2, &e.e3};
    for (int k = 0; k < 4; ++k) {
      parts[k]->d = 1.0;
      const M3<D> a = rotationOf(e);
      parts[k]->d = 0.0;
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
          axesDerivative_[4 * b + k].c[c][r] = a.c[c][r].d;
          if (k == 0) axes_[b].c[c][r] = a.c[c][r].v;
        }
    }
  }
}

namespace {

// True when MultibodySystem::analyticSideGradient of each side reads that side's own body's pose
// alone (Point: +-e_axis and (A^T (p - o)) x (A^T e_axis)): its derivatives along the other
// bodies are zero and are not computed (docs/performance.md, "The element-local Newton matrix,
// cheaper").
bool sideGradientReadsOwnBodyOnly(const ConstraintEquation& eq) {
  return eq.kind == ConstraintEquation::Kind::Point;
}

// A constant (zero-derivative) matrix times a constant vector, as M3<S>::from(a) *
// V3<S>::from(v) computes it, without the arithmetic on derivatives known to be zero
// (docs/performance.md, "The element-local Newton matrix, cheaper").
template <class S>
V3<S> timesConstant(const M3<S>& a, const V3<double>& v) {
  V3<S> r;
  for (int k = 0; k < 3; ++k) r[k] = v.x * a.c[0][k] + v.y * a.c[1][k] + v.z * a.c[2][k];
  return r;
}

}  // namespace

template <class S>
void LocalNewtonMatrix::buildSeeded(const ConstraintEquation& eq, const EquationPlan& plan,
                                    int base, V3<S>* origin, M3<S>* axes,
                                    Frame<S>* frames) const {
  const model::Model& m = system_.model();
  const int n = plan.bodyCount;
  const int last = std::min(7 * n, base + Seeds<S>::count);
  // The poses of the equation's bodies with the chunk's directions seeded: translations of
  // the origin, and the axes' derivatives along the Euler parameters.
  bool seeded[6] = {};
  for (int i = 0; i < n; ++i) {
    const int b = plan.bodies[i];
    origin[i] = V3<S>::from(origin_[b]);
    axes[i] = M3<S>::from(axes_[b]);
    for (int j = std::max(base, 7 * i); j < std::min(last, 7 * i + 7); ++j) {
      seeded[i] = true;
      const int q = j - 7 * i;
      if (q < 3) {
        Seeds<S>::at(origin[i][q], j - base) = 1.0;
      } else {
        const M3<double>& da = axesDerivative_[4 * b + q - 3];
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) Seeds<S>::at(axes[i].c[c][r], j - base) = da.c[c][r];
      }
    }
  }
  // Marker frames as the residual builds them (MultibodySystem::cachedFrame). The marker's
  // body-fixed position and orientation are constants, and a body none of whose directions
  // the chunk seeds gives a constant frame: both are multiplied in double and promoted, the
  // same numbers as the dual products (docs/performance.md, "The element-local Newton matrix,
  // cheaper").
  for (int side = 0; side < eq.markerCount(); ++side) {
    const model::Marker& mk = m.markers[eq.marker(side)];
    const V3<double> sb = V3<double>::from(mk.position);
    const M3<double> ab = M3<double>::from(mk.orientation);
    const int i = plan.slot[side];
    if (i < 0) {
      frames[side] = {V3<S>::from(sb), M3<S>::from(ab)};
    } else if (!seeded[i]) {
      const int b = plan.bodies[i];
      frames[side] = {V3<S>::from(origin_[b] + axes_[b] * sb), M3<S>::from(axes_[b] * ab)};
    } else {
      frames[side].p = origin[i] + timesConstant(axes[i], sb);
      for (int c = 0; c < 3; ++c) frames[side].a.c[c] = timesConstant(axes[i], ab.c[c]);
    }
  }
}

template <class S>
void LocalNewtonMatrix::equationChunk(const ConstraintEquation& eq, const EquationPlan& plan,
                                      int base, double lambda, double* values) {
  if constexpr (std::is_same_v<S, Multi>) {
    // The seeded poses and frames of this pass, reused from the previous equation when it read
    // the same markers (then its bodies, their order and the seeds are the same too); they live
    // in seeded_ so that nothing of the size of a multi-direction frame is zero-filled per
    // equation (docs/performance.md, "The element-local Newton matrix, cheaper").
    SeededFrames& cache = seeded_[base / kChunk];
    bool same = cache.markerCount == eq.markerCount() && cache.base == base;
    for (int side = 0; same && side < eq.markerCount(); ++side)
      same = cache.markers[side] == eq.marker(side);
    if (!same) {
      cache.markerCount = eq.markerCount();
      cache.base = base;
      for (int side = 0; side < eq.markerCount(); ++side) cache.markers[side] = eq.marker(side);
      buildSeeded(eq, plan, base, cache.origin, cache.axes, cache.frames);
      cache.armMask = 0;
    }
    equationRows(eq, plan, base, cache.origin, cache.axes, cache.frames, cache.arms,
                 &cache.armMask, lambda, values);
  } else {
    V3<S> origin[6];
    M3<S> axes[6];
    Frame<S> frames[ConstraintEquation::kMaxMarkers];
    buildSeeded(eq, plan, base, origin, axes, frames);
    equationRows<S>(eq, plan, base, origin, axes, frames, nullptr, nullptr, lambda, values);
  }
}

template <class S>
void LocalNewtonMatrix::equationRows(const ConstraintEquation& eq, const EquationPlan& plan,
                                     int base, const V3<S>* origin, const M3<S>* axes,
                                     const Frame<S>* frames, V3<S>* arms, int* armMask,
                                     double lambda, double* values) {
  constexpr int kCount = Seeds<S>::count;
  const int n = plan.bodyCount, directions = 7 * n;
  const int last = std::min(directions, base + kCount);
  const int* index = &index_[static_cast<size_t>(plan.index)];
  const int rowStride = directions + 1;
  const int* valueRow = index + 1;
  const int* forceRows = index + 1 + directions;
  S value;
  if constexpr (std::is_same_v<S, Dual<double>>)
    value = ConstraintSet::geometry(eq, frames);
  else
    value = MultibodySystem::analyticGeometry(eq, frames);
  for (int j = base; j < last; ++j) values[valueRow[j]] += Seeds<S>::get(value, j - base);
  // A side whose gradient reads its own body's pose only (Point) has no derivative along the
  // other bodies' directions: it is evaluated in the pass over its own body alone, and its
  // values (the multiplier's column) go in there; the others in the first pass
  // (docs/performance.md, "The element-local Newton matrix, cheaper").
  const bool ownOnly = sideGradientReadsOwnBodyOnly(eq);
  for (int side = 0; side < eq.markerCount(); ++side) {
    const int i = plan.slot[side];
    if (i < 0) continue;
    if (ownOnly && (7 * i + 7 <= base || last <= 7 * i)) continue;  // none of body i's
    const bool first = ownOnly ? base <= 7 * i && 7 * i < last : base == 0;
    S out[6];
    if constexpr (std::is_same_v<S, Dual<double>>) {
      MultibodySystem::sideGradient(eq, frames, side, origin[i], axes[i], out);
    } else if (arms != nullptr && eq.kind == ConstraintEquation::Kind::Point) {
      // MultibodySystem::analyticSideGradient's Point case (pointSideGradient) with the
      // arm A^T (p - o) computed once per joint side and pass instead of once per equation
      // (the three Point equations of a joint share it; docs/performance.md, "The
      // element-local Newton matrix, cheaper").
      if ((*armMask & (1 << side)) == 0) {
        arms[side] = axes[i].tmul(frames[side].p - origin[i]);
        *armMask |= 1 << side;
      }
      MultibodySystem::pointSideGradient(eq, side, arms[side], axes[i], out);
    } else {
      MultibodySystem::analyticSideGradient(eq, frames, side, origin[i], axes[i], out);
    }
    for (int r = 0; r < 6; ++r) {
      const int* row = forceRows + (6 * i + r) * rowStride;
      for (int j = base; j < last; ++j) values[row[j]] += lambda * Seeds<S>::get(out[r], j - base);
      // The multiplier's column: the gradient itself (once per side).
      if (first) values[row[directions]] += Seeds<S>::value(out[r]);
    }
    if (stabilised_) stabilisationChunk(plan, i, out, base, last, first, values);
  }
}

void LocalNewtonMatrix::assemble(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                 double cj, double* values, SparseJacobianWork& work) {
  const StateLayout& l = system_.layout();
  const int n = l.size();
  std::fill(values, values + nonZeros_, 0.0);
  bodyBlocks(y, cj, values);
  kinematics(y);
  for (SeededFrames& cache : seeded_) cache.markerCount = -1;  // a new state
  state_ = y.data();
  const auto& eqs = system_.constraints().equations();
  for (size_t k = 0; k < equations_.size(); ++k) {
    const ConstraintEquation& eq = eqs[k];
    const EquationPlan& plan = equations_[k];
    if (!eq.active) {
      values[index_[static_cast<size_t>(plan.index)]] += 1.0;  // row lambda_k = lambda_k
      if (stabilised_)  // and row eta_k = eta_k
        values[stabilisedIndex_[static_cast<size_t>(plan.stabilisedIndex)]] += 1.0;
      continue;
    }
    const double lambda = y(l.lambda(static_cast<int>(k)));
    if (stabilised_) eta_ = y(n + static_cast<int>(k));
    const int directions = 7 * plan.bodyCount;
    if (plan.bodyCount == 0) continue;  // between ground markers: a constant row
    if (MultibodySystem::hasAnalyticGradient(eq))
      for (int base = 0; base < directions; base += kChunk)
        equationChunk<Multi>(eq, plan, base, lambda, values);
    else
      for (int base = 0; base < directions; ++base)
        equationChunk<Dual<double>>(eq, plan, base, lambda, values);
  }
  // The state-local force elements one by one (local_newton_forces.cpp); the others and the
  // user equations by compressed forward AD of their rows alone (local_newton_colours.cpp).
  forceElementEntries(y, values);
  forceAndUserColours(t, y, yp, cj, values, work);
}

}  // namespace openmss::mechanics
