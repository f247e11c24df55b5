// The state-local force elements' entries of the element-local Newton matrix
// (local_newton_matrix.hpp; docs/theory.md, "Element-local Newton matrix", item (iii)).
// A SPRINGDAMPER, BUSHING, FIELD or BEAM (without USER) loads the force and moment rows of its
// two bodies with a function of those bodies' r, e, v and w alone: one forward-AD pass of a
// 13 n-direction dual (n = 1 or 2 bodies) over the element gives all its entries, where the
// colour passes evaluated every element once per colour (docs/performance.md, "Force elements'
// Newton-matrix entries, element-local"). The loads do not read y', so the c_j columns get
// nothing from them.
//
// The passes are independent, so above kParallelForceElements they run on the thread pool
// (common/parallel_for.hpp; docs/architecture.md, "Threads"): each element writes its terms into
// its own slots of forceTerms_, and one serial loop then adds them up in element order. Its terms
// are kept one per subtraction the residual makes (the force, the force's moment and the torque,
// per marker side), not summed within the element: a moment row receives two terms from a BUSHING
// or FIELD, and s - a - b is not s + (-a - b) in floating point. Adding 0 - a is adding -a, which
// IEEE makes subtracting a, and a sum that starts at +0 and only has numbers subtracted from it
// never becomes -0: the sums are the running subtraction's to the bit, for any thread count and
// with the pool or without.
//
// Each direction of a DualVec carries the same operations as a Dual<double> seeded along it
// (local_dual.hpp), and each entry is summed element by element in the residual's order starting
// from zero, as the colour pass summed its row: with only such elements, the matrix is the colour
// pass's to the bit.

#include <algorithm>

#include "common/parallel_for.hpp"
#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/multibody_system.hpp"
#include "mechanics/pose.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

// Directions per body: r (3), e (4), v (3), w (3), the state entries kR .. kW + 2; mu is not read.
constexpr int kBodyDirections = L::kMu;

// Below this many state-local force elements their passes stay on the calling thread: waking a
// worker (tens of microseconds) costs more than sharing out a few ~10 us passes saves. An
// estimate, the colour passes' value: the second core was never free to measure it
// (docs/performance.md, "Force elements' Newton-matrix entries on two threads").
constexpr size_t kParallelForceElements = 32;

// Per marker side the terms of its three subtractions (ForceElements::applyLoad): the force from
// the force rows, its moment and the torque from the moment rows, 3 rows each.
constexpr int kSideTerms = 9;
// Which of them a side wrote (forceTermsWritten_).
constexpr char kForceTerms = 1, kTorqueTerm = 2;

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
  size_t termCount = 0;
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
    plan.terms = termCount;
    const int n = plan.bodyCount;
    termCount += (plan.slotI >= 0 ? 1 : 0) * kSideTerms * kBodyDirections * n +
                 (plan.slotJ >= 0 ? 1 : 0) * kSideTerms * kBodyDirections * n;
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
  forceTerms_.assign(termCount, 0.0);
  forceTermsWritten_.assign(2 * forcePlans_.size(), 0);
  parallelForces_ = forcePlans_.size() >= kParallelForceElements;
}

template <int N>
void LocalNewtonMatrix::forceElementPass(const ForcePlan& plan, const Eigen::VectorXd& y,
                                         double* out, char* written) const {
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
    if (slots[side] < 0) state[side] = groundMarkerState<S>(m.markers[markers[side]]);
  const MarkerState<S>& mi = state[0];
  const MarkerState<S>& mj = state[1];
  const ElementLoads<S> loads = fe.stateLocalLoads(e, mi, mj);
  // Each subtraction applyLoad makes, on rows of its own starting from zero (0 - a is -a), in
  // the order it makes them: I's side, then J's. `written` tells the reduction which it made
  // (kForceTerms: the force and its moment; kTorqueTerm: the torque); the others are left out,
  // as the residual leaves them out.
  auto side = [&](int which, const BodyPose<S>& body, const V3<S>& point, const V3<S>& force,
                  const V3<S>& torque, bool applied) {
    const char parts = static_cast<char>(
        applied ? (loads.hasForce ? kForceTerms : 0) | (loads.hasTorque ? kTorqueTerm : 0) : 0);
    written[which] = parts;
    auto store = [&](const S* rows, double* to) {
      for (int r = 0; r < 3; ++r) std::copy(rows[r].d, rows[r].d + N, to + r * N);
    };
    if ((parts & kForceTerms) != 0) {
      S v[3], w[3];
      ForceElements::applyLoad(body, point, force, torque, true, false, v, w);
      store(v, out);
      store(w, out + 3 * N);
    }
    if ((parts & kTorqueTerm) != 0) {
      S unused[3], t[3];
      ForceElements::applyLoad(body, point, force, torque, false, true, unused, t);
      store(t, out + 6 * N);
    }
    out += kSideTerms * N;
  };
  if (plan.slotI >= 0) side(0, pose[plan.slotI], mi.p, loads.force, loads.torque, true);
  if (plan.slotJ >= 0)
    side(1, pose[plan.slotJ], loads.reactionPoint, loads.reactionForce, loads.reactionTorque,
         loads.reactionMarker >= 0);
}

void LocalNewtonMatrix::forceElementEntries(const Eigen::VectorXd& y, double* values) {
  if (forcePlans_.empty()) return;
  double* terms = forceTerms_.data();
  char* written = forceTermsWritten_.data();
  auto passes = [&](int, int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const ForcePlan& plan = forcePlans_[static_cast<size_t>(k)];
      if (plan.bodyCount == 1)
        forceElementPass<kBodyDirections>(plan, y, terms + plan.terms, written + 2 * k);
      else
        forceElementPass<2 * kBodyDirections>(plan, y, terms + plan.terms, written + 2 * k);
    }
  };
  const int count = static_cast<int>(forcePlans_.size());
  if (parallelForces_)
    parallelFor(count, passes);
  else
    passes(0, 0, count);
  // The reduction, on this thread in element order whatever ran the passes: per element its
  // sides' force terms into the force rows, then the force's moment and the torque into the
  // moment rows, as ForceElements::addToResidual subtracts them (the terms a side did not
  // write are ones the residual does not subtract).
  std::fill(forceSum_.begin(), forceSum_.end(), 0.0);
  const double* term = forceTerms_.data();
  const char* parts = forceTermsWritten_.data();
  for (const ForcePlan& plan : forcePlans_) {
    const int directions = kBodyDirections * plan.bodyCount;
    const int* slot = &forceSlot_[static_cast<size_t>(plan.index)];
    auto add = [&](int body, int rows, const double* from) {
      for (int r = 0; r < 3; ++r, from += directions) {
        const int* row = slot + (6 * body + rows + r) * directions;
        for (int j = 0; j < directions; ++j) forceSum_[row[j]] += from[j];
      }
    };
    for (int which = 0; which < 2; ++which, ++parts) {
      const int body = which == 0 ? plan.slotI : plan.slotJ;
      if (body < 0) continue;
      if ((*parts & kForceTerms) != 0) {
        add(body, 0, term);                   // the force, into the force rows
        add(body, 3, term + 3 * directions);  // its moment, into the moment rows
      }
      if ((*parts & kTorqueTerm) != 0) add(body, 3, term + 6 * directions);
      term += kSideTerms * directions;
    }
  }
  for (size_t s = 0; s < forceSlots_.size(); ++s) values[forceSlots_[s]] += forceSum_[s];
}

}  // namespace openmss::mechanics
