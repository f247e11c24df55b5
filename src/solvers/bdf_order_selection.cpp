// BdfIntegrator's choice of the next order and step after an accepted step (docs/integrators.md,
// "Order selection"): the error estimates of orders k-1, k and k+1, the stability-limit
// detection for orders >= 3, and the I3 velocity test's bound. Moved out of step() unchanged
// (file and function length).

#include <algorithm>
#include <cmath>

#include "solvers/bdf_integrator.hpp"

namespace openmss::solvers {
namespace {

// Stability-limit detection (selectNextStep): an order >= 3 whose step falls below this
// share of the last order-2 step is abandoned for order 2 for kFirstStabilityBar steps, twice
// as many at every further detection.
constexpr double kStabilityShrink = 0.7;
constexpr long kFirstStabilityBar = 50;
// ... or, at orders 3 and 4 (kGrowthTopOrder), whose estimates of orders k-1 and k both grow
// by more than kGrowthFactor over kGrowthWindow steps at one step size and order, at rates
// within kGrowthAgreement of each other: one mode growing geometrically behind both (even
// window: a mode near h*omega = pi alternates in sign from step to step). Measured on the
// 100-link planar chain (docs/integrators.md): a window of 8 and a factor of 1.5 caught the
// growth too late at ERROR = 1e-4; the test at orders 5-6 as well cost 100x in tip error at
// 1e-6, where those orders damp the resolved modes and the estimates grow with the physics.
constexpr int kGrowthWindow = 6;
constexpr double kGrowthFactor = 1.25;
constexpr int kGrowthTopOrder = 4;
constexpr double kGrowthAgreement = 1.3;

}  // namespace

void BdfIntegrator::selectNextStep(double h, double err) {
  // Next order and step: compare the error estimates of orders k-1, k, k+1.
  double ratio = 0.9 * std::pow(1.0 / std::max(err, 1e-10), 1.0 / (k_ + 1));
  const double ownRatio = ratio;
  int nextK = k_;
  if (stepsAtOrder_ > k_ + 1) {
    const double eLow = k_ > 1 ? orderErrorEstimate(k_ - 1, h) : -1.0;
    const double eHigh = k_ < settings_.kmax ? orderErrorEstimate(k_ + 1, h) : -1.0;
    const double rLow = eLow > 0 ? 0.9 * std::pow(1.0 / eLow, 1.0 / k_) : 0.0;
    const double rHigh = eHigh > 0 ? 0.9 * std::pow(1.0 / eHigh, 1.0 / (k_ + 2)) : 0.0;
    const double capped = settings_.hmax / h;  // ratios above this cannot lengthen the step
    if (ratio >= capped && (rLow >= capped || rLow == 0.0) && (rHigh >= capped || rHigh == 0.0)) {
      // The step is held at HMAX whatever the order: take the order with the smallest error.
      double eNow = std::max(err, 1e-300);
      if (eHigh > 0 && eHigh < eNow) {
        nextK = k_ + 1;
        ratio = rHigh;
      } else if (eLow > 0 && eLow < 0.5 * eNow) {
        nextK = k_ - 1;
        ratio = rLow;
      }
    } else if (rLow > ratio && rLow >= rHigh) {
      nextK = k_ - 1;
      ratio = rLow;
    } else if (rHigh > 1.1 * ratio) {
      nextK = k_ + 1;
      ratio = rHigh;
    }
  } else if (static_cast<int>(ts_.size()) >= 2 && k_ == 1 && stepsAtOrder_ >= 2 &&
             settings_.kmax > 1) {
    // Leave the start-up order as soon as history allows.
    nextK = 2;
  }
  // Stability limit of orders >= 3 (docs/integrators.md, "Order selection"). On an undamped
  // mode BDF3 and BDF4 grow the amplitude at every step, BDF5 and BDF6 in a band of h*omega
  // around 1-3; only orders 1-2 damp every such mode. A mode the error test had left below
  // the tolerance then grows until it holds the step, which shrinks step after step while
  // the solution itself does not change character. Detected early as the growth of the
  // order k-1 and k estimates at a held step (orders 3-4, kGrowthWindow), late as the step of
  // an order >= 3 falling below kStabilityShrink of the last one order 2 took: the order
  // drops to 2 (which damps the mode) and stays there for a bar that doubles at every
  // detection, so that a
  // model whose higher orders pay gets them back and one that keeps failing at them stops
  // paying for retries.
  const bool shortened = h < std::min(h_, settings_.hmax);  // landed on an output time
  bool stabilityJump = false;
  bool modeGrowing = false;
  if (k_ >= 3 && k_ <= kGrowthTopOrder && !shortened && stepsAtOrder_ > 1 && h == stats_.stepSize) {
    heldLow_.push_back(orderErrorEstimate(k_ - 1, h));
    heldOwn_.push_back(orderErrorEstimate(k_, h));
    if (static_cast<int>(heldOwn_.size()) > kGrowthWindow + 1) {
      heldLow_.pop_front();
      heldOwn_.pop_front();
    }
    if (static_cast<int>(heldOwn_.size()) == kGrowthWindow + 1 && heldLow_.front() > 0 &&
        heldOwn_.front() > 0) {
      const double gLow = heldLow_.back() / heldLow_.front();
      const double gOwn = heldOwn_.back() / heldOwn_.front();
      modeGrowing = gLow > kGrowthFactor && gOwn > kGrowthFactor &&
                    std::max(gLow, gOwn) < kGrowthAgreement * std::min(gLow, gOwn);
    }
  } else {
    heldLow_.clear();
    heldOwn_.clear();
  }
  // A corrector failure quarters the step whatever the error test says, and a solve accepted
  // at its noise (A02's flat passages) leaves that noise in the divided differences of the
  // next k + 1 steps, whose predictors extrapolate it and whose error tests then cut the
  // step (estimates up to 3000x the true local error): such a step is no evidence of a
  // stability limit (docs/integrators.md, "A rough solve is not a stability limit";
  // dropping to order 2 for the bar there cost A02 7e-4 of its energy).
  const bool historyHoldsRoughSolve = stepsSinceRoughSolve_ <= k_ + 1;
  if (!shortened) {
    if (k_ <= 2) {
      lowOrderStep_ = h;
    } else if ((h < kStabilityShrink * lowOrderStep_ && !historyHoldsRoughSolve) || modeGrowing) {
      nextK = 2;
      // Back to order 2's step, which damps the grown mode (kept when growth was caught).
      ratio = modeGrowing ? 1.0 : lowOrderStep_ / h;
      heldLow_.clear();
      heldOwn_.clear();
      ++stabilityLimitDetections_;
      stabilityJump = true;
      stabilityBar_ = stabilityBar_ == 0 ? kFirstStabilityBar : 2 * stabilityBar_;
      highOrderBarredUntil_ = stats_.steps + stabilityBar_;
    }
  }
  if (nextK > 2 && nextK > k_ && stats_.steps < highOrderBarredUntil_) {
    nextK = k_;
    ratio = ownRatio;
  }
  if (nextK != k_) {
    k_ = nextK;
    stepsAtOrder_ = 0;
  }
  // The I3 velocity test bounds the next step (at the estimate of the order just taken).
  if (velocityTested_)
    ratio = std::min(
        ratio, 0.9 * std::pow(1.0 / std::max(velocityError_, 1e-10), 1.0 / (lastStepOrder_ + 1)));
  if (ratio >= 1.5)
    h_ = h * std::min(ratio, stabilityJump ? ratio : 2.0);
  else if (ratio < 1.0)
    h_ = h * std::max(ratio, 0.5);
  else
    h_ = std::max(h, h_);
  h_ = std::min(h_, settings_.hmax);
  stats_.order = k_;
  stats_.stepSize = h;
}

}  // namespace openmss::solvers
