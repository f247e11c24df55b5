#include "analysis/request_values.hpp"

#include <cmath>
#include <optional>

#include "common/rotation.hpp"
#include "mechanics/friction/friction_output.hpp"
#include "mechanics/measures.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

struct Kin {
  Eigen::Vector3d p, v, a, w, alpha;
  Eigen::Matrix3d axes;
};

Kin markerKinematics(const mechanics::MultibodySystem& s, int marker, const Eigen::VectorXd& y,
                     const Eigen::VectorXd& yp) {
  Kin k;
  k.p.setZero(); k.v.setZero(); k.a.setZero(); k.w.setZero(); k.alpha.setZero();
  k.axes.setIdentity();
  if (marker < 0) return k;
  const auto& m = s.model();
  const auto& mk = m.markers[marker];
  const auto& part = m.parts[mk.part];
  if (part.body < 0) {
    k.p = mk.position;
    k.axes = mk.orientation;
    return k;
  }
  const auto& l = s.layout();
  const int o = l.body(part.body);
  const auto pose = mechanics::bodyPose(l, part.body, y.data());
  const Eigen::Matrix3d a = toEigen(pose.a);
  const Eigen::Vector3d sg = a * mk.position;
  k.w = toEigen(pose.wg);
  k.alpha = a * yp.segment<3>(o + StateLayout::kW);
  k.p = toEigen(pose.r) + sg;
  k.v = toEigen(pose.v) + k.w.cross(sg);
  k.a = yp.segment<3>(o + StateLayout::kV) + k.alpha.cross(sg) + k.w.cross(k.w.cross(sg));
  k.axes = a * mk.orientation;
  return k;
}

// The applied force element a read-back measure (SPDP, BUSH, FIELD, BEAM, VFORCE, VTORQ,
// GFORCE) names.
std::optional<mechanics::ForceElementRef> forceElementOf(model::MeasureKind kind, int element) {
  using K = model::MeasureKind;
  using FK = mechanics::ForceElementKind;
  switch (kind) {
    case K::SpringDamperForce: return mechanics::ForceElementRef{FK::SpringDamper, element};
    case K::BushingForce: case K::FieldForce: case K::BeamForce:
      return mechanics::ForceElementRef{FK::LinearField, element};
    case K::VForceForce: case K::VTorqueForce: case K::GForceForce:
      return mechanics::ForceElementRef{FK::VectorForce, element};
    case K::ContactForce: return mechanics::ForceElementRef{FK::Contact, element};
    default: return std::nullopt;
  }
}

// What force functions read besides y: accelerations (y') and reactions (the multipliers in y),
// so that a read-back of a force whose function reads them gives the force the DAE applied.
mechanics::DynamicReads<double> readsOf(const mechanics::MultibodySystem& s,
                                        const Eigen::VectorXd& yp) {
  const mechanics::DynamicReads<double> base{yp.data(), &s.constraints()};
  return s.forceElements().readsWith(&base);  // functions may read forces (theory.md §4d)
}

// Sum of the force elements acting on `marker` (as I, or as J / JFLOAT), only those between
// `marker` and `other` when other >= 0: force on the marker's part, torque about its origin.
void forceElementsOnMarker(const mechanics::MultibodySystem& s, int marker, int other, double t,
                           const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                           Eigen::Vector3d& force, Eigen::Vector3d& torque) {
  force.setZero();
  torque.setZero();
  const mechanics::ForceElements& fe = s.forceElements();
  const mechanics::DynamicReads<double> reads = readsOf(s, yp);
  Eigen::Vector3d f, tq;
  for (const mechanics::ForceElementRef& e : fe.elements()) {
    if (e.kind == mechanics::ForceElementKind::MultiPoint) {
      // NFORCE: its load on `marker` as FX..TM(marker, other) reads it (docs/theory.md §6b).
      bool atJ = false;
      if (!fe.netForceActs(e, marker, other, &atJ)) continue;
      V3<double> f3, t3;
      fe.multiPointAction(e.index, marker, y.data(), f3, t3);
      force += toEigen(f3);
      torque += toEigen(t3);
      continue;
    }
    const int i = fe.iMarker(e), j = fe.jMarker(e);
    const bool atI = i == marker && (other < 0 || j == other);
    const bool atJ = j == marker && (other < 0 || i == other);
    if (!atI && !atJ) continue;
    fe.action(e, !atI, t, y.data(), f, tq, &reads);
    force += f;
    torque += tq;
  }
}

