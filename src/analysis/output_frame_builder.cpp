#include "analysis/output_frame_builder.hpp"

#include "analysis/request_values.hpp"
#include "common/rotation.hpp"
#include "mechanics/pose.hpp"

namespace openmss::analysis {
namespace {

using mechanics::ForceElementKind;
using mechanics::StateLayout;
using CE = mechanics::MultibodySystem::ConstraintElement;

output::PartOutput partOutput(const mechanics::MultibodySystem& s, int body,
                              const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  const StateLayout& l = s.layout();
  const int o = l.body(body);
  const auto pose = mechanics::bodyPose(l, body, y.data());
  const Eigen::Matrix3d a = toEigen(pose.a);
  output::PartOutput p;
  p.position = toEigen(pose.r);
  p.angles = euler313FromMatrix(a);
  p.velocity = toEigen(pose.v);
  p.angularVelocity = toEigen(pose.wg);
  // The state holds v in ground axes and w in body axes (mechanics/state_layout.hpp).
  p.acceleration = yp.segment<3>(o + StateLayout::kV);
  p.angularAcceleration = a * yp.segment<3>(o + StateLayout::kW);
  return p;
}

output::ElementForceOutput reaction(const mechanics::MultibodySystem& s, CE kind, int element,
                                    const Eigen::VectorXd& y) {
  output::ElementForceOutput out;
  const int iMarker = s.elementMarkers(kind, element).first;
  s.elementReaction(kind, element, iMarker, y.data(), out.force, out.torque);
  return out;
}

void appliedForces(const mechanics::MultibodySystem& s, ForceElementKind kind, int count, double t,
                   const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                   std::vector<output::ElementForceOutput>& out) {
  // Force functions may read accelerations and reactions, as in the DAE (request_values.cpp).
  const mechanics::DynamicReads<double> base{yp.data(), &s.constraints()};
  const mechanics::DynamicReads<double> reads = s.forceElements().readsWith(&base);
  out.assign(count, {});
  if (kind == ForceElementKind::Contact) {
    // Only the contacts whose solids are near carry a load; the others' are the zeros `out`
    // holds (a pile of N spheres has N² / 2 pair elements, docs/performance.md, "Contact pile").
    for (const int e : s.forceElements().nearContacts(y.data()))
      s.forceElements().action({kind, e}, false, t, y.data(), out[e].force, out[e].torque, &reads);
    return;
  }
  for (int e = 0; e < count; ++e)
    s.forceElements().action({kind, e}, false, t, y.data(), out[e].force, out[e].torque, &reads);
}

}  // namespace

void fillRequestColumns(const mechanics::MultibodySystem& s, double t, const Eigen::VectorXd& y,
                        const Eigen::VectorXd& yp, OutputFrame& frame) {
  frame.time = t;
  frame.requests.clear();
  frame.requests.reserve(s.model().requests.size());
  for (const auto& r : s.model().requests) frame.requests.push_back(requestColumns(s, r, t, y, yp));
}

void fillStateOutputs(const mechanics::MultibodySystem& s, double t, const Eigen::VectorXd& y,
                      const Eigen::VectorXd& yp, OutputFrame& frame) {
  const model::Model& m = s.model();
  frame.parts.clear();
  for (const model::Part& p : m.parts)
    if (p.body >= 0) frame.parts.push_back(partOutput(s, p.body, y, yp));
  const auto reactions = [&](CE kind, std::size_t count,
                             std::vector<output::ElementForceOutput>& out) {
    out.clear();
    for (std::size_t e = 0; e < count; ++e)
      out.push_back(reaction(s, kind, static_cast<int>(e), y));
  };
  reactions(CE::Joint, m.joints.size(), frame.joints);
  reactions(CE::JPrim, m.jprims.size(), frame.jprims);
  reactions(CE::Motion, m.motions.size(), frame.motions);
  reactions(CE::Coupler, m.couplers.size(), frame.couplers);
  reactions(CE::Gear, m.gears.size(), frame.gears);
  reactions(CE::Gcon, m.gcons.size(), frame.gcons);
  const auto n = [](const auto& v) { return static_cast<int>(v.size()); };
  appliedForces(s, ForceElementKind::SForce, n(m.sforces), t, y, yp, frame.sforces);
  appliedForces(s, ForceElementKind::SpringDamper, n(m.springDampers), t, y, yp,
                frame.springDampers);
  appliedForces(s, ForceElementKind::LinearField, n(m.linearFields), t, y, yp, frame.linearFields);
  appliedForces(s, ForceElementKind::VectorForce, n(m.vectorForces), t, y, yp, frame.vectorForces);
  appliedForces(s, ForceElementKind::Friction, n(m.frictions), t, y, yp, frame.frictions);
  appliedForces(s, ForceElementKind::Contact, n(m.contacts), t, y, yp, frame.contacts);
  // NFORCE loads every I marker and J (mechanics/force_elements.hpp): its entry is J's share.
  frame.nforces.assign(m.nforces.size(), {});
  for (int e = 0; e < n(m.nforces); ++e) {
    std::vector<V3<double>> f, tq;
    V3<double> fj, tj;
    s.forceElements().multiPointLoads(e, y.data(), f, tq, fj, tj);
    frame.nforces[e].force = toEigen(fj);
    frame.nforces[e].torque = toEigen(tj);
  }
  const StateLayout& l = s.layout();
  frame.variables.assign(m.variables.size(), 0.0);
  for (std::size_t k = 0; k < m.variables.size(); ++k)
    frame.variables[k] = y(l.userAlg(static_cast<int>(k)));
  frame.diffs.assign(m.diffs.size(), 0.0);
  for (std::size_t k = 0; k < m.diffs.size(); ++k)
    frame.diffs[k] = y(l.userDiff(static_cast<int>(k)));
  // LSE/TFSISO and GSE states are user differential states from firstState on, GSE outputs
  // user algebraic unknowns from firstOutput on (model/model.hpp).
  frame.linearStates.clear();
  for (const model::LinearStateElement& e : m.linearStates) {
    std::vector<double> x(static_cast<std::size_t>(e.a.rows()));
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = y(l.userDiff(e.firstState + static_cast<int>(i)));
    frame.linearStates.push_back(std::move(x));
  }
  frame.gseStates.clear();
  frame.gseOutputs.clear();
  for (const model::GeneralStateElement& e : m.generalStates) {
    std::vector<double> x(static_cast<std::size_t>(e.ns)), out(static_cast<std::size_t>(e.no));
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = y(l.userDiff(e.firstState + static_cast<int>(i)));
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = y(l.userAlg(e.firstOutput + static_cast<int>(i)));
    frame.gseStates.push_back(std::move(x));
    frame.gseOutputs.push_back(std::move(out));
  }
}

}  // namespace openmss::analysis
