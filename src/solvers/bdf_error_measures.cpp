// BdfIntegrator's measures of error and change (docs/integrators.md): the weighted norms and
// weights of the error and convergence tests, the round-off floor of a corrector change, the
// noise widening of a stalled solve's error test, the order-selection estimates from the
// divided differences, the step and order after a displacement error-test failure, and the worst
// equation and unknown for failure reports. Moved out of bdf_integrator.cpp unchanged (file
// length).

#include <algorithm>
#include <cmath>
#include <utility>

#include "solvers/bdf_integrator.hpp"

namespace openmss::solvers {
namespace {

// A corrector that stops contracting with every change below this many ulps of the unknown's
// own round-off has converged: positions eps (1 + |y|), velocities cj eps (1 + max(|y|,
// |q|max)) (an index-3 velocity is recovered from positions through cj, so it carries their
// round-off: |q|max is the largest position of the current iterate; with the velocity's own |y|
// alone the 10,000-link chain, 10 km from its pivot, stalled just above the floor and failed at
// ERROR = 1e-6, docs/performance.md). At ERROR = 1e-10 and steps of 1e-8 s (the KUKA arm data
// sets of the corpus) that floor lies above the stalled-change rule's share of the tolerance.
constexpr double kRoundOffUlps = 1000.0;

}  // namespace

double BdfIntegrator::weightedNorm(const Eigen::VectorXd& v, const Eigen::VectorXd& w) {
  // The maximum (not a root-mean-square) so that one coordinate's error is not diluted by the
  // many that are at rest. PropagateNaN: a NaN anywhere fails the test (a plain maximum would
  // skip it).
  return v.cwiseProduct(w).cwiseAbs().maxCoeff<Eigen::PropagateNaN>();
}

bool BdfIntegrator::withinRoundOff(double cj) {
  constexpr double kEps = 2.220446049250313e-16;
  const double largestPosition = (yNew_.array().abs() * positionMask_.array()).maxCoeff();
  // One expression into the member: no temporary vector per corrector iteration.
  roundOffFloor_ = (kRoundOffUlps * kEps) *
                   (1.0 + yNew_.array().abs().max(largestPosition * velocityMask_.array())) *
                   (1.0 + (std::max(1.0, cj) - 1.0) * velocityMask_.array());
  return ((dy_.array().abs() - roundOffFloor_.array()) * differentialMask_.array()).maxCoeff() <=
         0.0;
}

void BdfIntegrator::setWeights() {
  // Weights from the last accepted solution, once per attempt: |v_i| / (ERROR (1 + |y_i|)),
  // relative for large values, absolute for small ones.
  errorWeight_ = (settings_.error * (1.0 + y_.array().abs())).inverse().matrix();
  // The corrector's convergence test counts every differential unknown, velocities included,
  // at full weight: a velocity left unconverged is a perturbation of the state that the
  // displacements integrate over the rest of the run (weighting velocities by 1/cj, their
  // effect within one step, flipped the 5 s spherical validation pendulum with WSTIFF).
  correctorWeight_ = errorWeight_.cwiseProduct(differentialMask_);
  errorWeight_.array() *= errorMask_.array();
  // CORRECTOR=MODIFIED: converged when the unknowns of the error test are (ADAMS's definition).
  if (settings_.modifiedCorrector) correctorWeight_ = errorWeight_;
}

void BdfIntegrator::noteWorst(const Eigen::VectorXd& g, const Eigen::VectorXd& dy) {
  // A NaN or infinite entry is the worst of all (comparisons alone would skip it).
  auto worse = [](double candidate, double current) {
    return !std::isfinite(candidate) ? std::isfinite(current) : candidate > current;
  };
  lastWorstEq_ = -1;
  lastWorstVar_ = -1;
  lastWorstRes_ = 0.0;
  lastWorstChange_ = 0.0;
  for (int i = 0; i < g.size(); ++i) {
    if (worse(std::abs(g(i)), lastWorstRes_)) {
      lastWorstRes_ = std::abs(g(i));
      lastWorstEq_ = i;
    }
    if (differentialMask_(i) != 0.0 && worse(std::abs(dy(i)), lastWorstChange_)) {
      lastWorstChange_ = std::abs(dy(i));
      lastWorstVar_ = i;
    }
  }
}

void BdfIntegrator::widenForNoise() {
  // errorWeight_ is 1 / (ERROR (1 + |y_n|)) masked (setWeights); the level of each role in
  // that weight, then each unknown's weight 1 / (1 / w + level / w) = w / (1 + level).
  double level[4] = {0.0, 0.0, 0.0, 0.0};  // per DaeProblem::Role
  for (Eigen::Index i = 0; i < laterChanges_.size(); ++i) {
    if (differentialMask_(i) == 0.0) continue;
    const int r = static_cast<int>(problem_.role(static_cast<int>(i)));
    level[r] = std::max(level[r], laterChanges_(i) * errorWeight_(i));
  }
  for (Eigen::Index i = 0; i < errorWeight_.size(); ++i)
    if (differentialMask_(i) != 0.0)
      errorWeight_(i) /= 1.0 + level[static_cast<int>(problem_.role(static_cast<int>(i)))];
}

double BdfIntegrator::orderErrorEstimate(int q, double h) const {
  // Local error of order q at step h from the (q+1)-th divided difference of the last q+2
  // solutions: LTE ~ q! h^(q+1) |y[q+2 points]|. Needs q+2 history points.
  if (static_cast<int>(diagonal_.size()) < q + 2) return -1.0;
  double fact = 1.0;
  for (int m = 2; m <= q; ++m) fact *= m;
  return fact * std::pow(h, q + 1) *
         weightedNorm(diagonal_[static_cast<size_t>(q + 1)], errorWeight_);
}

void BdfIntegrator::updateDivided() {
  // y[t_n..t_n-l] = (y[t_n..t_n-l+1] - y[t_n-1..t_n-l]) / (t_n - t_n-l): the last factor is
  // the previous step's diagonal at level l-1. The same operations, in the same order, as the
  // full table, so the estimates are unchanged to the last bit.
  const int levels = std::min(static_cast<int>(ts_.size()), settings_.kmax + 3);
  std::swap(diagonal_, previousDiagonal_);
  diagonal_.resize(static_cast<size_t>(levels));
  diagonal_[0] = ys_[0];
  for (int l = 1; l < levels; ++l) {
    const size_t u = static_cast<size_t>(l);
    diagonal_[u] = (diagonal_[u - 1] - previousDiagonal_[u - 1]) / (ts_[0] - ts_[u]);
  }
}

// The displacement error test failed: the next step and order (moved out of step(), then out of
// bdf_integrator.cpp, unchanged).
void BdfIntegrator::rejectOnDisplacement(double h, double err) {
  ++consecutiveErrorFailures_;
  double ratio = std::clamp(0.9 * std::pow(1.0 / err, 1.0 / (k_ + 1)), 0.2, 0.9);
  if (k_ > 1) {
    // Drop the order when the lower one promises the longer step (its error estimate
    // from the accepted history), or when the error test keeps failing at this order.
    const double eLow = orderErrorEstimate(k_ - 1, h);
    const double rLow = eLow > 0 ? 0.9 * std::pow(1.0 / eLow, 1.0 / k_) : 0.0;
    if (rLow > ratio || consecutiveErrorFailures_ >= 2) {
      k_ = k_ - 1;
      stepsAtOrder_ = 0;
      if (rLow > ratio) ratio = std::min(rLow, 0.9);
    }
  }
  h_ = h * ratio;
}

}  // namespace openmss::solvers