// Force and torque (about the marker origin, ground axes) on `marker` from element forces.
void elementForce(const mechanics::MultibodySystem& s, model::MeasureKind kind, int element,
                  bool atJ, double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                  Eigen::Vector3d& f, Eigen::Vector3d& tq) {
  const mechanics::DynamicReads<double> reads = readsOf(s, yp);
  if (kind == model::MeasureKind::SForceForce) {
    s.forceElements().action({mechanics::ForceElementKind::SForce, element}, atJ, t, y.data(), f,
                             tq, &reads);
    return;
  }
  if (auto e = forceElementOf(kind, element)) {
    s.forceElements().action(*e, atJ, t, y.data(), f, tq, &reads);
    return;
  }
  using CE = mechanics::MultibodySystem::ConstraintElement;
  const CE ce = kind == model::MeasureKind::MotionForce  ? CE::Motion
                : kind == model::MeasureKind::JPrimForce ? CE::JPrim
                                                         : CE::Joint;
  const auto [iMarker, jMarker] = s.elementMarkers(ce, element);
  s.elementReaction(ce, element, atJ ? jMarker : iMarker, y.data(), f, tq);
}

// True when GCON g's FUNCTION reads `marker` (as i, j or k of a measure).
bool gconReads(const model::GeneralConstraint& g, int marker) {
  for (const model::Measure& m : g.function.measures)
    if (m.i == marker || m.j == marker || m.k == marker) return true;
  return false;
}

// The reactions of the GCONs acting on `marker`, only those whose FUNCTION also reads `other`
// when other >= 0 (docs/theory.md §5c, "Reaction"): force on the marker's part, torque about
// the marker, ground axes, added to force and torque. A distance GCON DM(i, j) − L thus shows
// in REQUEST/…, FORCE, I=i, J=j (and FX..TM(i, j)) as it does in ADAMS.
void addGconReactions(const mechanics::MultibodySystem& s, int marker, int other,
                      const Eigen::VectorXd& y, Eigen::Vector3d& force, Eigen::Vector3d& torque) {
  const auto& gcons = s.model().gcons;
  Eigen::Vector3d f, tq;
  for (int e = 0; e < static_cast<int>(gcons.size()); ++e) {
    if (!gconReads(gcons[e], marker) || (other >= 0 && !gconReads(gcons[e], other))) continue;
    s.elementReaction(mechanics::MultibodySystem::ConstraintElement::Gcon, e, marker, y.data(), f,
                      tq);
    force += f;
    torque += tq;
  }
}

double component(const Eigen::Vector3d& f, const Eigen::Vector3d& tq, int comp,
                 const Eigen::Matrix3d& rm) {
  const Eigen::Vector3d fr = rm.transpose() * f;
  const Eigen::Vector3d tr = rm.transpose() * tq;
  switch (comp) {
    case 1: return f.norm();
    case 2: case 3: case 4: return fr(comp - 2);
    case 5: return tq.norm();
    default: return tr(comp - 6);
  }
}

}  // namespace

