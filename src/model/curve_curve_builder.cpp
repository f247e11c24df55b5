#include "model/curve_curve_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/curve_contact.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Statement;

// IFLOAT / JFLOAT: any marker (FLOATING or not) of the RM marker's part; nothing reads its pose.
int floatMarker(const Statement& s, const char* name, const char* rmName, const Model& model,
                int rm, Diagnostics& diags) {
  StatementArguments a(s, diags);
  const auto id = a.id(name);
  if (!id) {
    if (!s.has(name)) a.require(name, "<marker id>");
    return -1;
  }
  const auto it = model.markerIndex.find(*id);
  if (it == model.markerIndex.end()) {
    diags.error(s.find(name)->where, s.subject(),
                std::string(name) + "=" + std::to_string(*id) + ": marker " + std::to_string(*id) +
                    " does not exist",
                "Use the id of a MARKER statement of this data set.");
    return -1;
  }
  if (rm >= 0 && model.markers[it->second].part != model.markers[rm].part) {
    diags.error(s.find(name)->where, s.subject(),
                std::string(name) + "=" + std::to_string(*id) + " is not on the part of " + rmName +
                    ", which carries its curve",
                std::string("Put the ") + name + " marker on " + rmName +
                    "'s part (a FLOATING marker of that part).");
    return -1;
  }
  return it->second;
}

// ICURVE / JCURVE: an existing CURVE lying in the x-y plane of its RM (ADAMS: z components 0).
int planarCurve(const Statement& s, const char* name, const Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  const auto id = a.id(name);
  if (!id) {
    if (!s.has(name)) a.require(name, "<curve id>");
    return -1;
  }
  const auto it = model.curveIndex.find(*id);
  if (it == model.curveIndex.end()) {
    diags.error(s.find(name)->where, s.subject(),
                "CURVE/" + std::to_string(*id) + " does not exist or could not be built",
                "Use the id of a CURVE statement (MATRIX curve) of this data set.");
    return -1;
  }
  const BSplineCurve& curve = *model.curves[it->second].curve;
  double size = 0.0, worstZ = 0.0;
  const V3<double> first = curveDerivative(curve, -1.0, 0);
  for (int k = 0; k <= 64; ++k) {
    const V3<double> c = curveDerivative(curve, -1.0 + k / 32.0, 0);
    size = std::max(size, norm(c - first));
    worstZ = std::max(worstZ, std::abs(c.z));
  }
  if (worstZ > 1e-9 * std::max(size, 1e-12)) {
    diags.error(s.find(name)->where, s.subject(),
                "CURVE/" + std::to_string(*id) + " is not planar: its z components reach " +
                    std::to_string(worstZ) + " (a CVCV curve lies in the x-y plane of its RM)",
                "Give the curve's points with z = 0 and orient the RM marker so that its x-y "
                "plane is the plane of contact.");
    return -1;
  }
  return it->second;
}

// A marker's pose in ground at the data set's configuration, as a Frame-like pair.
void dataSetPose(const Model& model, int marker, V3<double>& p, M3<double>& a) {
  const Marker& mk = model.markers[marker];
  const Part& part = model.parts[mk.part];
  const Eigen::Vector3d o = part.position + part.orientation * mk.position;
  p = V3<double>::from(o);
  a = M3<double>::from(Eigen::Matrix3d(part.orientation * mk.orientation));
}

// Samples of a curve's nearest-pair search: 4 per MATRIX row, at least 64 (as PTCV).
int samplesOf(const Model& model, int curve) {
  const auto m = model.matrixIndex.find(model.curves[curve].matrixId);
  const int rows =
      m == model.matrixIndex.end() ? 16 : static_cast<int>(model.matrices[m->second].values.rows());
  return std::max(64, 4 * rows);
}

