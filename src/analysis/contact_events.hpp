#pragma once
// CONTACT onset and separation as integrator events (docs/theory.md §6c, "Events"). An
// integrator seen through its contacts: after every accepted step each CONTACT's state (any
// contact point or none) is compared with the step's start; a change is located by bisection
// on the method's own interpolant. At an onset the method is restarted from the located
// (consistent) state, so no step straddles the first touch: the step that found it is cut back
// to the onset and the impact is resolved from a fresh start at the lowest order. Separations
// are located and recorded only (the force returns to zero continuously there). Every event is
// kept for the .msg.

#include <string>
#include <vector>

#include "mechanics/contact/contact_broad_phase.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/integrator.hpp"

namespace openmss::analysis {

struct ContactEvent {
  double time = 0.0;
  long contactId = 0;
  bool onset = true;  // false: separation
};

class ContactEventIntegrator final : public solvers::Integrator {
 public:
  // `restartAtOnset` false only locates and records (tests compare both).
  ContactEventIntegrator(solvers::Integrator& inner, const mechanics::MultibodySystem& system,
                         bool restartAtOnset = true);

  bool active() const { return !system_.model().contacts.empty(); }
  void start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;
  bool setNextStepSize(double h) override { return inner_.setNextStepSize(h); }
  bool step(double tout) override;
  double t() const override { return inner_.t(); }
  const Eigen::VectorXd& y() const override { return inner_.y(); }
  const Eigen::VectorXd& yp() const override { return inner_.yp(); }
  double previousTime() const override { return inner_.previousTime(); }
  void interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const override {
    inner_.interpolate(s, y, yp);
  }
  const solvers::IntegratorStatistics& statistics() const override { return inner_.statistics(); }
  const solvers::IntegratorFailure& failure() const override { return inner_.failure(); }
  std::vector<std::string> warnings() const override { return inner_.warnings(); }

  const std::vector<ContactEvent>& events() const { return events_; }
  // The .msg line of one event.
  static std::string describe(const ContactEvent& e);

 private:
  // Which contacts touch (any contact point) in state y, ascending: the narrow phase of the
  // elements the broad phase finds near (the others have no point: contactLoads makes the same
  // test). Lists, not one flag per element: a pile of N spheres has N² / 2 elements, and a
  // step's work stays with the near ones (docs/performance.md, "Contact pile").
  std::vector<int> touching(const Eigen::VectorXd& y);
  // The state components contact k reads (its bodies' entries), or empty when it may read more
  // (a user law): the bisection then interpolates the whole state.
  const std::vector<int>& componentsRead(int k);

  solvers::Integrator& inner_;
  const mechanics::MultibodySystem& system_;
  bool restartAtOnset_;
  // The broad phase of touching() (docs/theory.md §6c), with the bodies and markers the
  // contacts read: touching() computes each state once per call.
  mechanics::contact::ContactBroadPhase broad_;
  std::vector<int> state_;  // the touching contacts at inner_.t(), ascending
  std::vector<int> components_;
  bool fromStart_ = true;  // the next step is the first from a (re)start
  std::vector<ContactEvent> events_;
};

}  // namespace openmss::analysis
