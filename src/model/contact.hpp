#pragma once
// CONTACT elements of the Model (docs/theory.md §6c): the solid geometries of each side, read
// from GRAPHICS statements, and the normal and friction laws. Built by contact_builder.cpp;
// the forces are computed by mechanics/contact/.

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/bspline_curve.hpp"
#include "common/source_location.hpp"
#include "model/triangle_mesh.hpp"
#include "user/contact_interfaces.hpp"

namespace openmss::model {

// One solid from a GRAPHICS statement, fixed to the part of its reference marker.
struct ContactSolid {
  enum class Shape {
    Sphere,  // ELLIPSOID with XSCALE = YSCALE = ZSCALE (the diameter): centre at the CM marker
    Box,     // BOX: CORNER marker, extents X, Y, Z along its axes (each may be negative)
    // CYLINDER (RADIUS) or FRUSTUM (BOTTOM, TOP): CM marker at the centre of the bottom disc,
    // LENGTH along its z axis (negative: along -z); a cylinder is a frustum with equal radii.
    Frustum,
    // PLANE: the half-space below the RM marker's xy-plane (z < 0 in its axes), limited
    // sideways to XMIN..XMAX, YMIN..YMAX along its x and y axes when they are given. A closed
    // planar OUTLINE is a plane too: through its first marker's origin, its normal by the
    // polygon's winding (planeAxes), limited sideways to the polygon.
    Plane,
    // ELLIPSOID with unequal scales: semi-axes XSCALE/2, YSCALE/2, ZSCALE/2 along the CM
    // marker's axes (narrow phase: FCL, or analytic against a PLANE; theory §6c, "FCL").
    Ellipsoid,
    // TORUS: centre circle of radius MAJOR_RADIUS in the CM marker's xy-plane, tube radius
    // MINOR_RADIUS (analytic against a PLANE, a sphere, a BOX, a mesh or a TORUS only).
    Torus,
    // EXTERNAL shell (.shl or .stl) read into `mesh`, in the RM marker's axes.
    Mesh,
    // 2-D geometry of planar contact (theory §6c, "2-D contact"), in the marker's xy-plane:
    // CIRCLE or ARC about the CM marker's z axis (radius in size[0], swept angle from its x
    // axis in size[1]: 2 pi for a CIRCLE), a disc, or a hole when `flipped`;
    Circle,
    // POINT: the RM marker's origin;
    Point,
    // CURVE: the CURVE statement `curve` in the CRM marker's xy-plane, its material on the
    // left of the direction of increasing parameter (on the right when `flipped`).
    Curve,
  };
  Shape shape = Shape::Sphere;
  long graphicsId = 0;
  int marker = -1;  // the reference marker (CM or CORNER)
  int part = -1;
  // Sphere: radius in x. Box: the extents X, Y, Z. Frustum: bottom radius in x, top radius in
  // y, LENGTH in z. Ellipsoid: the semi-axes. Torus: major radius in x, minor in y.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::shared_ptr<const TriangleMesh> mesh;  // Mesh only
  // Plane: XMIN, XMAX, YMIN, YMAX (infinite when not given).
  Eigen::Vector4d bounds{-HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL};
  // Plane from an OUTLINE (theory §6c, "OUTLINE floors"): the plane's axes in the reference
  // marker's axes (columns; z the normal) and the polygon's corners in them (x, y). An empty
  // polygon is a PLANE statement's: the marker's own axes and the rectangle above.
  Eigen::Matrix3d planeAxes = Eigen::Matrix3d::Identity();
  std::vector<Eigen::Vector2d> polygon;
  // 2-D geometry: the material side reversed (IFLIP_GEOMETRY / JFLIP_GEOMETRY name it).
  bool flipped = false;
  std::shared_ptr<const BSplineCurve> curve;  // Curve only
  int curveSamples = 64;                      // Curve: coarse samples of its nearest-point search
  // Radius of a sphere about the reference marker's origin that holds the solid: the
  // bounding test that skips far pairs before the narrow phase (theory §6c, "Broad phase").
  double boundingRadius = 0.0;
  SourceLocation where;
};

// Two frustums touch side against side through their sections perpendicular to the axes
// (theory §6c, "Frustum against frustum"): a depth off by the factor 1/cos(half-angle) of the
// sides' slope, at most 0.4 % up to this half-angle (5 degrees); steeper pairs go to FCL.
inline constexpr double kMaxFrustumPairHalfAngle = 5.0 * 3.14159265358979323846 / 180.0;

// Whether the shape is a 2-D geometry of planar contact (CIRCLE, ARC, POINT, CURVE).
inline bool planarShape(ContactSolid::Shape s) {
  return s == ContactSolid::Shape::Circle || s == ContactSolid::Shape::Point ||
         s == ContactSolid::Shape::Curve;
}

// Half-angle of a frustum's side (0 for a cylinder), radians.
inline double frustumHalfAngle(const ContactSolid& s) {
  return std::atan(std::abs(s.size[0] - s.size[1]) / std::abs(s.size[2]));
}

// Whether the pair goes to the FCL module (the dispatch of mechanics/contact/narrow_phase.hpp
// and curved_narrow_phase.hpp): 3-D solids, one an ELLIPSOID of unequal scales or an EXTERNAL
// shell, or two frustums steeper than kMaxFrustumPairHalfAngle, neither a PLANE nor a TORUS
// (those are analytic). The builder opens the module for such a pair (docs/architecture.md,
// "FCL module").
bool libraryPair(const ContactSolid& a, const ContactSolid& b);

struct Contact {
  // User: NORMAL_FUNCTION=USER(...), the force from CNFSUB (normalRoutine).
  enum class NormalLaw { Impact, Poisson, User };
  enum class Friction { Off, On, DynamicsOnly };
  long id = 0;
  std::vector<ContactSolid> iSolids, jSolids;
  int iPart = -1, jPart = -1;
  // The reference markers of the first I and J solids: the element's I and J markers (its
  // force on I acts through iMarker's origin, its reaction on J through jMarker's).
  int iMarker = -1, jMarker = -1;
  NormalLaw law = NormalLaw::Impact;
  // IMPACT: F = k d^e + STEP(d, 0, 0, DMAX, c) d', never pulling (d the penetration).
  double stiffness = 0.0, damping = 0.0, dmax = 0.0, exponent = 1.0;
  // POISSON: F = p d (approach) and e^2 p d (separation), blended over the normal
  // transition velocity (theory §6c).
  double penalty = 0.0, restitution = 1.0;
  Friction friction = Friction::Off;
  double muStatic = 0.0, muDynamic = 0.0;
  double stictionVelocity = 0.0, frictionVelocity = 0.0;
  // NORMAL_FUNCTION=USER(...) (CNFSUB) and FRICTION_FUNCTION=USER(...) (CFFSUB), or null: the
  // user laws of docs/user-subroutines.md, "CNFSUB and CFFSUB" (contact_user_laws.cpp).
  std::shared_ptr<const user::ContactNormalRoutine> normalRoutine;
  std::shared_ptr<const user::ContactFrictionRoutine> frictionRoutine;
  // Cleared to skip the element (the generic ACTIVATE/DEACTIVATE mechanism sets it).
  bool active = true;
  SourceLocation where;
};

}  // namespace openmss::model
