#pragma once
// GRAPHICS geometry of a model (docs/viewer.md, "Geometry"): what the viewer draws. Every drawn
// GRAPHICS statement becomes one Graphic fixed to the part of its reference marker; its frame and
// points are in that part's body frame (origin at the CM, CM-marker axes, as Marker poses are), so
// a part pose from the results places it. Built by graphics_builder.cpp on demand (the Model does
// not hold them: no analysis needs them); CONTACT reads its solids from the same statements
// (contact_builder.cpp).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/source_location.hpp"

namespace openmss::model {

struct Graphic {
  enum class Kind {
    Cylinder,   // CM at the centre of the bottom disc, LENGTH along z, RADIUS, RANGLE, SIDES
    Frustum,    // as CYLINDER with BOTTOM radius at CM and TOP radius at z = LENGTH
    Box,        // CORNER marker at one corner, extents X, Y, Z along its axes (signed)
    Ellipsoid,  // CM at the centre, XSCALE, YSCALE, ZSCALE the diameters along its axes
    Outline,    // polyline through the origins of the OUTLINE markers, in order
    Arc,        // CM at the centre, RADIUS, RANGLE from the CM x axis about z, SEG segments
    Circle,     // CM at the centre, RADIUS, in the CM x-y plane, SEG segments
  };
  long id = 0;
  Kind kind = Kind::Cylinder;
  int marker = -1;  // the reference marker (CM or CORNER); -1 for OUTLINE
  int part = -1;    // the part of the reference marker (of the first OUTLINE marker)
  // The reference marker's frame in the part's body frame.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  double radius = 0.0;             // CYLINDER, ARC, CIRCLE
  double length = 0.0;             // CYLINDER, FRUSTUM (signed: negative grows along -z)
  double top = 0.0, bottom = 0.0;  // FRUSTUM radii
  double rangle = 0.0;             // CYLINDER, FRUSTUM, ARC: swept angle, radians (2 pi default)
  int sides = 0;                   // CYLINDER, FRUSTUM: facets; ARC, CIRCLE: SEG
  Eigen::Vector3d extents = Eigen::Vector3d::Zero();  // BOX X Y Z; ELLIPSOID diameters
  // OUTLINE: the marker of each point (indices into Model::markers); the points may lie on
  // different parts (the line then stretches as they move).
  std::vector<int> outline;
  SourceLocation where;
};

const char* graphicKindName(Graphic::Kind kind);

}  // namespace openmss::model
