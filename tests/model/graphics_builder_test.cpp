// GRAPHICS geometry (model/graphics_builder.cpp, docs/viewer.md "Geometry"):
// - every drawn kind with its sizes, its reference marker's frame expressed in the part's body
//   frame (CM origin, CM-marker axes), checked against frames worked out by hand;
// - the piston example's five cylinders, on the parts and at the frames its comments give;
// - bad data (a missing marker or LENGTH, a negative radius) one located error each; zero sizes
//   are accepted (real data sets have discs: CYLINDERs of LENGTH 0); the kinds not drawn one
//   warning per kind, naming it, with the count.

#include "model/graphics_builder.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "support/built_model.hpp"

namespace openmss {
namespace {

using model::Graphic;

struct Built {
  testing::BuiltModel b;
  std::vector<Graphic> graphics;
  Diagnostics diags;
};

Built build(const std::string& text) {
  Built out;
  out.b = testing::buildModelFromText(text, "graphics.adm");
  language::Dataset dataset;
  language::readDatasetText(text, "graphics.adm", dataset, out.diags);
  out.graphics = model::buildGraphics(dataset, out.b.model, out.diags);
  return out;
}

// Part 2's CM marker sits at (1, 2, 3) turned 90 degrees about z (its x axis is global y), so a
// point p given in part coordinates (the LPRF, here ground's axes) is Rz(-90)(p - (1,2,3)) in
// the body frame: (x, y, z) -> (y - 2, -(x - 1), z - 3).
const char* kDeck =
    "graphics\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0, 0, 5\n"
    "PART/2, MASS=1, CM=20, IP=1, 1, 1\n"
    "MARKER/20, PART=2, QP=1, 2, 3, REULER=90D, 0, 0\n"
    "MARKER/21, PART=2, QP=4, 2, 3\n"
    "MARKER/22, PART=2, QP=1, 5, 3, REULER=0, 90D, 0\n"
    "GRAPHICS/1, CYLINDER, CM=21, LENGTH=-2, RADIUS=0.5, SIDES=12, RANGLE=180D\n"
    "GRAPHICS/2, FRUSTUM, CM=22, LENGTH=3, TOP=0.2, BOTTOM=0.6\n"
    "GRAPHICS/3, BOX, CORNER=20, X=1, Y=-2, Z=3\n"
    "GRAPHICS/4, ELLIPSOID, CM=20, XSCALE=1, YSCALE=2, ZSCALE=3\n"
    "GRAPHICS/5, OUTLINE=10, 21, 11\n"
    "GRAPHICS/6, ARC, CM=21, RADIUS=2, RANGLE=90D, SEG=8\n"
    "GRAPHICS/7, CIRCLE, CM=10, RADIUS=1.5\n"
    "GRAPHICS/11, CYLINDER, CM=10, LENGTH=0, RADIUS=1\n"
    "GRAPHICS/8, POINT, CM=20\n"
    "GRAPHICS/9, FORCE, ETYPE=SFORCE, EID=1, EMARKER=20\n"
    "GRAPHICS/10, FORCE, ETYPE=SFORCE, EID=1, EMARKER=20\n"
    "END\n";

// Tolerance: the frames come from sines and cosines of 90 degrees (exactSinCos gives exact 0
// and 1) and one subtraction: 1e-15 allows for the last bit of a product.
constexpr double kTol = 1e-15;

TEST(GraphicsBuilder, EveryDrawnKindWithItsFrameInTheBodyFrame) {
  const Built t = build(kDeck);
  ASSERT_TRUE(t.b.ok) << ::testing::PrintToString(t.b.messages());
  // POINT and the two FORCE graphics are not drawn; the LENGTH 0 cylinder is (a disc).
  ASSERT_EQ(t.graphics.size(), 8u);
  EXPECT_EQ(t.graphics[7].id, 11);
  const Graphic& cyl = t.graphics[0];
  EXPECT_EQ(cyl.kind, Graphic::Kind::Cylinder);
  EXPECT_EQ(t.b.model.parts[cyl.part].id, 2);
  EXPECT_TRUE(cyl.position.isApprox(Eigen::Vector3d(0, -3, 0), kTol)) << cyl.position.transpose();
  // Marker 21 has its part's axes; the body frame is turned +90 about z, so in body axes the
  // marker's x axis (global x) is body -y.
  EXPECT_NEAR(cyl.orientation(1, 0), -1.0, kTol);
  EXPECT_EQ(cyl.length, -2.0);
  EXPECT_EQ(cyl.radius, 0.5);
  EXPECT_EQ(cyl.sides, 12);
  EXPECT_NEAR(cyl.rangle, std::numbers::pi, 1e-15);
  const Graphic& fr = t.graphics[1];
  EXPECT_EQ(fr.kind, Graphic::Kind::Frustum);
  EXPECT_TRUE(fr.position.isApprox(Eigen::Vector3d(3, 0, 0), kTol)) << fr.position.transpose();
  EXPECT_EQ(fr.top, 0.2);
  EXPECT_EQ(fr.bottom, 0.6);
  EXPECT_EQ(fr.sides, 20);  // the default (docs/viewer.md)
  EXPECT_NEAR(fr.rangle, 2 * std::numbers::pi, 1e-15);
  // Marker 22's z axis is -global y after THETA=90D about x: in body axes (turned +90 about z)
  // that is -x.
  EXPECT_TRUE(fr.orientation.col(2).isApprox(Eigen::Vector3d(-1, 0, 0), kTol)) << fr.orientation;
  const Graphic& box = t.graphics[2];
  EXPECT_EQ(box.kind, Graphic::Kind::Box);
  EXPECT_TRUE(box.position.isZero(kTol));
  EXPECT_TRUE(box.orientation.isIdentity(kTol));  // the CM marker is the body frame
  EXPECT_EQ(box.extents, Eigen::Vector3d(1, -2, 3));
  EXPECT_EQ(t.graphics[3].kind, Graphic::Kind::Ellipsoid);
  EXPECT_EQ(t.graphics[3].extents, Eigen::Vector3d(1, 2, 3));
  const Graphic& outline = t.graphics[4];
  EXPECT_EQ(outline.kind, Graphic::Kind::Outline);
  ASSERT_EQ(outline.outline.size(), 3u);  // two ground markers and one on part 2
  EXPECT_EQ(t.b.model.markers[outline.outline[1]].id, 21);
  EXPECT_EQ(t.b.model.parts[outline.part].id, 1);
  EXPECT_EQ(t.graphics[5].kind, Graphic::Kind::Arc);
  EXPECT_EQ(t.graphics[5].sides, 8);
  EXPECT_NEAR(t.graphics[5].rangle, 0.5 * std::numbers::pi, 1e-15);
  EXPECT_EQ(t.graphics[6].kind, Graphic::Kind::Circle);
  EXPECT_EQ(t.graphics[6].radius, 1.5);
  EXPECT_EQ(t.b.model.parts[t.graphics[6].part].id, 1);
}

TEST(GraphicsBuilder, KindsNotDrawnWarnOncePerKindNamingIt) {
  const Built t = build(kDeck);
  std::vector<std::string> warnings;
  for (const auto& d : t.b.diags.all())
    if (d.severity == Severity::Warning) warnings.push_back(format(d));
  ASSERT_EQ(warnings.size(), 2u) << ::testing::PrintToString(warnings);
  EXPECT_NE(warnings[0].find("GRAPHICS/9: 2 GRAPHICS of kind FORCE"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find(":18:"), std::string::npos) << warnings[0];  // the first FORCE
  EXPECT_NE(warnings[1].find("GRAPHICS/8: 1 GRAPHICS of kind POINT"), std::string::npos)
      << warnings[1];
}

TEST(GraphicsBuilder, BadDataIsOneLocatedErrorEach) {
  const Built t = build(
      "bad graphics\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "GRAPHICS/1, CYLINDER, CM=99, LENGTH=1, RADIUS=1\n"
      "GRAPHICS/2, CYLINDER, CM=10, LENGTH=1, RADIUS=-1\n"
      "GRAPHICS/3, FRUSTUM, CM=10, TOP=1, BOTTOM=2\n"
      "GRAPHICS/4, OUTLINE=10, 77\n"
      "END\n");
  EXPECT_FALSE(t.b.ok);
  std::vector<std::string> errors;
  for (const auto& d : t.b.diags.all())
    if (d.severity == Severity::Error) errors.push_back(format(d));
  ASSERT_EQ(errors.size(), 4u) << ::testing::PrintToString(errors);
  EXPECT_NE(errors[0].find("graphics.adm:4:"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("CM=99 names no marker"), std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find("GRAPHICS/2: RADIUS must not be negative"), std::string::npos)
      << errors[1];
  EXPECT_NE(errors[2].find("GRAPHICS/3: the LENGTH of the graphic is missing"), std::string::npos)
      << errors[2];
  EXPECT_NE(errors[3].find("OUTLINE names MARKER/77"), std::string::npos) << errors[3];
}

TEST(GraphicsBuilder, PistonCylindersSitWhereItsCommentsPutThem) {
  const std::string path = std::string(OPENMSS_SOURCE_DIR) + "/examples/piston/piston.adm";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetFile(path, dataset, diags);
  model::Model m;
  ASSERT_TRUE(model::buildModel(dataset, m, diags));
  const std::vector<Graphic> g = model::buildGraphics(dataset, m, diags);
  ASSERT_EQ(g.size(), 5u);
  // Axes x=Y y=Z z=X (REULER 90D, 90D, 0): the cylinders along global X.
  Eigen::Matrix3d alongX;
  alongX << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  struct Expected {
    long id, part;
    Eigen::Vector3d position;  // in the body frame
    bool alongX;
    double length, radius;
  };
  // The piston's body frame has the same axes as its graphic marker (both REULER 90D, 90D, 0),
  // its CM 2 in beyond the skirt along global X, which is the body z axis.
  const Expected expected[] = {{101, 1, {5, 0, 0}, true, 9, 1.55},
                               {201, 2, {-1, 0, -2}, false, 2, 0.5},
                               {202, 2, {-1, 0, 0}, true, 2, 0.4},
                               {301, 3, {-4, 0, 0}, true, 8, 0.375},
                               {401, 4, {0, 0, -2}, false, 4, 1.5}};
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Expected& e = expected[i];
    EXPECT_EQ(g[i].id, e.id);
    EXPECT_EQ(g[i].kind, Graphic::Kind::Cylinder);
    EXPECT_EQ(m.parts[g[i].part].id, e.part);
    EXPECT_TRUE(g[i].position.isApprox(e.position, kTol) ||
                (e.position.isZero() && g[i].position.isZero(kTol)))
        << "GRAPHICS/" << e.id << ": " << g[i].position.transpose();
    const Eigen::Matrix3d axes = e.alongX ? alongX : Eigen::Matrix3d::Identity();
    EXPECT_TRUE(g[i].orientation.isApprox(axes, kTol)) << "GRAPHICS/" << e.id;
    EXPECT_EQ(g[i].length, e.length);
    EXPECT_EQ(g[i].radius, e.radius);
  }
}

}  // namespace
}  // namespace openmss