double measureValue(const mechanics::MultibodySystem& s, const model::Measure& ms, double t,
                    const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  using K = model::MeasureKind;
  double out = 0.0;
  if (mechanics::kinematicMeasure(s.model(), s.layout(), ms, y.data(), &out, s.runState()))
    return out;
  if (ms.l >= 0) {
    // Derivatives in the frame of marker l: the function's own definition
    // (mechanics/dynamic_measures.hpp), one for outputs and functions.
    const mechanics::DynamicReads<double> reads{yp.data(), &s.constraints()};
    if (mechanics::dynamicMeasure(s.model(), s.layout(), ms, y.data(), &reads, &out)) return out;
  }
  const Kin i = markerKinematics(s, ms.i, y, yp);
  const Kin j = markerKinematics(s, ms.j, y, yp);
  const Eigen::Matrix3d k = ms.k >= 0 ? markerKinematics(s, ms.k, y, yp).axes
                                      : Eigen::Matrix3d::Identity();
  // Time derivatives are taken in ground, so relative accelerations are plain differences.
  const Eigen::Vector3d acc = i.a - j.a, wdt = i.alpha - j.alpha;
  switch (ms.kind) {
    case K::ACCX: return acc.dot(k.col(0));
    case K::ACCY: return acc.dot(k.col(1));
    case K::ACCZ: return acc.dot(k.col(2));
    case K::ACCM: return acc.norm();
    case K::WDTX: return wdt.dot(k.col(0));
    case K::WDTY: return wdt.dot(k.col(1));
    case K::WDTZ: return wdt.dot(k.col(2));
    case K::WDTM: return wdt.norm();
    case K::JointForce: case K::MotionForce: case K::SForceForce: case K::JPrimForce:
    case K::SpringDamperForce: case K::BushingForce: case K::FieldForce: case K::BeamForce:
    case K::VForceForce: case K::VTorqueForce: case K::GForceForce: case K::ContactForce: {
      Eigen::Vector3d f, tq;
      elementForce(s, ms.kind, ms.element, ms.atJ == 1, t, y, yp, f, tq);
      return component(f, tq, ms.component, k);
    }
    case K::NetForce: case K::NForceForce: {
      // FX..TM (C++ semantics: with j omitted or 0 every element acting on marker i; with j,
      // only those acting between i and j; components in k axes) and NFORCE(id, marker, ...):
      // the function read-back itself (mechanics/force_read_back.hpp), one definition for
      // outputs and functions.
      const mechanics::DynamicReads<double> reads = readsOf(s, yp);
      double value = 0.0;
      s.forceElements().readBack(ms, t, y.data(), &reads, &value);
      return value;
    }
    case K::FrictionOutput:
      return mechanics::friction::frictionOutput(s.model(), s.layout(), &s.constraints(),
                                                 s.runState(), ms.element, ms.component,
                                                 y.data());
    case K::Time:
      return t;
    default:
      return 0.0;
  }
}

