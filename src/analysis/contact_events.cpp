#include "analysis/contact_events.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mechanics/contact/contact_loads.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::analysis {
namespace {

// Whether contact c has any contact point in state y (the narrow phase on values); `kin` the
// marker states, shared by the contacts of one state.
bool touches(const mechanics::MultibodySystem& s, const model::Contact& c,
             mechanics::contact::ContactKinematics<double>& kin) {
  return mechanics::contact::contactLoads<double>(s.model(), s.layout(), c, kin, false).points > 0;
}

bool touches(const mechanics::MultibodySystem& s, const model::Contact& c,
             const Eigen::VectorXd& y) {
  mechanics::contact::ContactKinematics<double> kin(s.model(), s.layout(), y.data());
  return touches(s, c, kin);
}

// The interpolated state made consistent as at the start of a run (as SENSOR events do,
// analysis/sensor_monitor.cpp); should a projection fail, the interpolated state is kept.
void makeConsistent(const mechanics::MultibodySystem& s, double t, Eigen::VectorXd& y,
                    Eigen::VectorXd& yp) {
  Eigen::VectorXd yc = y, ypc = yp;
  if (!mechanics::assemblePositions(s, t, yc, 1e-12, 25).converged) return;
  mechanics::solveVelocities(s, t, yc);
  if (!mechanics::solveUserAlgebraic(s, t, yc).converged) return;
  if (!mechanics::solveAccelerations(s, t, yc, ypc)) return;
  mechanics::userStateRates(s, t, yc, ypc);
  y = std::move(yc);
  yp = std::move(ypc);
}

}  // namespace

ContactEventIntegrator::ContactEventIntegrator(solvers::Integrator& inner,
                                               const mechanics::MultibodySystem& system,
                                               bool restartAtOnset)
    : inner_(inner),
      system_(system),
      restartAtOnset_(restartAtOnset),
      broad_(system.model(), system.layout()) {}

std::vector<bool> ContactEventIntegrator::touching(const Eigen::VectorXd& y) {
  const auto& contacts = system_.model().contacts;
  std::vector<bool> out(contacts.size(), false);
  mechanics::contact::ContactKinematics<double> kin(system_.model(), system_.layout(), y.data(),
                                                    &broad_.slots());
  for (const int k : broad_.near(y.data())) out[k] = touches(system_, contacts[k], kin);
  return out;
}

void ContactEventIntegrator::start(double t0, const Eigen::VectorXd& y0,
                                   const Eigen::VectorXd& yp0) {
  inner_.start(t0, y0, yp0);
  state_ = touching(inner_.y());
  fromStart_ = true;
}

bool ContactEventIntegrator::step(double tout) {
  const double a = inner_.t();
  // Whether this step is the first from a (re)start: order 1 with no history before a.
  const bool fromStart = fromStart_;
  fromStart_ = false;
  if (!inner_.step(tout)) return false;
  if (!active()) return true;
  const double b = inner_.t();
  const std::vector<bool> now = touching(inner_.y());
  if (now == state_) return true;
  // Each change located by bisection on the interpolant: lo keeps the old state, hi the new,
  // until the bracket is 1e-10 of the step (or at rounding); the event time is hi.
  const auto& contacts = system_.model().contacts;
  std::vector<ContactEvent> found;
  Eigen::VectorXd y, yp;
  const double tol = std::max(1e-10 * (b - a), 4e-16 * std::max(1.0, std::abs(b)));
  for (size_t k = 0; k < contacts.size(); ++k) {
    if (now[k] == state_[k]) continue;
    double lo = a, hi = b;
    for (int it = 0; it < 200 && hi - lo > tol; ++it) {
      const double mid = 0.5 * (lo + hi);
      inner_.interpolate(mid, y, yp);
      (touches(system_, contacts[k], y) == state_[k] ? lo : hi) = mid;
    }
    found.push_back({hi, contacts[k].id, static_cast<bool>(now[k])});
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const ContactEvent& x, const ContactEvent& z) { return x.time < z.time; });
  // The step is cut back to its first onset, so that no step's history (the solutions before
  // its start the multistep method interpolates) lies before an onset and its end after it.
  // A step from a (re)start has no such history (order 1 from one consistent state, under the
  // error test like any one-step method): it is cut back to its *last* onset instead, so that
  // the onsets of one cluster (a layer of a pile landing within 1e-7 s) cost two restarts (at
  // the first, then from there at the last), not one each (docs/theory.md §6c, "Events";
  // docs/performance.md, "Contact pile").
  double restartAt = b;
  if (restartAtOnset_)
    for (const ContactEvent& e : found)
      if (e.onset) {
        restartAt = e.time;
        if (!fromStart) break;
      }
  if (restartAt < b) {
    // Cut the step back to that onset: the events after it are found again from there.
    inner_.interpolate(restartAt, y, yp);
    makeConsistent(system_, restartAt, y, yp);
    // The method keeps its Newton matrix: the new contact's IMPACT stiffness is zero at the
    // onset (k delta^e, e > 1), so the matrix of the step just taken is nearly exact for it,
    // and forming and factorising a new one at every onset was one full factorisation per step
    // of a landing pile (docs/performance.md, "Contact pile").
    inner_.restart(restartAt, y, yp);
    fromStart_ = true;
    // The restart's first step is the one the error control had just accepted (b - a), not
    // HINIT: HINIT is the size for a run's start, often far longer than the steps an impact
    // allows, and cost a corrector failure and error-test rejections at every restart.
    inner_.setNextStepSize(b - a);
    std::vector<bool> at = touching(inner_.y());
    for (size_t k = 0; k < contacts.size(); ++k)
      for (const ContactEvent& e : found)
        if (e.contactId == contacts[k].id && e.time <= restartAt) at[k] = e.onset;
    state_ = at;
    for (const ContactEvent& e : found)
      if (e.time <= restartAt) events_.push_back(e);
    return true;
  }
  events_.insert(events_.end(), found.begin(), found.end());
  state_ = now;
  return true;
}

std::string ContactEventIntegrator::describe(const ContactEvent& e) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "   CONTACT/%ld %s at time %.10E", e.contactId,
                e.onset ? "onset (first touch)" : "separation", e.time);
  return buf;
}

}  // namespace openmss::analysis
