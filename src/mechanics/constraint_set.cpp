#include "mechanics/constraint_set.hpp"

#include <algorithm>

namespace openmss::mechanics {
namespace {

const char* kAxis[3] = {"X", "Y", "Z"};

// An equation between the markers of a joint (element = joint index) or a joint primitive.
struct Element {
  int iMarker, jMarker, joint, jprim;
};

ConstraintEquation base(ConstraintEquation::Kind kind, const Element& el) {
  ConstraintEquation e;
  e.kind = kind;
  e.iMarker = el.iMarker;
  e.jMarker = el.jMarker;
  e.joint = el.joint;
  e.jprim = el.jprim;
  return e;
}

ConstraintEquation point(int axis, const Element& el) {
  ConstraintEquation e = base(ConstraintEquation::Kind::Point, el);
  e.axisJ = axis;
  e.label = std::string(kAxis[axis]) + " (I-J)";
  return e;
}

ConstraintEquation dotEq(int ai, int aj, const Element& el) {
  ConstraintEquation e = base(ConstraintEquation::Kind::Dot, el);
  e.axisI = ai;
  e.axisJ = aj;
  e.label = std::string(kAxis[ai]) + "i." + kAxis[aj] + "j";
  return e;
}

ConstraintEquation along(int aj, const Element& el) {
  ConstraintEquation e = base(ConstraintEquation::Kind::Along, el);
  e.axisJ = aj;
  e.label = std::string(kAxis[aj]) + "j.(I-J)";
  return e;
}

// A marker's frame in ground at the data set's configuration.
Frame<double> dataSetFrame(const model::Model& model, int marker) {
  const model::Marker& mk = model.markers[marker];
  const model::Part& part = model.parts[mk.part];
  const Eigen::Vector3d p = part.position + part.orientation * mk.position;
  const Eigen::Matrix3d a = part.orientation * mk.orientation;
  return {V3<double>::from(p), M3<double>::from(a)};
}

// A coupled translation-rotation equation (RACKPIN, SCREW) that holds at the data set's
// configuration: the offset is the coupling's value there.
ConstraintEquation coupling(ConstraintEquation::Kind kind, double ratio, const Element& el,
                            const model::Model& model, const char* label) {
  ConstraintEquation e = base(kind, el);
  e.ratio = ratio;
  e.label = label;
  const Frame<double> fi = dataSetFrame(model, el.iMarker);
  const Frame<double> fj = dataSetFrame(model, el.jMarker);
  e.offset = ConstraintSet::geometry(e, fi, fj);  // with offset 0: the value to take off
  return e;
}

}  // namespace

int ConstraintSet::equationCount(model::JointType t) {
  switch (t) {
    case model::JointType::Revolute:
      return 5;
    case model::JointType::Spherical:
      return 3;
    case model::JointType::Universal:
      return 4;
    case model::JointType::Hooke:
      return 4;
    case model::JointType::Translational:
      return 5;
    case model::JointType::Cylindrical:
      return 4;
    case model::JointType::Fixed:
      return 6;
    case model::JointType::Convel:
      return 4;
    case model::JointType::Planar:
      return 3;
    case model::JointType::RackPin:
      return 1;
    case model::JointType::Screw:
      return 1;
  }
  return 0;
}

int ConstraintSet::equationCount(model::JPrimType t) {
  switch (t) {
    case model::JPrimType::AtPoint:
      return 3;
    case model::JPrimType::InLine:
      return 2;
    case model::JPrimType::InPlane:
      return 1;
    case model::JPrimType::Orientation:
      return 3;
    case model::JPrimType::ParallelAxes:
      return 2;
    case model::JPrimType::Perpendicular:
      return 1;
  }
  return 0;
}

int ConstraintSet::grueblerCount(const model::Model& model) {
  int count = 6 * model.bodyCount();
  for (const auto& j : model.joints) count -= equationCount(j.type);
  for (const auto& p : model.jprims) count -= equationCount(p.type);
  count -= static_cast<int>(model.motions.size());
  count -= static_cast<int>(model.couplers.size() + model.gears.size());
  count -= static_cast<int>(model.gcons.size());
  count -= static_cast<int>(model.ucons.size());  // one each (docs/theory.md §5f)
  count -= 2 * static_cast<int>(model.ptcvs.size());  // PTCV removes two (docs/theory.md §5d)
  count -= 2 * static_cast<int>(model.cvcvs.size());  // CVCV removes two (docs/theory.md §5e)
  return count;
}

namespace {

// Displacement term `pair` of a coupled equation on joint `joint`: the term's reference is the
// displacement at the data set's configuration, so the equation holds there.
ConstraintEquation::CoupledTerm coupledTerm(const model::Model& model, int joint, int pair,
                                            bool rotation, double scale) {
  const model::Joint& j = model.joints[joint];
  const Frame<double> f[2] = {dataSetFrame(model, j.iMarker), dataSetFrame(model, j.jMarker)};
  ConstraintEquation::CoupledTerm t;
  t.pair = pair;
  t.rotation = rotation;
  t.scale = scale;
  t.reference = rotation ? std::atan2(dot(f[0].a.c[0], f[1].a.c[1]), dot(f[0].a.c[0], f[1].a.c[0]))
                         : dot(f[1].a.c[2], f[0].p - f[1].p);
  return t;
}

// An equation reading the marker pairs of the given joints (pair k = joint k's I and J).
ConstraintEquation coupledEquation(const model::Model& model, const std::vector<int>& joints) {
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::Coupled;
  e.iMarker = model.joints[joints[0]].iMarker;
  e.jMarker = model.joints[joints[0]].jMarker;
  for (size_t k = 1; k < joints.size(); ++k) {
    e.moreMarkers.push_back(model.joints[joints[k]].iMarker);
    e.moreMarkers.push_back(model.joints[joints[k]].jMarker);
  }
  return e;
}

// GEAR (docs/theory.md §5b): the velocity of the contact point P (CV origin) carried by gear k
// relative to the carrier, along z_CV, is c_k q_k' for each displacement q_k of joint k:
// rotation: c = s zCV.(zJ x (P - O_J)); translation: c = s zCV.zJ, with s = +1 when the gear is
// the joint's I part (J on the carrier) and -1 otherwise. Equal velocities integrate to
// c_1 (q_1 - q_1,0) - c_2 (q_2 - q_2,0) = 0, the c_k being constant on the carrier.
ConstraintEquation gearEquation(const model::Model& model, int index) {
  const model::Gear& g = model.gears[index];
  ConstraintEquation e = coupledEquation(model, {g.joints[0], g.joints[1]});
  e.gear = index;
  e.label = "common velocity along Zcv";
  const Frame<double> cv = dataSetFrame(model, g.cvMarker);
  const int carrier = model.markers[g.cvMarker].part;
  using JT = model::JointType;
  for (int k = 0; k < 2; ++k) {
    const model::Joint& j = model.joints[g.joints[k]];
    const double sign = model.markers[j.jMarker].part == carrier ? 1.0 : -1.0;
    const Frame<double> fj = dataSetFrame(model, j.jMarker);
    const double side = k == 0 ? 1.0 : -1.0;
    if (j.type == JT::Revolute || j.type == JT::Cylindrical) {
      const double c = sign * dot(cv.a.c[2], cross(fj.a.c[2], cv.p - fj.p));
      e.terms.push_back(coupledTerm(model, g.joints[k], k, true, side * c));
    }
    if (j.type == JT::Translational || j.type == JT::Cylindrical) {
      const double c = sign * dot(cv.a.c[2], fj.a.c[2]);
      e.terms.push_back(coupledTerm(model, g.joints[k], k, false, side * c));
    }
  }
  return e;
}

// GCON (docs/theory.md §5c): the markers its measures read become the equation's frame slots
// (I first when it is read, so the reaction on I is taken from its own slot); an equation
// needs two slots, so a GCON that reads one marker repeats it (the second slot is unread).
ConstraintEquation generalEquation(const model::Model& model, int index) {
  const model::GeneralConstraint& g = model.gcons[index];
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::General;
  e.gcon = index;
  e.function = &g.function;
  e.label = "FUNCTION=0";
  std::vector<int> markers;
  auto slot = [&markers](int marker) {
    if (marker < 0) return -1;
    for (size_t s = 0; s < markers.size(); ++s)
      if (markers[s] == marker) return static_cast<int>(s);
    markers.push_back(marker);
    return static_cast<int>(markers.size()) - 1;
  };
  const bool readsI = std::any_of(g.function.measures.begin(), g.function.measures.end(),
                                  [&g](const model::Measure& m) {
                                    return m.i == g.iMarker || m.j == g.iMarker ||
                                           m.k == g.iMarker;
                                  });
  if (g.iMarker >= 0 && readsI) slot(g.iMarker);
  for (const model::Measure& m : g.function.measures)
    e.measureSlots.push_back({slot(m.i), slot(m.j), slot(m.k)});
  if (markers.size() == 1) markers.push_back(markers[0]);
  e.iMarker = markers[0];
  e.jMarker = markers[1];
  e.moreMarkers.assign(markers.begin() + 2, markers.end());
  return e;
}

// UCON (docs/theory.md §5f): the distinct body-frame markers of its variables become the
// equation's frame slots, in the order UCOVAR first names them (a UCON of one part repeats its
// marker: an equation has two slots, the second unread).
ConstraintEquation userConstraintEquation(const model::Model& model, int index) {
  const model::UserConstraint& u = model.ucons[index];
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::User;
  e.ucon = index;
  e.userConstraint = u.user.get();
  e.label = "UCOSUB F = 0";
  std::vector<int> markers;
  for (size_t k = 0; k < u.markers.size(); ++k) {
    auto it = std::find(markers.begin(), markers.end(), u.markers[k]);
    if (it == markers.end()) it = markers.insert(markers.end(), u.markers[k]);
    e.measureSlots.push_back({static_cast<int>(it - markers.begin()), u.codes[k], 0});
  }
  if (markers.size() == 1) markers.push_back(markers[0]);
  e.iMarker = markers[0];
  e.jMarker = markers[1];
  e.moreMarkers.assign(markers.begin() + 2, markers.end());
  return e;
}

// Normal equation n (0, 1) of PTCV k (docs/theory.md §5d). The helper axis is the RM axis least
// aligned with the curve's tangents over the whole curve (sampled), so the normals n_1 = h x t,
// n_2 = t x n_1 stay defined and smooth along it; the nearest-point search samples the curve
// 4 times per MATRIX row, at least 64 times.
ConstraintEquation pointCurveEquation(const model::Model& model, int k, int n) {
  const model::PointCurve& p = model.ptcvs[k];
  const model::CurveData& data = model.curves[p.curve];
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::PointCurve;
  e.iMarker = p.iMarker;
  e.jMarker = p.rmMarker;
  e.ptcv = k;
  e.curve = data.curve.get();
  const auto matrix = model.matrixIndex.find(data.matrixId);
  const int rows =
      matrix == model.matrixIndex.end() ? 16 : static_cast<int>(model.matrices[matrix->second].values.rows());
  e.curveSamples = std::max(64, 4 * rows);
  double worst[3] = {0.0, 0.0, 0.0};
  for (int s = 0; s <= e.curveSamples; ++s) {
    const V3<double> t = curveDerivative(*e.curve, -1.0 + 2.0 * s / e.curveSamples, 1);
    const double length = norm(t);
    if (length == 0.0) continue;
    for (int a = 0; a < 3; ++a) worst[a] = std::max(worst[a], std::abs(t[a]) / length);
  }
  e.axisJ = static_cast<int>(std::min_element(worst, worst + 3) - worst);
  e.axisI = n;
  e.label = n == 0 ? "N1.(I-curve)" : "N2.(I-curve)";
  return e;
}

// Samples of a curve's coarse search: 4 per MATRIX row, at least 64.
int curveSamplesOf(const model::Model& model, const model::CurveData& data) {
  const auto matrix = model.matrixIndex.find(data.matrixId);
  const int rows = matrix == model.matrixIndex.end()
                       ? 16
                       : static_cast<int>(model.matrices[matrix->second].values.rows());
  return std::max(64, 4 * rows);
}

// Equation n (0: along the common normal, 1: along z of IRM) of CVCV k (docs/theory.md §5e).
ConstraintEquation curveCurveEquation(const model::Model& model, int k, int n) {
  const model::CurveCurve& c = model.cvcvs[k];
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::CurveCurve;
  e.iMarker = c.iRm;
  e.jMarker = c.jRm;
  e.cvcv = k;
  e.curve = model.curves[c.iCurve].curve.get();
  e.curveSamples = curveSamplesOf(model, model.curves[c.iCurve]);
  e.curveJ = model.curves[c.jCurve].curve.get();
  e.curveSamplesJ = curveSamplesOf(model, model.curves[c.jCurve]);
  e.axisI = n;
  e.label = n == 0 ? "N.(Jcurve-Icurve)" : "Zirm.(Jcurve-Icurve)";
  return e;
}

}  // namespace

std::vector<ConstraintSet::JointInitialCondition> ConstraintSet::jointInitialConditions(
    const model::Model& model) {
  std::vector<JointInitialCondition> out;
  for (int k = 0; k < static_cast<int>(model.joints.size()); ++k) {
    const model::Joint& j = model.joints[k];
    auto add = [&](bool rotation, const std::optional<double>& disp,
                   const std::optional<double>& vel) {
      if (!disp && !vel) return;
      JointInitialCondition ic;
      ic.equation.kind = rotation ? ConstraintEquation::Kind::MotionRotation
                                  : ConstraintEquation::Kind::MotionTranslation;
      ic.equation.axisJ = 2;
      ic.equation.iMarker = j.iMarker;
      ic.equation.jMarker = j.jMarker;
      ic.equation.joint = k;
      ic.equation.label = rotation ? "initial rotation about Zj" : "initial translation along Zj";
      ic.hasDisplacement = disp.has_value();
      ic.displacement = disp.value_or(0.0);
      ic.hasVelocity = vel.has_value();
      ic.velocity = vel.value_or(0.0);
      out.push_back(ic);
    };
    add(true, j.icRotation, j.icRotationVelocity);
    add(false, j.icTranslation, j.icTranslationVelocity);
  }
  return out;
}

ConstraintSet::ConstraintSet(const model::Model& model) {
  using JT = model::JointType;
  for (int k = 0; k < static_cast<int>(model.joints.size()); ++k) {
    const model::Joint& j = model.joints[k];
    const Element el{j.iMarker, j.jMarker, k, -1};
    const bool coincident = j.type == JT::Revolute || j.type == JT::Spherical ||
                            j.type == JT::Universal || j.type == JT::Hooke || j.type == JT::Fixed ||
                            j.type == JT::Convel;
    if (coincident)
      for (int a = 0; a < 3; ++a) eqs_.push_back(point(a, el));
    switch (j.type) {
      case JT::Revolute:
        eqs_.push_back(dotEq(2, 0, el));  // zI stays parallel to zJ
        eqs_.push_back(dotEq(2, 1, el));
        break;
      case JT::Universal:
        eqs_.push_back(dotEq(2, 2, el));  // the two cross-pin axes stay perpendicular
        break;
      case JT::Hooke:
        eqs_.push_back(dotEq(0, 1, el));  // xI and yJ outline the cross piece
        break;
      case JT::Fixed:
        eqs_.push_back(dotEq(2, 0, el));
        eqs_.push_back(dotEq(2, 1, el));
        eqs_.push_back(dotEq(0, 1, el));
        break;
      case JT::Translational:
        eqs_.push_back(dotEq(2, 0, el));
        eqs_.push_back(dotEq(2, 1, el));
        eqs_.push_back(dotEq(0, 1, el));  // no rotation about the common z axis
        eqs_.push_back(along(0, el));     // I origin stays on the zJ line
        eqs_.push_back(along(1, el));
        break;
      case JT::Cylindrical:
        eqs_.push_back(dotEq(2, 0, el));
        eqs_.push_back(dotEq(2, 1, el));
        eqs_.push_back(along(0, el));
        eqs_.push_back(along(1, el));
        break;
      case JT::Convel: {
        ConstraintEquation e = base(ConstraintEquation::Kind::Convel, el);
        e.label = "Xi.Yj+Yi.Xj";
        eqs_.push_back(e);
        break;
      }
      case JT::Planar:
        eqs_.push_back(dotEq(2, 0, el));  // the x-y planes stay parallel
        eqs_.push_back(dotEq(2, 1, el));
        eqs_.push_back(along(2, el));  // and I's origin stays in J's x-y plane
        break;
      case JT::RackPin:
        eqs_.push_back(coupling(ConstraintEquation::Kind::RackPin, 0.5 * j.pitchDiameter, el, model,
                                "Zj.(I-J)-PD/2*rotation"));
        break;
      case JT::Screw:
        eqs_.push_back(coupling(ConstraintEquation::Kind::Screw, j.pitch / (2.0 * std::numbers::pi),
                                el, model, "Zj.(I-J)-PITCH*rotation/2pi"));
        break;
      case JT::Spherical:
        break;
    }
  }
  using PT = model::JPrimType;
  for (int k = 0; k < static_cast<int>(model.jprims.size()); ++k) {
    const model::JPrim& p = model.jprims[k];
    const Element el{p.iMarker, p.jMarker, -1, k};
    switch (p.type) {
      case PT::AtPoint:
        for (int a = 0; a < 3; ++a) eqs_.push_back(point(a, el));
        break;
      case PT::InLine:
        eqs_.push_back(along(0, el));
        eqs_.push_back(along(1, el));
        break;
      case PT::InPlane:
        eqs_.push_back(along(2, el));
        break;
      case PT::Orientation:
        eqs_.push_back(dotEq(2, 0, el));
        eqs_.push_back(dotEq(2, 1, el));
        eqs_.push_back(dotEq(0, 1, el));
        break;
      case PT::ParallelAxes:
        eqs_.push_back(dotEq(2, 0, el));
        eqs_.push_back(dotEq(2, 1, el));
        break;
      case PT::Perpendicular:
        eqs_.push_back(dotEq(2, 2, el));
        break;
    }
  }
  static const char* kMotionLabel[6] = {"X (I rel J, J axes)", "Y (I rel J, J axes)",
                                        "Z (I rel J, J axes)", "B1 (I rel J)",
                                        "B2 (I rel J)",        "B3 (I rel J)"};
  for (int k = 0; k < static_cast<int>(model.motions.size()); ++k) {
    const model::Motion& m = model.motions[k];
    ConstraintEquation e;
    e.iMarker = m.iMarker;
    e.jMarker = m.jMarker;
    e.motion = k;
    if (m.joint >= 0) {
      e.kind = m.rotation ? ConstraintEquation::Kind::MotionRotation
                          : ConstraintEquation::Kind::MotionTranslation;
      e.axisJ = 2;
      e.label = m.rotation ? "rotation about Zj" : "translation along Zj";
    } else if (m.axis < 3) {
      e.kind = ConstraintEquation::Kind::MotionTranslation;
      e.axisJ = m.axis;
      e.label = kMotionLabel[m.axis];
    } else {
      e.kind = ConstraintEquation::Kind::MotionAngle;
      e.axisI = m.axis - 3;
      e.label = kMotionLabel[m.axis];
    }
    eqs_.push_back(e);
  }
  for (int k = 0; k < static_cast<int>(model.couplers.size()); ++k) {
    const model::Coupler& c = model.couplers[k];
    ConstraintEquation e = coupledEquation(model, c.joints);
    e.coupler = k;
    e.label = c.user ? "COUSUB phi = 0" : "sum of scaled joint displacements";
    e.userCoupler = c.user.get();
    for (size_t p = 0; p < c.joints.size(); ++p)
      e.terms.push_back(coupledTerm(model, c.joints[p], static_cast<int>(p), c.rotation[p],
                                    c.scales[p]));
    eqs_.push_back(e);
  }
  for (int k = 0; k < static_cast<int>(model.gears.size()); ++k)
    eqs_.push_back(gearEquation(model, k));
  for (int k = 0; k < static_cast<int>(model.gcons.size()); ++k)
    eqs_.push_back(generalEquation(model, k));
  for (int k = 0; k < static_cast<int>(model.ucons.size()); ++k)
    eqs_.push_back(userConstraintEquation(model, k));
  for (int k = 0; k < static_cast<int>(model.ptcvs.size()); ++k)
    for (int n = 0; n < 2; ++n) eqs_.push_back(pointCurveEquation(model, k, n));
  for (int k = 0; k < static_cast<int>(model.cvcvs.size()); ++k)
    for (int n = 0; n < 2; ++n) eqs_.push_back(curveCurveEquation(model, k, n));
  // PTCV (one) and CVCV (two) curve parameters in element order: their committed values'
  // places in the run state (both equations of an element share them).
  for (ConstraintEquation& e : eqs_) {
    if (e.kind == ConstraintEquation::Kind::PointCurve) e.curveSlot = e.ptcv;
    if (e.kind == ConstraintEquation::Kind::CurveCurve)
      e.curveSlot = static_cast<int>(model.ptcvs.size()) + 2 * e.cvcv;
  }
  curveParameterCount_ = static_cast<int>(model.ptcvs.size() + 2 * model.cvcvs.size());
  // Coupled rotation terms in equation order: their committed angles' places in the run state.
  int slot = 0;
  for (ConstraintEquation& e : eqs_)
    for (ConstraintEquation::CoupledTerm& t : e.terms)
      if (t.rotation) t.slot = slot++;
}

void ConstraintSet::bindCoupledAngles(const double* angles) {
  for (ConstraintEquation& e : eqs_)
    for (ConstraintEquation::CoupledTerm& t : e.terms)
      t.committed = t.slot >= 0 && angles ? angles + t.slot : nullptr;
}

void ConstraintSet::bindCurveParameters(const double* parameters) {
  for (ConstraintEquation& e : eqs_)
    e.warm = e.curveSlot >= 0 && parameters ? parameters + e.curveSlot : nullptr;
}

std::string ConstraintSet::describe(int k, const model::Model& model) const {
  const ConstraintEquation& e = eqs_[k];
  if (e.joint >= 0) {
    const model::Joint& j = model.joints[e.joint];
    return "JOINT/" + std::to_string(j.id) + " (" + model::jointTypeName(j.type) + ") equation " +
           e.label;
  }
  if (e.jprim >= 0) {
    const model::JPrim& p = model.jprims[e.jprim];
    return "JPRIM/" + std::to_string(p.id) + " (" + model::jprimTypeName(p.type) + ") equation " +
           e.label;
  }
  if (e.coupler >= 0)
    return "COUPLER/" + std::to_string(model.couplers[e.coupler].id) + " equation " + e.label;
  if (e.gear >= 0)
    return "GEAR/" + std::to_string(model.gears[e.gear].id) + " equation " + e.label;
  if (e.ptcv >= 0)
    return "PTCV/" + std::to_string(model.ptcvs[e.ptcv].id) + " equation " + e.label;
  if (e.cvcv >= 0)
    return "CVCV/" + std::to_string(model.cvcvs[e.cvcv].id) + " equation " + e.label;
  if (e.ucon >= 0)
    return "UCON/" + std::to_string(model.ucons[e.ucon].id) + " equation " + e.label;
  if (e.gcon >= 0)
    return "GCON/" + std::to_string(model.gcons[e.gcon].id) + " equation " + e.label;
  return "MOTION/" + std::to_string(model.motions[e.motion].id) + " equation " + e.label;
}

}  // namespace openmss::mechanics
