// The constraint rows of MultibodySystem::residual<double> on one thread: the serial loop of
// residual<T> (constraintRow in multibody_system.hpp) with the work that consecutive equations
// on the same two markers share done once. A joint's equations are consecutive and read the
// same I and J markers (a revolute's three Point and two Dot equations): their marker frames
// are fetched and copied once, their parts' bodies looked up once, and the arm A^T (p - o) of
// each side, which analyticSideGradient's Point case forms per equation, once per joint side
// (as the element-local Newton matrix does, docs/performance.md, "GSTIFF's cost per step,
// cheaper"). Every number is computed by the same operations on the same operands as in
// constraintRow, and the additions into g are made in the same order, so the residual is
// bit-identical to the generic loop.

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

void MultibodySystem::serialConstraintRows(double t, const double* y, double* g) const {
  using K = ConstraintEquation::Kind;
  const auto& eqs = constraints_.equations();
  KinematicsScratch<double>& kin = beginKinematics<double>();
  // The two-marker group of the last equation taken here: its markers, their frames, the
  // bodies carrying them (-1: ground) and the Point arms formed so far (bit s for side s).
  int groupI = -1, groupJ = -1;
  Frame<double> frames[2];
  int body[2] = {-1, -1};
  V3<double> arm[2];
  int armMask = 0;
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    const ConstraintEquation& eq = eqs[k];
    if (!eq.active || eq.markerCount() != 2 || !hasAnalyticGradient(eq)) {
      constraintRow(k, t, kin, y, g);
      continue;
    }
    if (eq.iMarker != groupI || eq.jMarker != groupJ) {
      groupI = eq.iMarker;
      groupJ = eq.jMarker;
      for (int side = 0; side < 2; ++side) {
        const int marker = eq.marker(side);
        frames[side] = cachedFrame(kin, marker, y);
        body[side] = model_->parts[model_->markers[marker].part].body;
        if (body[side] >= 0) cachedBody(kin, body[side], y);
      }
      armMask = 0;
    }
    // addConstraintForce with the group's frames and bodies.
    const double lambda = y[layout_.lambda(k)];
    for (int side = 0; side < 2; ++side) {
      const int b = body[side];
      if (b < 0) continue;
      const V3<double>& origin = kin.origin[b];
      const M3<double>& axes = kin.axes[b];
      double d[6];
      if (eq.kind == K::Point) {
        // analyticSideGradient's Point case with the joint side's arm.
        if ((armMask & (1 << side)) == 0) {
          arm[side] = axes.tmul(frames[side].p - origin);
          armMask |= 1 << side;
        }
        pointSideGradient(eq, side, arm[side], axes, d);
      } else {
        analyticSideGradient(eq, frames, side, origin, axes, d);
      }
      const int o = layout_.body(b);
      for (int dir = 0; dir < 3; ++dir) {
        g[o + StateLayout::kV + dir] = g[o + StateLayout::kV + dir] + d[dir] * lambda;
        g[o + StateLayout::kW + dir] = g[o + StateLayout::kW + dir] + d[3 + dir] * lambda;
      }
    }
    // constraintRow's value: ConstraintSet::geometry of these kinds is analyticGeometry.
    g[layout_.lambda(k)] = rowValue(k, t, analyticGeometry(eq, frames));
  }
}

}  // namespace openmss::mechanics
