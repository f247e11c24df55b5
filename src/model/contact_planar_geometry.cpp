#include "model/contact_planar_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/curve_projection.hpp"
#include "model/graphics_builder.hpp"

namespace openmss::model {

using language::Statement;

bool readOutlineFloor(const Statement& g, const Model& model, const SourceLocation& where,
                      const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  auto refuse = [&](const std::string& what, const std::string& fix) {
    diags.error(where, subject, graphicsAt(g) + " is an OUTLINE " + what, fix);
    return false;
  };
  const language::Argument* a = g.find("OUTLINE");
  std::vector<int> markers;
  for (const language::Value& v : a ? a->values : std::vector<language::Value>{}) {
    const auto it = model.markerIndex.find(static_cast<long>(v.number));
    if (it == model.markerIndex.end())
      return refuse(
          "naming MARKER/" + std::to_string(static_cast<long>(v.number)) + ", which does not exist",
          "Use the ids of MARKER statements of this data set.");
    markers.push_back(it->second);
  }
  if (markers.size() < 4)
    return refuse("of " + std::to_string(markers.size()) +
                      " markers: a contact face needs a closed polygon of three corners or more",
                  "List the corners and close the polygon by repeating the first marker.");
  const Marker& first = model.markers[markers.front()];
  std::vector<Eigen::Vector3d> corners;  // in the first marker's axes, from its origin
  double reach = 0.0;
  for (int k : markers) {
    const Marker& m = model.markers[k];
    if (m.part != first.part)
      return refuse("whose markers lie on different parts (PART/" +
                        std::to_string(model.parts[first.part].id) + " and PART/" +
                        std::to_string(model.parts[m.part].id) + ")",
                    "Put every marker of an OUTLINE used for contact on one part.");
    corners.push_back(first.orientation.transpose() * (m.position - first.position));
    reach = std::max(reach, corners.back().norm());
  }
  // Closed: the last corner is the first again (the same marker, or one at its position to
  // 1e-9 of the polygon's size); it is then dropped.
  if (markers.back() != markers.front() && corners.back().norm() > 1e-9 * reach)
    return refuse("that is open (its last marker is not at its first)",
                  "Close the polygon: end OUTLINE with the first marker's id again.");
  corners.pop_back();
  // Newell's normal: sum of v_k x v_k+1, along the right-hand rule of the winding, its length
  // twice the area.
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < corners.size(); ++k)
    newell += corners[k].cross(corners[(k + 1) % corners.size()]);
  if (!(newell.norm() > 1e-12 * reach * reach))
    return refuse("enclosing no area", "Give at least three corners that are not in line.");
  const Eigen::Vector3d n = newell.normalized();
  double offPlane = 0.0;
  for (const Eigen::Vector3d& c : corners) offPlane = std::max(offPlane, std::abs(n.dot(c)));
  if (offPlane > 1e-9 * reach)
    return refuse("that is not planar (a corner lies " + std::to_string(offPlane) +
                      " off the plane of the others)",
                  "Place every marker of the OUTLINE in one plane.");
  // The plane's axes in the first marker's: that marker's own when the normal is its z axis,
  // otherwise x the marker's x (or y) made normal to n.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  if (n != Eigen::Vector3d::UnitZ()) {
    const Eigen::Vector3d seed =
        std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d x = (seed - n * n.dot(seed)).normalized();
    axes.col(0) = x;
    axes.col(1) = n.cross(x);
    axes.col(2) = n;
  }
  out.shape = ContactSolid::Shape::Plane;
  out.planeAxes = axes;
  for (const Eigen::Vector3d& c : corners) {
    const Eigen::Vector3d q = axes.transpose() * c;
    out.polygon.emplace_back(q.x(), q.y());
  }
  out.boundingRadius = HUGE_VAL;  // a half-space, as a PLANE: every pair to the narrow phase
  out.marker = markers.front();
  return true;
}

}  // namespace openmss::model

