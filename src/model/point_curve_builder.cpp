#include "model/point_curve_builder.hpp"

#include <cmath>
#include <string>

#include "common/curve_projection.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Statement;

// A marker's origin in ground at the data set's configuration.
Eigen::Vector3d dataSetPosition(const Model& model, int marker) {
  const Marker& mk = model.markers[marker];
  const Part& part = model.parts[mk.part];
  return part.position + part.orientation * mk.position;
}

// JFLOAT: any marker (FLOATING or not) of RM's part; nothing reads its pose.
int contactMarker(const Statement& s, const Model& model, int rm, Diagnostics& diags) {
  StatementArguments a(s, diags);
  const auto id = a.id("JFLOAT");
  if (!id) {
    if (!s.has("JFLOAT")) a.require("JFLOAT", "<marker id>");
    return -1;
  }
  const auto it = model.markerIndex.find(*id);
  if (it == model.markerIndex.end()) {
    diags.error(
        s.find("JFLOAT")->where, s.subject(),
        "JFLOAT=" + std::to_string(*id) + ": marker " + std::to_string(*id) + " does not exist",
        "Use the id of a MARKER statement of this data set.");
    return -1;
  }
  if (rm >= 0 && model.markers[it->second].part != model.markers[rm].part) {
    diags.error(s.find("JFLOAT")->where, s.subject(),
                "JFLOAT=" + std::to_string(*id) +
                    " is not on the part of RM, which carries the "
                    "curve",
                "Put the JFLOAT marker on RM's part (a FLOATING marker of that part).");
    return -1;
  }
  return it->second;
}

void buildPointCurve(const Statement& s, Model& model, Diagnostics& diags) {
  PointCurve p;
  p.id = *s.id;
  p.where = s.where;
  p.iMarker = markerReference(model, s, "I", diags);
  p.rmMarker = markerReference(model, s, "RM", diags);
  p.jFloat = contactMarker(s, model, p.rmMarker, diags);
  StatementArguments a(s, diags);
  const auto curveId = a.id("CURVE");
  if (!curveId && !s.has("CURVE")) a.require("CURVE", "<curve id>");
  if (curveId) {
    const auto it = model.curveIndex.find(*curveId);
    if (it == model.curveIndex.end()) {
      diags.error(s.find("CURVE")->where, s.subject(),
                  "CURVE/" + std::to_string(*curveId) + " does not exist or could not be built",
                  "Use the id of a CURVE statement (MATRIX curve) of this data set.");
    } else {
      p.curve = it->second;
    }
  }
  if (s.has("VEL"))
    diags.error(s.find("VEL")->where, s.subject(),
                "VEL (the initial speed along the curve) is not supported yet",
                "Remove VEL and give the initial velocity of I's part (PART VX/VY/VZ) instead.");
  for (const char* name : {"DISP", "ICM"})
    if (s.has(name))
      diags.warning(s.find(name)->where, s.subject(),
                    std::string(name) +
                        " has no effect: the contact point is always the curve "
                        "point nearest to I (docs/theory.md §5d)",
                    std::string("Remove ") + name + ".");
  if (p.iMarker < 0 || p.rmMarker < 0 || p.jFloat < 0 || p.curve < 0) return;
  if (model.markers[p.iMarker].part == model.markers[p.rmMarker].part) {
    diags.error(s.where, s.subject(), "I and RM are on the same part",
                "The point (I) and the curve (RM) must be on different parts.");
    return;
  }
  // I should start on the curve: the initial-conditions analysis would move it there, which
  // ADAMS does too, but a large gap usually means a wrong RM or curve.
  const Marker& rm = model.markers[p.rmMarker];
  const Eigen::Matrix3d axes = model.parts[rm.part].orientation * rm.orientation;
  const Eigen::Vector3d q =
      axes.transpose() * (dataSetPosition(model, p.iMarker) - dataSetPosition(model, p.rmMarker));
  const BSplineCurve& curve = *model.curves[p.curve].curve;
  const V3<double> q3(q.x(), q.y(), q.z());
  const double alpha = nearestCurveParameter(curve, q3, 256);
  const V3<double> c = curveDerivative(curve, alpha, 0);
  const double gap = norm(c - q3);
  double size = 0.0;
  for (int k = 0; k <= 16; ++k)
    size = std::max(size, norm(curveDerivative(curve, -1.0 + k / 8.0, 0) - c));
  if (gap > 1e-3 * std::max(size, 1e-12)) {
    diags.warning(s.where, s.subject(),
                  "marker I starts " + std::to_string(gap) + " away from CURVE/" +
                      std::to_string(model.curves[p.curve].id) +
                      " (in RM's frame); the initial-conditions analysis will move it onto the "
                      "curve",
                  "Place I (or the curve's points) so that I lies on the curve.");
  }
  model.ptcvs.push_back(p);
}

}  // namespace

void buildPointCurves(const std::vector<const Statement*>& statements, Model& model,
                      Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildPointCurve(*s, model, diags);
}

}  // namespace openmss::model
