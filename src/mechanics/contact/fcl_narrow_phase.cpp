// FCL as the library narrow phase of CONTACT (docs/theory.md §6c, "FCL"). Everything here works
// on doubles: the partials are made on T by fcl_narrow_phase.hpp from the contact frame.
// Built alone as the module openmss_fcl.so (docs/architecture.md, "FCL module"): everything is
// hidden but the extern "C" entry point at the end, and it needs nothing from the program but
// header-only code (linked with --no-undefined, src/CMakeLists.txt).

#include "mechanics/contact/fcl_narrow_phase.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <type_traits>
#include <utility>

namespace openmss::mechanics::contact {
namespace {

using Shape = model::ContactSolid::Shape;
using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

// A solid as FCL geometry and where FCL's origin lies in the solid's reference frame (FCL's
// box and cylinder are centred; the GRAPHICS BOX has its corner at CORNER, the CYLINDER its
// bottom disc at CM).
struct Placed {
  Geometry geometry;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// A FRUSTUM of unequal radii: the convex polytope of two kFrustumSides-gons (a cone's apex a
// single vertex), in the CM marker's axes.
Geometry frustumPolytope(const model::ContactSolid& s) {
  auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>();
  auto faces = std::make_shared<std::vector<int>>();
  const double radius[2] = {s.size[0], s.size[1]}, z[2] = {0.0, s.size[2]};
  int start[2] = {0, 0}, count[2] = {0, 0};
  for (int rim = 0; rim < 2; ++rim) {
    start[rim] = static_cast<int>(vertices->size());
    count[rim] = radius[rim] == 0.0 ? 1 : kFrustumSides;
    for (int k = 0; k < count[rim]; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / kFrustumSides;
      vertices->emplace_back(radius[rim] * std::cos(phi), radius[rim] * std::sin(phi), z[rim]);
    }
  }
  // Faces: each rim's polygon and the side quads (triangles to an apex). GJK/EPA uses the
  // vertices only; the faces make the polytope well formed.
  int faceCount = 0;
  for (int rim = 0; rim < 2; ++rim)
    if (count[rim] > 1) {
      faces->push_back(count[rim]);
      for (int k = 0; k < count[rim]; ++k) faces->push_back(start[rim] + k);
      ++faceCount;
    }
  for (int k = 0; k < kFrustumSides; ++k) {
    const int k1 = (k + 1) % kFrustumSides;
    std::vector<int> f;
    for (int rim = 0; rim < 2; ++rim) {
      if (count[rim] == 1) {
        f.push_back(start[rim]);
      } else {
        f.push_back(start[rim] + (rim == 0 ? k : k1));
        f.push_back(start[rim] + (rim == 0 ? k1 : k));
      }
    }
    faces->push_back(static_cast<int>(f.size()));
    faces->insert(faces->end(), f.begin(), f.end());
    ++faceCount;
  }
  return std::make_shared<fcl::Convexd>(vertices, faceCount, faces);
}

// The mesh's bounding-volume hierarchy, built once per mesh (the model holds the mesh; this
// cache holds only what is derived from it, the same whenever it is built).
Geometry meshHierarchy(const std::shared_ptr<const model::TriangleMesh>& mesh) {
  static std::mutex lock;
  static std::vector<std::pair<std::weak_ptr<const model::TriangleMesh>, Geometry>> built;
  std::lock_guard<std::mutex> guard(lock);
  for (auto it = built.begin(); it != built.end();) {
    if (it->first.expired()) {
      it = built.erase(it);
      continue;
    }
    if (!it->first.owner_before(mesh) && !mesh.owner_before(it->first)) return it->second;
    ++it;
  }
  auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Triangle> triangles;
  for (const auto& t : mesh->triangles) triangles.emplace_back(t[0], t[1], t[2]);
  bvh->beginModel();
  bvh->addSubModel(mesh->vertices, triangles);
  bvh->endModel();
  built.emplace_back(mesh, bvh);
  return bvh;
}

Placed placed(const model::ContactSolid& s) {
  Placed p;
  switch (s.shape) {
    case Shape::Sphere:
      // As an ellipsoid: GJK/EPA for every pair, one convention for the contact point.
      p.geometry = std::make_shared<fcl::Ellipsoidd>(s.size[0], s.size[0], s.size[0]);
      break;
    case Shape::Ellipsoid:
      p.geometry = std::make_shared<fcl::Ellipsoidd>(s.size[0], s.size[1], s.size[2]);
      break;
    case Shape::Box:
      p.geometry = std::make_shared<fcl::Boxd>(s.size.cwiseAbs());
      p.offset = 0.5 * s.size;
      break;
    case Shape::Frustum:
      if (s.size[0] == s.size[1]) {
        p.geometry = std::make_shared<fcl::Cylinderd>(s.size[0], std::abs(s.size[2]));
        p.offset = Eigen::Vector3d(0.0, 0.0, 0.5 * s.size[2]);
      } else {
        p.geometry = frustumPolytope(s);
      }
      break;
    case Shape::Mesh:
      p.geometry = meshHierarchy(s.mesh);
      break;
    default:
      break;  // planes and tori are analytic (the builder sends no such pair here)
  }
  return p;
}

// The point of a sphere or ellipsoid farthest along the ground direction u (its support point):
// x = p + A diag(s^2) w / |diag(s) w|, w = A^T u. Smooth in the frame and u, unlike MPR's
// point, which wanders within the contact patch (theory §6c, "Partials of the FCL pairs").
Eigen::Vector3d supportPoint(const model::ContactSolid& s, const SolidFrame<double>& f,
                             const Eigen::Vector3d& u) {
  const Eigen::Matrix3d a = toEigen(f.a);
  const Eigen::Vector3d semi =
      s.shape == Shape::Sphere ? Eigen::Vector3d::Constant(s.size[0]) : Eigen::Vector3d(s.size);
  const Eigen::Vector3d sw = semi.cwiseProduct(a.transpose() * u);
  return toEigen(f.p) + a * (semi.cwiseProduct(sw) / sw.norm());
}

// The frame with unit axes. Away from |e| = 1 (a Newton iterate, a differenced state) the
// quadratic form gives axes |e|^2 R(e/|e|); FCL takes its transform as a rotation (inverse =
// transpose), so it gets R(e/|e|): the contact then depends on e through e/|e| only, and the
// residual and its differences agree (theory §6c, "Partials of the FCL pairs").
SolidFrame<double> unitFrame(const SolidFrame<double>& f) {
  SolidFrame<double> u = f;
  for (V3<double>& c : u.a.c) c = c * (1.0 / norm(c));
  return u;
}

bool smooth(const model::ContactSolid& s) {
  return s.shape == Shape::Sphere || s.shape == Shape::Ellipsoid;
}

fcl::Transform3d transformOf(const SolidFrame<double>& f, const Eigen::Vector3d& offset) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = toEigen(f.a);
  t.translation() = toEigen(f.p) + t.linear() * offset;
  return t;
}

}  // namespace

void libraryContacts(const model::ContactSolid& si, const SolidFrame<double>& givenI,
                     const model::ContactSolid& sj, const SolidFrame<double>& givenJ,
                     std::vector<LibraryContact>& out) {
  const SolidFrame<double> fi = unitFrame(givenI), fj = unitFrame(givenJ);
  const Placed pi = placed(si), pj = placed(sj);
  if (!pi.geometry || !pj.geometry) return;
  const fcl::CollisionObjectd oi(pi.geometry, transformOf(fi, pi.offset));
  const fcl::CollisionObjectd oj(pj.geometry, transformOf(fj, pj.offset));
  const bool mesh = si.shape == Shape::Mesh || sj.shape == Shape::Mesh;
  fcl::CollisionRequestd request(mesh ? 256 : 1, true);
  request.gjk_solver_type = fcl::GST_LIBCCD;
  // MPR to 1e-12 (FCL's default 1e-6 would be the noise of the central differences).
  request.gjk_tolerance = 1e-12;
  fcl::CollisionResultd result;
  fcl::collide(&oi, &oj, request, result);
  const bool meshI = si.shape == Shape::Mesh, meshJ = sj.shape == Shape::Mesh;
  for (size_t k = 0; k < result.numContacts(); ++k) {
    const fcl::Contactd& c = result.getContact(k);
    const double d = c.penetration_depth;
    if (!(d > 0.0)) continue;
    // FCL's conventions differ by pair kind (checked on boxes resting on boxes and meshes):
    // convex-convex (GJK/MPR): normal from the first object (I) to the second (J), point
    // midway between the witnesses; mesh-mesh: normal from I to J, point I's witness (inside
    // J); mesh-convex, in either order: normal from the mesh to the convex solid, point the
    // mesh's witness (inside the convex solid). `toJ` is the unit normal from I towards J.
    Eigen::Vector3d toJ = c.normal, onI, onJ;
    if (!meshI && !meshJ) {
      // A smooth solid's witness is its support point along the normal; the other's lies d
      // back along it. Otherwise FCL's midway point.
      if (smooth(si)) {
        onI = supportPoint(si, fi, toJ);
        onJ = onI - d * toJ;
      } else if (smooth(sj)) {
        onJ = supportPoint(sj, fj, -toJ);
        onI = onJ + d * toJ;
      } else {
        onI = c.pos + 0.5 * d * toJ;
        onJ = c.pos - 0.5 * d * toJ;
      }
    } else if (meshI && meshJ) {
      onI = c.pos;
      onJ = c.pos - d * toJ;
    } else {
      if (meshJ) toJ = -toJ;  // FCL's normal points from the mesh (J) to I
      const Eigen::Vector3d meshPoint = c.pos, convexPoint = c.pos - d * c.normal;
      onI = meshI ? meshPoint : convexPoint;
      onJ = meshI ? convexPoint : meshPoint;
    }
    out.push_back(
        {V3<double>::from(onI), V3<double>::from(onJ), V3<double>::from(Eigen::Vector3d(-toJ)), d});
  }
}

}  // namespace openmss::mechanics::contact

// The module's one export (user::kFclEntryName), called by fcl_module.cpp.
extern "C" __attribute__((visibility("default"))) void openmss_fcl_library_contacts(
    const openmss::model::ContactSolid* si,
    const openmss::mechanics::contact::SolidFrame<double>* fi,
    const openmss::model::ContactSolid* sj,
    const openmss::mechanics::contact::SolidFrame<double>* fj,
    std::vector<openmss::mechanics::contact::LibraryContact>* out) {
  static_assert(std::is_same_v<decltype(openmss_fcl_library_contacts),
                               openmss::mechanics::contact::LibraryContactsEntry>);
  openmss::mechanics::contact::libraryContacts(*si, *fi, *sj, *fj, *out);
}
