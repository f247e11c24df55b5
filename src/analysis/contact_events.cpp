#include "analysis/contact_events.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

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

std::vector<int> ContactEventIntegrator::touching(const Eigen::VectorXd& y) {
  const auto& contacts = system_.model().contacts;
  std::vector<int> out;
  mechanics::contact::ContactKinematics<double> kin(system_.model(), system_.layout(), y.data(),
                                                    &broad_.slots());
  for (const int k : broad_.near(y.data()))
    if (touches(system_, contacts[k], kin)) out.push_back(k);
  return out;
}

const std::vector<int>& ContactEventIntegrator::componentsRead(int k) {
  const model::Model& m = system_.model();
  const model::Contact& c = m.contacts[static_cast<size_t>(k)];
  components_.clear();
  if (c.normalRoutine || c.frictionRoutine) return components_;
  std::vector<int> bodies;
  auto take = [&](int marker) {
    if (marker < 0) return;
    const int b = m.parts[m.markers[marker].part].body;
    if (b >= 0) bodies.push_back(b);
  };
  take(c.iMarker);
  take(c.jMarker);
  for (const model::ContactSolid& s : c.iSolids) take(s.marker);
  for (const model::ContactSolid& s : c.jSolids) take(s.marker);
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  // A contact between two ground solids reads no state; one entry keeps the list non-empty.
  if (bodies.empty()) components_.push_back(0);
  for (const int b : bodies)
    for (int i = 0; i < mechanics::StateLayout::kPerBody; ++i)
      components_.push_back(system_.layout().body(b) + i);
  return components_;
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
  const std::vector<int> now = touching(inner_.y());
  if (now == state_) return true;
  // The contacts that changed, ascending (the two lists are).
  std::vector<int> changed;
  std::set_symmetric_difference(state_.begin(), state_.end(), now.begin(), now.end(),
                                std::back_inserter(changed));
  // Each change located by bisection on the interpolant: lo keeps the old state, hi the new,
  // until the bracket is 1e-10 of the step (or at rounding); the event time is hi. Only the
  // entries the contact reads are interpolated (the same bits as the whole state's).
  const auto& contacts = system_.model().contacts;
  struct Located {
    ContactEvent event;
    int element;  // index into Model::contacts
  };
  std::vector<Located> found;
  Eigen::VectorXd y = inner_.y(), yp;
  const double tol = std::max(1e-10 * (b - a), 4e-16 * std::max(1.0, std::abs(b)));
  for (const int k : changed) {
    const bool before = std::binary_search(state_.begin(), state_.end(), k);
    const std::vector<int>& read = componentsRead(k);
    double lo = a, hi = b;
    for (int it = 0; it < 200 && hi - lo > tol; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (read.empty())
        inner_.interpolate(mid, y, yp);
      else
        inner_.interpolateComponents(mid, read, y);
      (touches(system_, contacts[k], y) == before ? lo : hi) = mid;
    }
    found.push_back({{hi, contacts[k].id, !before}, k});
  }
  // By time; ties keep the ascending element order.
  std::stable_sort(found.begin(), found.end(),
                   [](const Located& x, const Located& z) { return x.event.time < z.event.time; });
  // The step is cut back to its first onset, so that no step's history (the solutions before
  // its start the multistep method interpolates) lies before an onset and its end after it.
  // A step from a (re)start has no such history (order 1 from one consistent state, under the
  // error test like any one-step method): it is cut back to its *last* onset instead, so that
  // the onsets of one cluster (a layer of a pile landing within 1e-7 s) cost two restarts (at
  // the first, then from there at the last), not one each (docs/theory.md §6c, "Events";
  // docs/performance.md, "Contact pile").
  double restartAt = b;
  if (restartAtOnset_)
    for (const Located& f : found)
      if (f.event.onset) {
        restartAt = f.event.time;
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
    // The located events up to the restart set those contacts' state (the projection may
    // have moved a touch by a rounding); the rest is the state at the restart.
    std::vector<int> at = touching(inner_.y());
    for (const Located& f : found) {
      if (f.event.time > restartAt) continue;
      const auto it = std::lower_bound(at.begin(), at.end(), f.element);
      const bool in = it != at.end() && *it == f.element;
      if (f.event.onset && !in) at.insert(it, f.element);
      if (!f.event.onset && in) at.erase(it);
      events_.push_back(f.event);
    }
    state_ = at;
    return true;
  }
  for (const Located& f : found) events_.push_back(f.event);
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
