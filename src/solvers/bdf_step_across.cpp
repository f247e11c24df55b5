// BdfIntegrator's entry state for stepping across a singular instant (docs/integrators.md,
// "Stepping across a singular instant"): a multistep method goes back with its history, so
// everything an accepted step changes is saved and put back together.

#include "solvers/bdf_integrator.hpp"

namespace openmss::solvers {

void BdfIntegrator::saveEntry() {
  Resumable& e = entry_;
  e.t = t_;
  e.y = y_;
  e.yp = yp_;
  e.ts = ts_;
  e.ys = ys_;
  e.diagonal = diagonal_;
  e.h = h_;
  e.k = k_;
  e.stepsAtOrder = stepsAtOrder_;
  e.lastStepOrder = lastStepOrder_;
  e.lowOrderStep = lowOrderStep_;
  e.highOrderBarredUntil = highOrderBarredUntil_;
  e.stabilityBar = stabilityBar_;
  e.stepsSinceRoughSolve = stepsSinceRoughSolve_;
  e.lastSolveAtNoise = lastSolveAtNoise_;
  e.heldLow = heldLow_;
  e.heldOwn = heldOwn_;
  e.order = stats_.order;
  e.stepSize = stats_.stepSize;
}

void BdfIntegrator::restoreEntry() {
  const Resumable& e = entry_;
  t_ = e.t;
  y_ = e.y;
  yp_ = e.yp;
  ts_ = e.ts;
  ys_ = e.ys;
  diagonal_ = e.diagonal;
  h_ = e.h;
  k_ = e.k;
  stepsAtOrder_ = e.stepsAtOrder;
  lastStepOrder_ = e.lastStepOrder;
  lowOrderStep_ = e.lowOrderStep;
  highOrderBarredUntil_ = e.highOrderBarredUntil;
  stabilityBar_ = e.stabilityBar;
  stepsSinceRoughSolve_ = e.stepsSinceRoughSolve;
  lastSolveAtNoise_ = e.lastSolveAtNoise;
  heldLow_ = e.heldLow;
  heldOwn_ = e.heldOwn;
  stats_.order = e.order;
  stats_.stepSize = e.stepSize;
  stalledMove_ = false;
}

}  // namespace openmss::solvers