namespace openmss::model {
namespace {

// Coarse samples of a curve's nearest-point search: 4 per MATRIX row, at least 64 (as PTCV's).
int curveSamples(const Model& model, const CurveData& data) {
  const auto matrix = model.matrixIndex.find(data.matrixId);
  const int rows = matrix == model.matrixIndex.end()
                       ? 16
                       : static_cast<int>(model.matrices[matrix->second].values.rows());
  return std::max(64, 4 * rows);
}

bool readCurveGeometry(const Statement& g, const Model& model, const SourceLocation& where,
                       const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const long id = static_cast<long>(graphicsNumber(g, "CID"));
  const CurveData* data = nullptr;
  for (const CurveData& c : model.curves)
    if (c.id == id) data = &c;
  if (!data) {
    diags.error(
        where, subject,
        graphicsAt(g) + " is a CURVE naming CURVE/" + std::to_string(id) + ", which does not exist",
        "Give CID=<id of a CURVE statement>.");
    return false;
  }
  // The curve must lie in its CRM marker's xy-plane: z at every sample within 1e-9 of its size.
  out.curveSamples = curveSamples(model, *data);
  const int n = 4 * out.curveSamples;
  double reach = 0.0, height = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double a = data->curve->minParameter() +
                     (data->curve->maxParameter() - data->curve->minParameter()) * k / n;
    const V3<double> p = curveDerivative(*data->curve, a, 0);
    reach = std::max(reach, std::hypot(p.x, p.y));
    height = std::max(height, std::abs(p.z));
  }
  if (height > 1e-9 * reach) {
    diags.error(where, subject,
                graphicsAt(g) + " is a CURVE leaving its CRM marker's xy-plane (z up to " +
                    std::to_string(height) + "): 2-D contact needs a planar curve",
                "Give the curve's points with z = 0 in the CRM marker's axes.");
    return false;
  }
  out.shape = ContactSolid::Shape::Curve;
  out.curve = data->curve;
  out.boundingRadius = HUGE_VAL;  // its material extends to one side without bound
  out.marker = graphicsMarker(g, "CRM", model, where, subject, diags);
  return true;
}

// A marker's z axis and origin in ground at the data set's configuration.
void groundPlane(const Model& model, int marker, Eigen::Vector3d& z, Eigen::Vector3d& o) {
  const Marker& m = model.markers[marker];
  const Part& p = model.parts[m.part];
  z = p.orientation * m.orientation.col(2);
  o = p.position + p.orientation * m.position;
}

std::string named(const ContactSolid& s) { return "GRAPHICS/" + std::to_string(s.graphicsId); }

// IFLIP_GEOMETRY or JFLIP_GEOMETRY: flip the named geometries of `side`.
bool readFlips(const Statement& s, const char* name, const char* sideName,
               std::vector<ContactSolid>& side, Diagnostics& diags) {
  const language::Argument* a = s.find(name);
  if (!a) return true;
  bool ok = true;
  for (const language::Value& v : a->values) {
    const long id = static_cast<long>(v.number);
    ContactSolid* hit = nullptr;
    for (ContactSolid& x : side)
      if (x.graphicsId == id) hit = &x;
    if (!hit ||
        (hit->shape != ContactSolid::Shape::Circle && hit->shape != ContactSolid::Shape::Curve)) {
      diags.error(v.where, s.subject(),
                  std::string(name) + " names GRAPHICS/" + std::to_string(id) + ", which is " +
                      (hit ? "not a CIRCLE, ARC or CURVE (only those have a side to flip)"
                           : std::string("not in ") + sideName),
                  std::string("Name CIRCLE, ARC or CURVE geometries of ") + sideName + " only.");
      ok = false;
      continue;
    }
    hit->flipped = true;
    if (hit->shape == ContactSolid::Shape::Circle) hit->boundingRadius = HUGE_VAL;  // a hole
  }
  return ok;
}

// The pair a (I) and b (J) of 2-D geometries is one planar_narrow_phase.hpp covers; one located
// message otherwise.
bool planarPairSupported(const Statement& s, const ContactSolid& a, const ContactSolid& b,
                         Diagnostics& diags) {
  using S = ContactSolid::Shape;
  const std::string pair = named(a) + " against " + named(b);
  auto refuse = [&](const std::string& why, const std::string& fix) {
    diags.error(s.where, s.subject(), pair + ": " + why, fix);
    return false;
  };
  const bool holeA = a.shape == S::Circle && a.flipped, holeB = b.shape == S::Circle && b.flipped;
  if (a.shape == S::Point && b.shape == S::Point)
    return refuse("two POINT geometries cannot touch", "Make one of them a CIRCLE or a CURVE.");
  if (a.shape == S::Curve && b.shape == S::Curve)
    return refuse("curve against curve is not simulated (a CIRCLE, ARC or POINT meets a CURVE)",
                  "Model one side as CIRCLE, ARC or POINT geometries, or use CVCV.");
  if (holeA && holeB)
    return refuse("two flipped circles (holes) always overlap", "Flip at most one of them.");
  if ((holeA || holeB) && (a.shape == S::Curve || b.shape == S::Curve))
    return refuse("a flipped circle (a hole) against a CURVE is not simulated",
                  "Flip the curve instead, or remove the circle from IFLIP_GEOMETRY/"
                  "JFLIP_GEOMETRY.");
  if (holeA || holeB) {
    const ContactSolid& hole = holeA ? a : b;
    const ContactSolid& disc = holeA ? b : a;
    const double r = disc.shape == S::Point ? 0.0 : disc.size[0];
    if (!(r < hole.size[0]))
      return refuse("the disc (radius " + std::to_string(r) +
                        ") does not fit in the hole (radius " + std::to_string(hole.size[0]) + ")",
                    "Give the inner circle a smaller RADIUS than the flipped one.");
  }
  return true;
}

}  // namespace

