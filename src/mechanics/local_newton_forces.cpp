// The state-local force elements' entries of the element-local Newton matrix
// (local_newton_matrix.hpp; docs/theory.md, "Element-local Newton matrix", item (iii)).
// A SPRINGDAMPER, BUSHING, FIELD or BEAM (without USER) loads the force and moment rows of its
// two bodies with a function of those bodies' r, e, v and w alone: one forward-AD pass of a
// 13 n-direction dual (n = 1 or 2 bodies) over the element gives all its entries, where the
// colour passes evaluated every element once per colour (docs/performance.md, "Force elements'
// Newton-matrix entries, element-local"). The loads do not read y', so the c_j columns get
// nothing from them.
//
// Each direction of a DualVec carries the same operations as a Dual<double> seeded along it
// (local_dual.hpp), and each entry is summed element by element in the residual's order starting
// from zero, as the colour pass summed its row: with only such elements, the matrix is the colour
// pass's to the bit.

#include <algorithm>

#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

// Directions per body: r (3), e (4), v (3), w (3), the state entries kR .. kW + 2; mu is not read.
constexpr int kBodyDirections = L::kMu;

template <class T>
MarkerState<T> markerOn(const model::Marker& mk, const BodyPose<T>* pose) {
  if (pose != nullptr) return markerStateOnBody(mk, *pose);
  // A ground marker, as markerState builds it.
  MarkerState<T> s;
  s.p = V3<T>::from(mk.position);
  s.a = M3<T>::from(mk.orientation);
  s.pdot = {T(0.0), T(0.0), T(0.0)};
  s.w = s.pdot;
  return s;
}

// A 13-direction dual placed at directions offset .. offset + 12 of an N-direction one.
template <int N>
DualVec<N> widen(const DualVec<kBodyDirections>& x, int offset) {
  DualVec<N> r(x.v);
  for (int k = 0; k < kBodyDirections; ++k) r.d[offset + k] = x.d[k];
  return r;
}
template <int N>
V3<DualVec<N>> widen(const V3<DualVec<kBodyDirections>>& x, int offset) {
  return {widen<N>(x.x, offset), widen<N>(x.y, offset), widen<N>(x.z, offset)};
}
template <int N>
M3<DualVec<N>> widen(const M3<DualVec<kBodyDirections>>& x, int offset) {
  return {{widen<N>(x.c[0], offset), widen<N>(x.c[1], offset), widen<N>(x.c[2], offset)}};
}

}  // namespace

void LocalNewtonMatrix::planForceElements(const JacobianPattern& p) {
  const StateLayout& l = system_.layout();
  const model::Model& m = system_.model();
  const ForceElements& fe = system_.forceElements();
  const auto& elements = fe.elements();
  std::vector<int> slotOf(static_cast<size_t>(nonZeros_), -1);
  for (int k = 0; k < static_cast<int>(elements.size()) && usable_; ++k) {
    const ForceElementRef& e = elements[k];
    if (!fe.isStateLocal(e)) continue;
    forceSkip_[k] = 1;
    ForcePlan plan;
    plan.element = k;
    const int bi = m.parts[m.markers[fe.iMarker(e)].part].body;
    const int bj = m.parts[m.markers[fe.jMarker(e)].part].body;
    for (int b : {bi, bj})
      if (b >= 0 &&
          std::find(plan.bodies, plan.bodies + plan.bodyCount, b) == plan.bodies + plan.bodyCount)
        plan.bodies[plan.bodyCount++] = b;
    if (plan.bodyCount == 0) continue;  // between ground markers: no entries
    auto slotOfBody = [&](int b) { return b < 0 ? -1 : (b == plan.bodies[0] ? 0 : 1); };
    plan.slotI = slotOfBody(bi);
    plan.slotJ = slotOfBody(bj);
    plan.index = static_cast<int>(forceSlot_.size());
    const int n = plan.bodyCount;
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 6; ++r) {
        const int row = l.body(plan.bodies[i]) + (r < 3 ? L::kV + r : L::kW + r - 3);
        for (int j = 0; j < kBodyDirections * n; ++j) {
          const int column = l.body(plan.bodies[j / kBodyDirections]) + j % kBodyDirections;
          const int v = find(p, row, column);
          if (v < 0) {
            usable_ = false;
            return;
          }
          if (slotOf[v] < 0) {
            slotOf[v] = static_cast<int>(forceSlots_.size());
            forceSlots_.push_back(v);
          }
          forceSlot_.push_back(slotOf[v]);
        }
      }
    forcePlans_.push_back(plan);
  }
  forceSum_.assign(forceSlots_.size(), 0.0);
}

