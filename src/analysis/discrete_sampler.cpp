#include "analysis/discrete_sampler.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "mechanics/general_state_rows.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::analysis {

DiscreteSampler::DiscreteSampler(const mechanics::MultibodySystem& system,
                                 mechanics::ExpressionRunState* run)
    : system_(system), run_(run) {
  for (const auto& e : system.model().generalStates)
    if (e.nd > 0 && e.routines && e.routines->hasUpdate()) active_ = true;
}

double DiscreteSampler::nextTime(int k) const {
  const model::GeneralStateElement& e = system_.model().generalStates[k];
  if (e.nd == 0 || !e.routines || !e.routines->hasUpdate())
    return std::numeric_limits<double>::infinity();
  const double last = run_ ? run_->gseLastSample(k) : 0.0;
  double period = 0.0;
  if (const auto step = e.routines->sampleStep(last))
    period = *step;
  else if (e.samplePeriod)
    period = e.samplePeriod->evaluate(nullptr, last);
  // A period that is not positive would stop time: no further samples.
  if (!(period > 0.0) || !std::isfinite(period)) return std::numeric_limits<double>::infinity();
  return last + period;
}

double DiscreteSampler::nextTime() const {
  double next = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(system_.model().generalStates.size()); ++k)
    next = std::min(next, nextTime(k));
  return next;
}

void DiscreteSampler::sample(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  const model::Model& m = system_.model();
  const mechanics::StateLayout& l = system_.layout();
  const double eps = 1e-12 * std::max(1.0, std::abs(t));
  std::vector<std::vector<double>> updated(m.generalStates.size());
  std::vector<double> scheduled(m.generalStates.size());
  for (int k = 0; k < static_cast<int>(m.generalStates.size()); ++k) {
    const model::GeneralStateElement& e = m.generalStates[k];
    scheduled[k] = nextTime(k);
    if (!(std::abs(scheduled[k] - t) <= eps)) continue;
    std::vector<double> x(static_cast<size_t>(e.ns)), u(static_cast<size_t>(e.ni));
    for (int c = 0; c < e.ns; ++c) x[c] = y(mechanics::gseStateColumn(m, l, k, c));
    for (int c = 0; c < e.ni; ++c) u[c] = y(mechanics::gseInputColumn(m, l, k, c));
    updated[k].assign(static_cast<size_t>(e.nd), 0.0);
    const user::GseArguments a{t, x.data(), run_->gseDiscrete(k).data(), u.data(), false};
    e.routines->update(a, updated[k].data());
  }
  for (size_t k = 0; k < updated.size(); ++k) {
    if (updated[k].empty()) continue;
    // The scheduled time, not t: no drift of the sample grid from rounding.
    run_->setGseSample(static_cast<int>(k), updated[k], scheduled[k]);
  }
  // Outputs, rates and accelerations that read xd jump with it.
  Eigen::VectorXd yc = y, ypc = yp;
  if (!mechanics::solveUserAlgebraic(system_, t, yc).converged) return;
  if (!mechanics::solveAccelerations(system_, t, yc, ypc)) return;
  mechanics::userStateRates(system_, t, yc, ypc);
  y = std::move(yc);
  yp = std::move(ypc);
}

}  // namespace openmss::analysis
