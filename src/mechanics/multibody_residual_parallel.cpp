// The constraint rows of MultibodySystem::residual<double> on the thread pool
// (common/parallel_for.hpp; docs/architecture.md, "Threads"). Phase 1 runs per equation, in
// parallel: the marker frames, the geometry and, per marker side, the products
// d(geometry)/d(virtual displacement) * lambda, each into the equation's own slot. Phase 2 runs
// on the calling thread in equation order and makes exactly the additions of the serial loop
// (residual<T> in multibody_system.hpp), in the same order on every entry of g, with the same
// operands (-ffp-contract=off keeps a product and its sum separate roundings in both): the
// residual is bit-identical to the serial one for any thread count.

#include <algorithm>
#include <limits>

#include "common/parallel_for.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

// Off for every model size: measured on two cores, two threads made the chains slower than one
// (100-link planar chain, 500 equations: 1.19 s against 0.78 s; 1000-link spatial chain:
// 2.06 s against 1.75 s; docs/performance.md, "Re-measured after GSTIFF's I3 velocity test").
// The hand-off and the serial second phase cost more than the rows save. The path stays, bit-
// identical to the serial loop, for the next measurement; lower this bound only where one
// shows a gain.
constexpr size_t kParallelEquations = std::numeric_limits<size_t>::max();

// Kinds whose geometry and gradient read only the marker frames and the equation's own
// constants. Coupled (run-state turn counts), General (GCON expressions: shared scratch) and
// PointCurve (curve search) stay on the serial loop. Motions are in: their targets
// (motionJet, a shared cache) are taken in phase 2, on the calling thread.
bool pureKind(ConstraintEquation::Kind kind) {
  using K = ConstraintEquation::Kind;
  switch (kind) {
    case K::Point:
    case K::Dot:
    case K::Along:
    case K::MotionRotation:
    case K::MotionTranslation:
    case K::MotionAngle:
    case K::Convel:
    case K::RackPin:
    case K::Screw:
      return true;
    default:
      return false;
  }
}

// One equation's phase-1 results.
struct RowSlot {
  double value = 0.0;                                // geometry (motion target not yet taken)
  int body[ConstraintEquation::kMaxMarkers];         // per side, -1 for ground
  double force[ConstraintEquation::kMaxMarkers][6];  // d[dir] * lambda per side
};

}  // namespace

bool MultibodySystem::parallelConstraintRows(double t, const double* y, double* g) const {
  const auto& eqs = constraints_.equations();
  if (eqs.size() < kParallelEquations || threadCount() <= 1) return false;
  for (const ConstraintEquation& eq : eqs)
    if (eq.active && !pureKind(eq.kind)) return false;
  // The calling thread's slots: nothing allocated after the first call, and re-entrant.
  thread_local std::vector<RowSlot> callerSlots;
  // A named reference: a lambda naming a thread_local directly would reach the worker's own.
  std::vector<RowSlot>& slots = callerSlots;
  slots.resize(eqs.size());
  parallelFor(static_cast<int>(eqs.size()), [&](int, int begin, int end) {
    KinematicsScratch<double>& kin = beginKinematics<double>();  // this thread's
    for (int k = begin; k < end; ++k) {
      const ConstraintEquation& eq = eqs[k];
      if (!eq.active) continue;
      RowSlot& slot = slots[static_cast<size_t>(k)];
      const double lambda = y[layout_.lambda(k)];
      Frame<double> frames[ConstraintEquation::kMaxMarkers];
      for (int s = 0; s < eq.markerCount(); ++s) frames[s] = cachedFrame(kin, eq.marker(s), y);
      // As addConstraintForce, side by side.
      for (int side = 0; side < eq.markerCount(); ++side) {
        const int body = model_->parts[model_->markers[eq.marker(side)].part].body;
        slot.body[side] = body;
        if (body < 0) continue;
        cachedBody(kin, body, y);
        double d[6];
        sideGradient(eq, frames, side, kin.origin[body], kin.axes[body], d);
        for (int dir = 0; dir < 6; ++dir) slot.force[side][dir] = d[dir] * lambda;
      }
      slot.value = ConstraintSet::geometry(eq, frames);
    }
  });
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    const ConstraintEquation& eq = eqs[k];
    double& row = g[layout_.lambda(k)];
    if (!eq.active) {
      row = y[layout_.lambda(k)];
      continue;
    }
    const RowSlot& slot = slots[static_cast<size_t>(k)];
    for (int side = 0; side < eq.markerCount(); ++side) {
      if (slot.body[side] < 0) continue;
      const int o = layout_.body(slot.body[side]);
      for (int dir = 0; dir < 3; ++dir) {
        g[o + StateLayout::kV + dir] = g[o + StateLayout::kV + dir] + slot.force[side][dir];
        g[o + StateLayout::kW + dir] = g[o + StateLayout::kW + dir] + slot.force[side][3 + dir];
      }
    }
    double value = slot.value;
    if (eq.motion >= 0) {
      const double target = motionJet(k, t).value;
      value = value - target;
      if (ConstraintSet::wrapsAngle(eq)) value = value - wrapDelta(value + target, target);
    }
    row = value;
  }
  return true;
}

}  // namespace openmss::mechanics