template <int N>
void LocalNewtonMatrix::forceElementPass(const ForcePlan& plan, const Eigen::VectorXd& y) {
  using S = DualVec<N>;
  const StateLayout& l = system_.layout();
  const model::Model& m = system_.model();
  const ForceElements& fe = system_.forceElements();
  const ForceElementRef e = fe.elements()[static_cast<size_t>(plan.element)];
  constexpr int n = N / kBodyDirections;
  // Each body's pose and marker state on its own 13 directions (bodyPose on the body's 14
  // entries), then widened to the element's 13 n: half the work of forming them on all 13 n
  // (docs/performance.md, "Force elements' Newton-matrix entries, element-local").
  using B = DualVec<kBodyDirections>;
  BodyPose<S> pose[n];
  const int markers[2] = {fe.iMarker(e), fe.jMarker(e)};
  const int slots[2] = {plan.slotI, plan.slotJ};
  MarkerState<S> state[2];
  for (int i = 0; i < n; ++i) {
    const double* q = y.data() + l.body(plan.bodies[i]);
    B local[L::kPerBody];
    for (int j = 0; j < L::kPerBody; ++j) local[j] = B(q[j]);
    for (int j = 0; j < kBodyDirections; ++j) local[j].d[j] = 1.0;
    const BodyPose<B> own = bodyPose(StateLayout{}, 0, local);
    const int offset = kBodyDirections * i;
    pose[i] = {widen<N>(own.r, offset), widen<N>(own.a, offset), widen<N>(own.v, offset),
               widen<N>(own.wg, offset)};
    for (int side = 0; side < 2; ++side)
      if (slots[side] == i) {
        const MarkerState<B> ms = markerStateOnBody(m.markers[markers[side]], own);
        state[side] = {widen<N>(ms.p, offset), widen<N>(ms.a, offset), widen<N>(ms.pdot, offset),
                       widen<N>(ms.w, offset)};
      }
  }
  for (int side = 0; side < 2; ++side)
    if (slots[side] < 0) state[side] = markerOn<S>(m.markers[markers[side]], nullptr);
  const MarkerState<S>& mi = state[0];
  const MarkerState<S>& mj = state[1];
  const ElementLoads<S> loads = fe.stateLocalLoads(e, mi, mj);
  // The rows' sums so far, in the derivative parts: the element subtracts its loads from them
  // as ForceElements::addToResidual does from the residual's rows.
  const int* slot = &forceSlot_[static_cast<size_t>(plan.index)];
  S g[n][6];
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 6; ++r)
      for (int j = 0; j < N; ++j) g[i][r].d[j] = forceSum_[slot[(6 * i + r) * N + j]];
  if (plan.slotI >= 0)
    ForceElements::applyLoad(pose[plan.slotI], mi.p, loads.force, loads.torque, loads.hasForce,
                             loads.hasTorque, g[plan.slotI], g[plan.slotI] + 3);
  if (loads.reactionMarker >= 0 && plan.slotJ >= 0)
    ForceElements::applyLoad(pose[plan.slotJ], loads.reactionPoint, loads.reactionForce,
                             loads.reactionTorque, loads.hasForce, loads.hasTorque, g[plan.slotJ],
                             g[plan.slotJ] + 3);
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 6; ++r)
      for (int j = 0; j < N; ++j) forceSum_[slot[(6 * i + r) * N + j]] = g[i][r].d[j];
}

void LocalNewtonMatrix::forceElementEntries(const Eigen::VectorXd& y, double* values) {
  if (forcePlans_.empty()) return;
  std::fill(forceSum_.begin(), forceSum_.end(), 0.0);
  for (const ForcePlan& plan : forcePlans_) {
    if (plan.bodyCount == 1)
      forceElementPass<kBodyDirections>(plan, y);
    else
      forceElementPass<2 * kBodyDirections>(plan, y);
  }
  for (size_t s = 0; s < forceSlots_.size(); ++s) values[forceSlots_[s]] += forceSum_[s];
}

}  // namespace openmss::mechanics