bool readPlanarGeometry(const Statement& g, const std::string& kind, const Model& model,
                        const SourceLocation& where, const std::string& subject, Diagnostics& diags,
                        ContactSolid& out) {
  if (kind == "CURVE") return readCurveGeometry(g, model, where, subject, diags, out);
  if (kind == "POINT") {
    out.shape = ContactSolid::Shape::Point;
    out.marker = graphicsMarker(g, "RM", model, where, subject, diags);
    return true;
  }
  const double r = graphicsNumber(g, "RADIUS");
  const double sweep = kind == "ARC" && g.has("RANGLE") ? graphicsNumber(g, "RANGLE") : 2.0 * M_PI;
  if (!(r > 0.0) || sweep == 0.0) {
    diags.error(where, subject,
                graphicsAt(g) + " is a " + kind + " with RADIUS = " + std::to_string(r) +
                    (kind == "ARC" ? " and RANGLE = " + std::to_string(sweep) : "") +
                    ": contact needs a circle",
                "Give RADIUS > 0 (and RANGLE different from 0).");
    return false;
  }
  out.shape = ContactSolid::Shape::Circle;
  out.size = Eigen::Vector3d(r, sweep, 0.0);
  out.boundingRadius = r;
  out.marker = graphicsMarker(g, "CM", model, where, subject, diags);
  return true;
}

bool checkPlanarContact(const Statement& s, Contact& c, const Model& model, Diagnostics& diags) {
  bool ok = readFlips(s, "IFLIP_GEOMETRY", "IGEOM", c.iSolids, diags);
  ok = readFlips(s, "JFLIP_GEOMETRY", "JGEOM", c.jSolids, diags) && ok;
  const ContactSolid *flat = nullptr, *solid = nullptr;
  for (const std::vector<ContactSolid>* side : {&c.iSolids, &c.jSolids})
    for (const ContactSolid& x : *side) (planarShape(x.shape) ? flat : solid) = &x;
  if (!flat || !ok) return ok;
  if (solid) {
    diags.error(s.where, s.subject(),
                named(*flat) + " is 2-D geometry and " + named(*solid) +
                    " a 3-D solid: a CONTACT does not mix them",
                "Use CIRCLE, ARC, POINT and CURVE on both sides (2-D contact), or solids on both "
                "sides.");
    return false;
  }
  for (const ContactSolid& a : c.iSolids)
    for (const ContactSolid& b : c.jSolids) ok = planarPairSupported(s, a, b, diags) && ok;
  // One plane: every circle's and curve's marker z axis along the first one's (1e-6 rad), and
  // every marker origin in its plane (1e-6 of the distance, at least 1e-6 model units).
  const ContactSolid* ref = nullptr;
  for (const std::vector<ContactSolid>* side : {&c.jSolids, &c.iSolids})
    for (const ContactSolid& x : *side)
      if (!ref && x.shape != ContactSolid::Shape::Point) ref = &x;
  if (!ref) return ok;  // two points: refused above
  Eigen::Vector3d z0, o0, z, o;
  groundPlane(model, ref->marker, z0, o0);
  for (const std::vector<ContactSolid>* side : {&c.iSolids, &c.jSolids})
    for (const ContactSolid& x : *side) {
      groundPlane(model, x.marker, z, o);
      const double tilt = x.shape == ContactSolid::Shape::Point ? 0.0 : z.cross(z0).norm();
      const double offset = std::abs(z0.dot(o - o0));
      if (tilt <= 1e-6 && offset <= 1e-6 * std::max(1.0, (o - o0).norm())) continue;
      diags.error(s.where, s.subject(),
                  named(x) + " and " + named(*ref) + " are not in one plane (normals " +
                      std::to_string(tilt) + " rad apart, " + std::to_string(offset) +
                      " off the plane)",
                  "Place the 2-D geometries of a CONTACT in one plane: their markers' xy-planes "
                  "(a POINT's origin) coincide.");
      ok = false;
    }
  return ok;
}

}  // namespace openmss::model
