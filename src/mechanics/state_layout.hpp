#pragma once
// Where each unknown of the equations of motion lives in the state vector y (docs/theory.md):
// per moving body 14 entries [r(3) e(4) v(3) w(3) mu], then one Lagrange multiplier per
// constraint equation. r is the CM position in ground, e the Euler parameters of the body
// frame, v the CM velocity in ground axes, w the angular velocity in body axes, mu the
// multiplier of the Euler-parameter normalisation.

namespace openmss::mechanics {

struct StateLayout {
  static constexpr int kPerBody = 14;
  static constexpr int kR = 0, kE = 3, kV = 7, kW = 10, kMu = 13;

  int bodies = 0;
  int constraintEquations = 0;

  int body(int b) const { return kPerBody * b; }
  int lambda(int k) const { return kPerBody * bodies + k; }
  int size() const { return kPerBody * bodies + constraintEquations; }
  // Unknowns whose time derivative appears in the equations (r, e, v, w).
  bool differential(int i) const { return i < kPerBody * bodies && (i % kPerBody) != kMu; }
  // Unknowns under integration-error control: displacements (r, e), as ADAMS's I3 does.
  bool displacement(int i) const { return i < kPerBody * bodies && (i % kPerBody) < kV; }
};

}  // namespace openmss::mechanics