std::array<double, 8> requestColumns(const mechanics::MultibodySystem& s,
                                     const model::Request& r, double t,
                                     const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  std::array<double, 8> c{};
  using RK = model::Request::Kind;
  if (r.kind == RK::Expressions) {
    std::vector<double> host;
    for (int col = 0; col < 8; ++col) {
      if (!r.columns[col]) continue;
      const auto& b = *r.columns[col];
      host.assign(b.measures.size(), 0.0);
      for (size_t k = 0; k < b.measures.size(); ++k)
        host[k] = measureValue(s, b.measures[k], t, y, yp);
      c[col] = b.expression.evaluate(host.empty() ? nullptr : host.data(), t, s.runState());
    }
    return c;
  }
  const Kin i = markerKinematics(s, r.iMarker, y, yp);
  const Kin j = markerKinematics(s, r.jMarker, y, yp);
  const Eigen::Matrix3d rm = r.rmMarker >= 0 ? markerKinematics(s, r.rmMarker, y, yp).axes
                                             : Eigen::Matrix3d::Identity();
  auto put = [&](const Eigen::Vector3d& lin, const Eigen::Vector3d& ang, bool angMagnitude) {
    const Eigen::Vector3d l = rm.transpose() * lin;
    const Eigen::Vector3d a = rm.transpose() * ang;
    c[0] = lin.norm();
    c[1] = l(0); c[2] = l(1); c[3] = l(2);
    c[4] = angMagnitude ? ang.norm() : 0.0;
    c[5] = a(0); c[6] = a(1); c[7] = a(2);
  };
  switch (r.kind) {
    case RK::Displacement: {
      const Eigen::Vector3d d = i.p - j.p;
      const Eigen::Vector3d l = rm.transpose() * d;
      // Body 3-1-3 angles of I relative to J (not affected by RM).
      const Eigen::Vector3d e = euler313FromMatrix(j.axes.transpose() * i.axes);
      c = {d.norm(), l(0), l(1), l(2), 0.0, e(0), e(1), e(2)};
      break;
    }
    case RK::Velocity:
      put(i.v - j.v, i.w - j.w, true);
      break;
    case RK::Acceleration:
      put(i.a - j.a, i.alpha - j.alpha, true);
      break;
    case RK::Force: {
      // Every joint, joint primitive, motion, GCON and force element acting between I and J, on
      // I.
      const auto& m = s.model();
      Eigen::Vector3d ft = Eigen::Vector3d::Zero(), tt = Eigen::Vector3d::Zero();
      auto between = [&](int a, int b) {
        return (a == r.iMarker && b == r.jMarker) || (a == r.jMarker && b == r.iMarker);
      };
      Eigen::Vector3d f, tq;
      for (int e = 0; e < static_cast<int>(m.joints.size()); ++e)
        if (between(m.joints[e].iMarker, m.joints[e].jMarker)) {
          s.elementReaction(false, e, r.iMarker, y.data(), f, tq);
          ft += f; tt += tq;
        }
      for (int e = 0; e < static_cast<int>(m.jprims.size()); ++e)
        if (between(m.jprims[e].iMarker, m.jprims[e].jMarker)) {
          s.elementReaction(mechanics::MultibodySystem::ConstraintElement::JPrim, e, r.iMarker,
                            y.data(), f, tq);
          ft += f; tt += tq;
        }
      for (int e = 0; e < static_cast<int>(m.motions.size()); ++e) {
        const auto& jt = m.motions[e];  // the markers it acts between
        if (between(jt.iMarker, jt.jMarker)) {
          s.elementReaction(true, e, r.iMarker, y.data(), f, tq);
          ft += f; tt += tq;
        }
      }
      // PTCV: its reaction on I when J is its JFLOAT or RM marker (docs/theory.md §5d).
      for (int e = 0; e < static_cast<int>(m.ptcvs.size()); ++e) {
        const model::PointCurve& p = m.ptcvs[e];
        if (r.iMarker == p.iMarker && (r.jMarker == p.jFloat || r.jMarker == p.rmMarker)) {
          s.elementReaction(mechanics::MultibodySystem::ConstraintElement::PointCurve, e,
                            r.iMarker, y.data(), f, tq);
          ft += f; tt += tq;
        }
      }
      // CVCV: its reaction on IRM's part (JRM's) when I is its IRM (JRM) and J is the other
      // curve's RM or float marker; torque about I (docs/theory.md §5e).
      for (int e = 0; e < static_cast<int>(m.cvcvs.size()); ++e) {
        const model::CurveCurve& cv = m.cvcvs[e];
        if ((r.iMarker == cv.iRm && (r.jMarker == cv.jRm || r.jMarker == cv.jFloat)) ||
            (r.iMarker == cv.jRm && (r.jMarker == cv.iRm || r.jMarker == cv.iFloat))) {
          s.elementReaction(mechanics::MultibodySystem::ConstraintElement::CurveCurve, e,
                            r.iMarker, y.data(), f, tq);
          ft += f; tt += tq;
        }
      }
      // GCONs and applied force elements (SFORCE, SPRINGDAMPER, BUSHING, ...) between I and J.
      if (r.jMarker >= 0) {
        addGconReactions(s, r.iMarker, r.jMarker, y, ft, tt);
        forceElementsOnMarker(s, r.iMarker, r.jMarker, t, y, yp, f, tq);
        ft += f; tt += tq;
      }
      put(ft, tt, true);
      break;
    }
    default:
      break;
  }
  return c;
}

}  // namespace openmss::analysis