void buildCurveCurve(const Statement& s, Model& model, Diagnostics& diags) {
  CurveCurve c;
  c.id = *s.id;
  c.where = s.where;
  c.iRm = markerReference(model, s, "IRM", diags);
  c.jRm = markerReference(model, s, "JRM", diags);
  c.iFloat = floatMarker(s, "IFLOAT", "IRM", model, c.iRm, diags);
  c.jFloat = floatMarker(s, "JFLOAT", "JRM", model, c.jRm, diags);
  c.iCurve = planarCurve(s, "ICURVE", model, diags);
  c.jCurve = planarCurve(s, "JCURVE", model, diags);
  for (const char* name : {"IVEL", "JVEL"})
    if (s.has(name))
      diags.error(s.find(name)->where, s.subject(),
                  std::string(name) + " (the initial speed along the curve) is not supported yet",
                  std::string("Remove ") + name +
                      " and give the initial velocities of the parts (PART VX.., WX..) instead.");
  for (const char* name : {"IDISP", "JDISP", "IICM", "JICM"})
    if (s.has(name))
      diags.warning(s.find(name)->where, s.subject(),
                    std::string(name) +
                        " has no effect: the contact points are always the pair with a common "
                        "normal nearest to each other (docs/theory.md §5e)",
                    std::string("Remove ") + name + ".");
  if (c.iRm < 0 || c.jRm < 0 || c.iFloat < 0 || c.jFloat < 0 || c.iCurve < 0 || c.jCurve < 0)
    return;
  if (model.markers[c.iRm].part == model.markers[c.jRm].part) {
    diags.error(s.where, s.subject(), "IRM and JRM are on the same part",
                "The two curves (IRM, JRM) must be on different parts.");
    return;
  }
  V3<double> pi, pj;
  M3<double> ai, aj;
  dataSetPose(model, c.iRm, pi, ai);
  dataSetPose(model, c.jRm, pj, aj);
  // The two RM x-y planes must be one plane (ADAMS: the curves lie in the same plane).
  const double tilt = norm(cross(ai.c[2], aj.c[2]));
  const double offset = std::abs(dot(ai.c[2], pj - pi));
  const BSplineCurve& ci = *model.curves[c.iCurve].curve;
  const BSplineCurve& cj = *model.curves[c.jCurve].curve;
  double size = 0.0;
  const V3<double> first = curveDerivative(ci, -1.0, 0);
  for (int k = 0; k <= 16; ++k)
    size = std::max(size, norm(curveDerivative(ci, -1.0 + k / 8.0, 0) - first));
  if (tilt > 1e-6 || offset > 1e-6 * std::max(size, 1e-12)) {
    diags.error(s.where, s.subject(),
                "the x-y planes of IRM and JRM are not one plane (z axes at an angle of " +
                    std::to_string(std::asin(std::min(1.0, tilt))) + " rad, origins " +
                    std::to_string(offset) + " apart along z of IRM)",
                "Orient IRM and JRM so that their z axes are parallel and their origins lie in "
                "one plane normal to them: both curves must lie in the plane of contact.");
    return;
  }
  // The curves should start in contact: the initial-conditions analysis would close a gap, but
  // a large one usually means a wrong RM marker or curve.
  const std::array<double, 2> gap = curveCurveResiduals(ci, samplesOf(model, c.iCurve), cj,
                                                        samplesOf(model, c.jCurve), pi, ai, pj, aj);
  if (std::abs(gap[0]) > 1e-3 * std::max(size, 1e-12)) {
    diags.warning(s.where, s.subject(),
                  "the curves start " + std::to_string(std::abs(gap[0])) +
                      " apart along their common normal; the initial-conditions analysis will "
                      "bring them into contact",
                  "Place the parts (or the curves' points) so that CURVE/" +
                      std::to_string(model.curves[c.iCurve].id) + " and CURVE/" +
                      std::to_string(model.curves[c.jCurve].id) + " touch.");
  }
  model.cvcvs.push_back(c);
}

}  // namespace

void buildCurveCurves(const std::vector<const Statement*>& statements, Model& model,
                      Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildCurveCurve(*s, model, diags);
}

}  // namespace openmss::model
