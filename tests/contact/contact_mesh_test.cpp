// CONTACT with EXTERNAL shells (.shl, .stl) against independent truth (docs/theory.md §6c,
// "Meshes"):
// - a BOX written as an ADAMS shell and dropped tilted on a PLANE runs as the analytic BOX (the
//   same vertices below the plane), and rests at 4 k d^e = m g;
// - the same box as an STL (ASCII and binary) pressed 1e-3 into a ground BOX (FCL, mesh
//   against box) carries k d^e (the triangles' contacts share one force);
// - a sphere bouncing on a shell floor (FCL, sphere against triangles) bounces as on the
//   analytic BOX floor;
// - the Newton matrix of the shell on the PLANE against central differences (exact partials);
// - bad input: an unreadable shell, a Parasolid file present, a file of another kind: one
//   located message each.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "contact/contact_support.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

namespace fs = std::filesystem;
constexpr double kG = 9.81;

// A fresh folder for one test's data set and shell files.
fs::path folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("openmss_contact_mesh_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

// The corners of an X x Y x Z box from the origin, numbered as the analytic BOX's vertices
// (bit 0: x, bit 1: y, bit 2: z), and its six faces as corner lists.
std::vector<Eigen::Vector3d> boxCorners(double x, double y, double z) {
  std::vector<Eigen::Vector3d> c;
  for (int k = 0; k < 8; ++k) c.emplace_back(k & 1 ? x : 0.0, k & 2 ? y : 0.0, k & 4 ? z : 0.0);
  return c;
}
const int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                          {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

std::string boxShl(double x, double y, double z) {
  std::string s = "8 6\n1.0\n";
  char line[120];
  for (const Eigen::Vector3d& p : boxCorners(x, y, z)) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    s += line;
  }
  for (const auto& f : kFaces) {
    std::snprintf(line, sizeof line, "4 %d %d %d %d\n", f[0] + 1, f[1] + 1, f[2] + 1, f[3] + 1);
    s += line;
  }
  return s;
}

// The box's twelve triangles (each face split along its first diagonal).
std::vector<std::array<Eigen::Vector3d, 3>> boxTriangles(double x, double y, double z) {
  const std::vector<Eigen::Vector3d> c = boxCorners(x, y, z);
  std::vector<std::array<Eigen::Vector3d, 3>> t;
  for (const auto& f : kFaces) {
    t.push_back({c[f[0]], c[f[1]], c[f[2]]});
    t.push_back({c[f[0]], c[f[2]], c[f[3]]});
  }
  return t;
}

std::string boxStlText(double x, double y, double z) {
  std::string s = "solid box\n";
  char line[160];
  for (const auto& tri : boxTriangles(x, y, z)) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const Eigen::Vector3d& p : tri) {
      std::snprintf(line, sizeof line, "      vertex %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
      s += line;
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid box\n";
}

std::string boxStlBinary(double x, double y, double z) {
  const auto tris = boxTriangles(x, y, z);
  std::string s(80, ' ');
  const std::uint32_t n = static_cast<std::uint32_t>(tris.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& tri : tris) {
    float rec[12] = {0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) rec[3 + 3 * c + k] = static_cast<float>(tri[c][k]);
    s.append(reinterpret_cast<const char*>(rec), 48);
    s.append(2, '\0');
  }
  return s;
}

model::Model buildIn(const fs::path& dir, const std::string& text) {
  const testing::BuiltModel b = testing::buildModelFromText(text, (dir / "c.adm").string());
  EXPECT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  return b.model;
}

const char* kLaw = "IMPACT, STIFFNESS=1e6, DAMPING=300, DMAX=1e-4, EXPONENT=1.5";

// A 0.4 x 0.3 x 0.2 box of mass 2 (its centre at the CM, its corner marker 21) given by
// `graphics` at height z, turned by `reuler`, over `floor`.
std::string boxDeck(const std::string& floor, const std::string& graphics, double z,
                    const std::string& reuler) {
  char part[220];
  std::snprintf(part, sizeof part,
                "PART/2, MASS=2, CM=20, IP=0.0216666667,0.0333333333,0.0416666667, "
                "QG=0,0,%.17g, REULER=%s\n",
                z, reuler.c_str());
  return std::string("box\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n") +
         "PART/1, GROUND\n" + floor + part +
         "MARKER/20, PART=2\nMARKER/21, PART=2, QP=-0.2,-0.15,-0.1\n" + graphics +
         "CONTACT/1, IGEOM=2, JGEOM=1, " + kLaw + "\nACCGRAV/KGRAV=-9.81\nEND\n";
}

const char* kPlaneFloor = "MARKER/10, PART=1\nGRAPHICS/1, PLANE, RM=10\n";
const char* kBoxFloor =
    "MARKER/10, PART=1, QP=-1,-1,-1\nGRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n";
const char* kBox = "GRAPHICS/2, BOX, CORNER=21, X=0.4, Y=0.3, Z=0.2\n";

TEST(ContactMesh, ShellBoxOnAPlaneRunsAsTheAnalyticBox) {
  const fs::path dir = folder("shl_plane");
  write(dir / "box.shl", boxShl(0.4, 0.3, 0.2));
  const std::string shell = "GRAPHICS/2, EXTERNAL, RM=21, FILE=box.shl\n";
  // Dropped tilted from 2 mm above its lowest corner's contact: bounces on corners and edges.
  const double z = 0.1 * std::cos(0.1) + 0.2 * std::sin(0.1) * std::cos(0.05) + 2e-3;
  const std::vector<Sample> exact =
      simulate(buildIn(dir, boxDeck(kPlaneFloor, kBox, z, "0.05,0.1,0")), 0.2, 1e-3, 1e-9, 1e-3);
  const std::vector<Sample> mesh =
      simulate(buildIn(dir, boxDeck(kPlaneFloor, shell, z, "0.05,0.1,0")), 0.2, 1e-3, 1e-9, 1e-3);
  ASSERT_EQ(exact.size(), mesh.size());
  double worst = 0.0;
  for (size_t k = 0; k < exact.size(); ++k)
    worst = std::max({worst, (exact[k].r - mesh[k].r).cwiseAbs().maxCoeff(),
                      (exact[k].v - mesh[k].v).cwiseAbs().maxCoeff(),
                      (exact[k].w - mesh[k].w).cwiseAbs().maxCoeff()});
  std::printf("shell box vs BOX on a PLANE, tilted drop: max difference %.2e over %zu samples\n",
              worst, exact.size());
  // The same vertices in the same order: the runs differ by rounding only.
  EXPECT_LT(worst, 1e-10);
  // Released flat 1e-4 above: four corners carry m g, 4 k d^e = m g.
  const std::vector<Sample> rest =
      simulate(buildIn(dir, boxDeck(kPlaneFloor, shell, 0.1001, "0,0,0")), 1.0, 1e-2, 1e-9, 1e-3);
  const double depth = 0.1 - rest.back().r.z(), truth = std::pow(2 * kG / 4e6, 1.0 / 1.5);
  std::printf("shell box at rest on a PLANE: penetration %.12e, (m g / 4 k)^(1/e) = %.12e\n", depth,
              truth);
  EXPECT_NEAR(depth, truth, 1e-6 * truth);
}

TEST(ContactMesh, StlBoxPressedIntoABoxCarriesOneForce) {
  // The box as an STL (ASCII and binary), its bottom face 1e-3 into a ground BOX's top face, at
  // rest: FCL's triangle contacts share one force, k d^e straight up, through the bottom face's
  // centre (no moment about the CM, which is above it).
  const fs::path dir = folder("stl_box");
  write(dir / "text.stl", boxStlText(0.4, 0.3, 0.2));
  write(dir / "binary.STL", boxStlBinary(0.4, 0.3, 0.2));
  const double d = 1e-3, force = 1e6 * std::pow(d, 1.5);
  for (const char* file : {"text.stl", "binary.STL"}) {
    const std::string g = std::string("GRAPHICS/2, EXTERNAL, RM=21, FILE=") + file + "\n";
    const model::Model m = buildIn(dir, boxDeck(kBoxFloor, g, 0.1 - d, "0,0,0"));
    ASSERT_EQ(m.contacts.size(), 1u);
    const auto& solid = m.contacts[0].iSolids[0];
    ASSERT_EQ(solid.shape, model::ContactSolid::Shape::Mesh);
    EXPECT_EQ(solid.mesh->vertices.size(), 8u) << file;  // STL corners merged
    EXPECT_EQ(solid.mesh->triangles.size(), 12u) << file;
    mechanics::MultibodySystem s(m);
    const Eigen::VectorXd y = s.initialState();
    const auto loads =
        mechanics::contact::contactLoads(m, s.layout(), m.contacts[0], y.data(), false);
    const Eigen::Vector3d f(loads.force.x, loads.force.y, loads.force.z);
    std::printf(
        "%s box 1e-3 into a BOX (FCL): %d triangle contacts, force %.9e %.3e %.3e (k d^e "
        "%.9e)\n",
        file, loads.points, f.z(), f.x(), f.y(), force);
    EXPECT_GE(loads.points, 2) << file;
    // FCL's depths on these face contacts are exact to its 1e-12 convergence.
    EXPECT_NEAR(f.z(), force, 1e-6 * force) << file;
    EXPECT_NEAR(f.head<2>().norm(), 0.0, 1e-6 * force) << file;
  }
}

TEST(ContactMesh, SphereBouncesOnAShellFloorAsOnTheAnalyticBox) {
  const fs::path dir = folder("sphere_floor");
  write(dir / "floor.shl", boxShl(2, 2, 1));
  auto deck = [](const std::string& floor) {
    return std::string("ball\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n") +
           "PART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\n" + floor +
           "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0.3,0.1,0.1, VZ=-1\n"
           "MARKER/20, PART=2\n"
           "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
           "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, "
           "EXPONENT=1.5\nACCGRAV/KGRAV=-9.81\nEND\n";
  };
  double result[2][2];
  const char* floors[2] = {"GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n",
                           "GRAPHICS/1, EXTERNAL, RM=10, FILE=floor.shl\n"};
  for (int k = 0; k < 2; ++k) {
    const std::vector<Sample> run =
        simulate(buildIn(dir, deck(floors[k])), 0.02, 1e-5, 1e-10, 2e-6);
    std::vector<double> t, depth;
    for (const Sample& s : run) t.push_back(s.t), depth.push_back(0.1 - s.r.z());
    result[k][0] = peak(depth);
    result[k][1] = returnTime(t, depth);
  }
  std::printf(
      "sphere bounce, BOX floor: peak %.9e, contact %.9e s; shell floor (FCL): peak "
      "%.9e, contact %.9e s\n",
      result[0][0], result[0][1], result[1][0], result[1][1]);
  EXPECT_NEAR(result[1][0], result[0][0], 1e-6 * result[0][0]);
  EXPECT_NEAR(result[1][1], result[0][1], 1e-6 * result[0][1]);
}

TEST(ContactMesh, ShellOnAPlaneHasExactPartials) {
  const fs::path dir = folder("partials");
  write(dir / "box.shl", boxShl(0.4, 0.3, 0.2));
  std::string text =
      boxDeck(kPlaneFloor, "GRAPHICS/2, EXTERNAL, RM=21, FILE=box.shl\n", 0.14, "0.3,0.4,0");
  const model::Model m = buildIn(dir, text);
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState();
  y.segment<3>(StateLayout::kV) = Eigen::Vector3d(0.3, 0.2, -0.4);
  y.segment<3>(StateLayout::kW) = Eigen::Vector3d(0.5, -0.3, 0.8);
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());
  Eigen::MatrixXd exact;
  s.newtonMatrix(0.0, y, yp, 0.0, exact);
  const int n = static_cast<int>(y.size());
  Eigen::VectorXd gp(n), gm(n);
  double worst = 0.0, scale = 0.0;
  for (int c = 0; c < n; ++c) {
    Eigen::VectorXd a = y, b = y;
    a(c) += 1e-7;
    b(c) -= 1e-7;
    s.residual(0.0, a.data(), yp.data(), gp.data());
    s.residual(0.0, b.data(), yp.data(), gm.data());
    worst = std::max(worst, ((gp - gm) / 2e-7 - exact.col(c)).cwiseAbs().maxCoeff());
    scale = std::max(scale, exact.col(c).cwiseAbs().maxCoeff());
  }
  const auto loads =
      mechanics::contact::contactLoads(m, s.layout(), m.contacts[0], y.data(), false);
  std::printf(
      "shell on a PLANE: %d vertices in contact, Newton matrix vs central differences "
      "%.2e of %.2e\n",
      loads.points, worst, scale);
  EXPECT_GE(loads.points, 1);
  EXPECT_LT(worst, 1e-6 * scale);
}

TEST(ContactMesh, BadShellFilesAreLocated) {
  const fs::path dir = folder("bad");
  std::string broken = boxShl(0.4, 0.3, 0.2);
  broken.replace(broken.rfind("4 2 4 8 6"), 9, "4 2 4 9 6");  // a corner past the 8 points
  write(dir / "broken.shl", broken);
  write(dir / "body.xmt_txt", "**ABCDEFGHIJKLMNOPQRSTUVWXYZ\n");
  write(dir / "body.obj", "v 0 0 0\n");
  auto deck = [&](const std::string& file) {
    return boxDeck(kPlaneFloor, "GRAPHICS/2, EXTERNAL, RM=21, FILE=" + file + "\n", 0.2, "0,0,0");
  };
  auto built = [&](const std::string& file) {
    return testing::buildModelFromText(deck(file), (dir / "c.adm").string());
  };
  // The CONTACT is line 10; its IGEOM value is where the message points.
  expectOneError(built("broken.shl"), 10,
                 "reads its shell from 'broken.shl', which cannot be read: line 16: face "
                 "corner 9 is not a point number 1..8");
  expectOneError(built("body.xmt_txt"), 10,
                 "(body.xmt_txt): Parasolid files are not read; contact reads ADAMS shell "
                 "(.shl) and STL (.stl) files");
  expectOneError(built("body.obj"), 10, "'.obj' files are not read");
  expectOneError(built("absent.shl"), 10, "'absent.shl', which is missing");
}

}  // namespace
}  // namespace openmss::contact_test
