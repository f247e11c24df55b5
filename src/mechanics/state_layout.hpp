#pragma once
// Where each unknown of the equations of motion lives in the state vector y (docs/theory.md):
// per moving body 14 entries [r(3) e(4) v(3) w(3) mu], then the user states (docs/theory.md
// §4a): the differential ones (DIFF states, LSE/TFSISO states) and the algebraic ones
// (VARIABLE values, DIFF derivatives), then one Lagrange multiplier per constraint equation.
// r is the CM position in ground, e the Euler parameters of the body frame, v the CM velocity
// in ground axes, w the angular velocity in body axes, mu the multiplier of the
// Euler-parameter normalisation.

namespace openmss::mechanics {

struct StateLayout {
  static constexpr int kPerBody = 14;
  static constexpr int kR = 0, kE = 3, kV = 7, kW = 10, kMu = 13;

  int bodies = 0;
  int userDifferential = 0;  // DIFF states, then LSE/TFSISO states
  int userAlgebraic = 0;     // VARIABLE values, then DIFF derivatives
  int constraintEquations = 0;

  int body(int b) const { return kPerBody * b; }
  int userStates() const { return kPerBody * bodies; }
  int userDiff(int k) const { return kPerBody * bodies + k; }
  int userAlg(int k) const { return kPerBody * bodies + userDifferential + k; }
  int lambda(int k) const { return kPerBody * bodies + userDifferential + userAlgebraic + k; }
  int size() const { return lambda(constraintEquations); }
  bool isUserDifferential(int i) const {
    return i >= userDiff(0) && i < userDiff(userDifferential);
  }
  bool isUser(int i) const { return i >= userDiff(0) && i < lambda(0); }
  // Unknowns whose time derivative appears in the equations (r, e, v, w, user states).
  bool differential(int i) const {
    return (i < kPerBody * bodies && (i % kPerBody) != kMu) || isUserDifferential(i);
  }
  // Unknowns under integration-error control: displacements (r, e), as ADAMS's I3 does, and
  // the user differential states (ADAMS controls DIFF states too).
  bool displacement(int i) const {
    return (i < kPerBody * bodies && (i % kPerBody) < kV) || isUserDifferential(i);
  }
};

}  // namespace openmss::mechanics
