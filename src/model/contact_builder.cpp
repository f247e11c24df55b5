#include "model/contact_builder.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "model/contact_planar_geometry.hpp"
#include "model/contact_user_laws.hpp"
#include "model/graphics_builder.hpp"
#include "model/shell_file.hpp"
#include "model/statement_arguments.hpp"
#include "user/fcl_module.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// CYLINDER (RADIUS) or FRUSTUM (BOTTOM, TOP): a solid of revolution about the CM marker's z
// axis from the CM origin over LENGTH (theory §6c); false after a diagnostic at `where`.
bool readFrustum(const Statement& g, const std::string& kind, const Model& model,
                 const SourceLocation& where, const std::string& subject, Diagnostics& diags,
                 ContactSolid& out) {
  const bool cylinder = kind == "CYLINDER";
  const double bottom = graphicsNumber(g, cylinder ? "RADIUS" : "BOTTOM");
  const double top = cylinder ? bottom : graphicsNumber(g, "TOP");
  const double length = graphicsNumber(g, "LENGTH");
  if (!(bottom >= 0.0) || !(top >= 0.0) || bottom + top == 0.0 || !(length != 0.0)) {
    diags.error(
        where, subject,
        graphicsAt(g) + " is a " + kind + " with " +
            (cylinder ? "RADIUS = " + std::to_string(bottom)
                      : "BOTTOM = " + std::to_string(bottom) + ", TOP = " + std::to_string(top)) +
            " and LENGTH = " + std::to_string(length) + ": it has no volume",
        cylinder ? "Give RADIUS > 0 and LENGTH different from 0."
                 : "Give BOTTOM, TOP >= 0 (not both 0) and LENGTH different from 0.");
    return false;
  }
  if (const Argument* r = g.find("RANGLE"); r && !r->values.empty()) {
    const double angle = r->values[0].number;  // radians (a D suffix is converted on reading)
    if (std::abs(angle) < 2.0 * M_PI * (1.0 - 1e-9)) {
      diags.error(where, subject,
                  graphicsAt(g) + " is a partial " + kind + " (RANGLE = " + r->values[0].written +
                      "): contact needs the full solid of revolution",
                  "Remove RANGLE (or give 360D) from the GRAPHICS used for contact.");
      return false;
    }
  }
  out.shape = ContactSolid::Shape::Frustum;
  out.size = Eigen::Vector3d(bottom, top, length);
  out.boundingRadius = std::hypot(std::max(bottom, top), length);
  out.marker = graphicsMarker(g, "CM", model, where, subject, diags);
  return true;
}

// PLANE (RM, XMIN, XMAX, YMIN, YMAX): the half-space below RM's xy-plane, limited sideways to
// the rectangle when one is given (theory §6c, "Plane"); false after a diagnostic at `where`.
bool readPlane(const Statement& g, const Model& model, const SourceLocation& where,
               const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const char* names[4] = {"XMIN", "XMAX", "YMIN", "YMAX"};
  int given = 0;
  for (int k = 0; k < 4; ++k)
    if (g.find(names[k])) {
      out.bounds[k] = graphicsNumber(g, names[k]);
      ++given;
    }
  if ((given != 0 && given != 4) || !(out.bounds[0] < out.bounds[1]) ||
      !(out.bounds[2] < out.bounds[3])) {
    diags.error(where, subject,
                graphicsAt(g) + " is a PLANE with " + std::to_string(given) +
                    " of XMIN, XMAX, YMIN, YMAX given or an empty rectangle",
                "Give all four with XMIN < XMAX and YMIN < YMAX, or none (an unbounded plane).");
    return false;
  }
  out.shape = ContactSolid::Shape::Plane;
  out.boundingRadius = HUGE_VAL;  // a half-space: every pair goes to the narrow phase
  out.marker = graphicsMarker(g, "RM", model, where, subject, diags);
  return true;
}

// ELLIPSOID (CM, XSCALE, YSCALE, ZSCALE: the diameters): a sphere when the three are equal,
// else an ellipsoid (theory §6c); false after a diagnostic at `where`.
bool readEllipsoid(const Statement& g, const Model& model, const SourceLocation& where,
                   const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const double x = graphicsNumber(g, "XSCALE"), y = graphicsNumber(g, "YSCALE"),
               z = graphicsNumber(g, "ZSCALE");
  if (!(x > 0.0) || !(y > 0.0) || !(z > 0.0)) {
    diags.error(where, subject,
                graphicsAt(g) + " is an ELLIPSOID with scales " + std::to_string(x) + ", " +
                    std::to_string(y) + ", " + std::to_string(z) + ": it has no volume",
                "Give XSCALE, YSCALE and ZSCALE (the diameters) all positive.");
    return false;
  }
  const bool sphere = x == y && x == z;
  out.shape = sphere ? ContactSolid::Shape::Sphere : ContactSolid::Shape::Ellipsoid;
  out.size =
      sphere ? Eigen::Vector3d(0.5 * x, 0.0, 0.0) : Eigen::Vector3d(0.5 * x, 0.5 * y, 0.5 * z);
  out.boundingRadius = 0.5 * std::max({x, y, z});
  out.marker = graphicsMarker(g, "CM", model, where, subject, diags);
  return true;
}

// TORUS (CM, MAJOR_RADIUS, MINOR_RADIUS): a ring about the CM marker's z axis; false after a
// diagnostic at `where`.
bool readTorus(const Statement& g, const Model& model, const SourceLocation& where,
               const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const double big = graphicsNumber(g, "MAJOR_RADIUS"), tube = graphicsNumber(g, "MINOR_RADIUS");
  if (!(tube > 0.0) || !(big > tube)) {
    diags.error(where, subject,
                graphicsAt(g) + " is a TORUS with MAJOR_RADIUS = " + std::to_string(big) +
                    " and MINOR_RADIUS = " + std::to_string(tube) + ": contact needs a ring",
                "Give MAJOR_RADIUS > MINOR_RADIUS > 0.");
    return false;
  }
  out.shape = ContactSolid::Shape::Torus;
  out.size = Eigen::Vector3d(big, tube, 0.0);
  out.boundingRadius = big + tube;
  out.marker = graphicsMarker(g, "CM", model, where, subject, diags);
  return true;
}

// EXTERNAL (RM, FILE): an ADAMS shell (.shl) or STL file next to the data set, read into a
// triangle mesh (theory §6c, "Meshes"); Parasolid and other files are refused by name. False
// after a diagnostic at `where`.
bool readExternal(const Statement& g, const Model& model, const SourceLocation& where,
                  const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const Argument* f = g.find("FILE");
  const std::string file = f && !f->values.empty() ? f->values[0].written : "";
  const std::filesystem::path path =
      std::filesystem::path(model.file).parent_path() / std::filesystem::path(file);
  std::string ext = std::filesystem::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (file.empty() || !std::filesystem::exists(path)) {
    diags.error(where, subject,
                graphicsAt(g) + " reads its shell from the file '" + file +
                    "', which is missing (" + path.string() + ")",
                "Put the file next to the data set, or replace the EXTERNAL geometry by "
                "ELLIPSOID, BOX, CYLINDER or FRUSTUM solids.");
    return false;
  }
  if (ext != ".shl" && ext != ".stl") {
    const bool parasolid = ext.rfind(".x_", 0) == 0 || ext.rfind(".xmt", 0) == 0;
    diags.error(
        where, subject,
        graphicsAt(g) + " is an EXTERNAL shell (" + file + "): " +
            (parasolid ? "Parasolid files are not read" : "'" + ext + "' files are not read") +
            "; contact reads ADAMS shell (.shl) and STL (.stl) files",
        "Export the body as .shl or .stl and name that file in FILE, or replace it by "
        "ELLIPSOID, BOX, CYLINDER or FRUSTUM solids.");
    return false;
  }
  std::string why;
  std::optional<TriangleMesh> mesh = readShellFile(path.string(), why);
  if (!mesh) {
    diags.error(
        where, subject,
        graphicsAt(g) + " reads its shell from '" + file + "', which cannot be read: " + why,
        "Give a shell file of the ADAMS .shl layout (points, then faces) or an STL file.");
    return false;
  }
  double reach = 0.0;
  for (const Eigen::Vector3d& v : mesh->vertices) reach = std::max(reach, v.norm());
  out.shape = ContactSolid::Shape::Mesh;
  out.mesh = std::make_shared<const TriangleMesh>(std::move(*mesh));
  out.boundingRadius = reach;
  out.marker = graphicsMarker(g, "RM", model, where, subject, diags);
  return true;
}

// One GRAPHICS solid for a CONTACT; false after a diagnostic at `where` (the IGEOM/JGEOM value).
bool readSolid(const Statement& g, const Model& model, const SourceLocation& where,
               const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const std::string kind = graphicsKind(g);
  out.graphicsId = g.id.value_or(0);
  out.where = g.where;
  if (kind == "ELLIPSOID") {
    if (!readEllipsoid(g, model, where, subject, diags, out)) return false;
  } else if (kind == "BOX") {
    out.shape = ContactSolid::Shape::Box;
    out.size =
        Eigen::Vector3d(graphicsNumber(g, "X"), graphicsNumber(g, "Y"), graphicsNumber(g, "Z"));
    if (out.size.cwiseAbs().minCoeff() == 0.0) {
      diags.error(where, subject, graphicsAt(g) + " is a BOX with a zero extent: it has no volume",
                  "Give X, Y and Z all different from 0.");
      return false;
    }
    out.boundingRadius = out.size.norm();
    out.marker = graphicsMarker(g, "CORNER", model, where, subject, diags);
  } else if (kind == "EXTERNAL") {
    if (!readExternal(g, model, where, subject, diags, out)) return false;
  } else if (kind == "CYLINDER" || kind == "FRUSTUM") {
    if (!readFrustum(g, kind, model, where, subject, diags, out)) return false;
  } else if (kind == "PLANE") {
    if (!readPlane(g, model, where, subject, diags, out)) return false;
  } else if (kind == "TORUS") {
    if (!readTorus(g, model, where, subject, diags, out)) return false;
  } else if (kind == "OUTLINE") {
    if (!readOutlineFloor(g, model, where, subject, diags, out)) return false;
  } else if (kind == "CIRCLE" || kind == "ARC" || kind == "POINT" || kind == "CURVE") {
    if (!readPlanarGeometry(g, kind, model, where, subject, diags, out)) return false;
  } else {
    diags.error(where, subject,
                graphicsAt(g) + " is " +
                    (kind.empty() ? "no solid" : "a " + kind + ", not a solid") +
                    ": CONTACT needs solids (a volume)",
                "Name ELLIPSOID, BOX, CYLINDER, FRUSTUM, TORUS, PLANE, a closed OUTLINE or "
                "EXTERNAL (.shl, .stl) GRAPHICS in IGEOM and JGEOM (CIRCLE, ARC, POINT or CURVE "
                "for 2-D contact).");
    return false;
  }
  if (out.marker < 0) return false;
  out.part = model.markers[out.marker].part;
  return true;
}

// IGEOM or JGEOM: every solid, all on one part; false after a diagnostic.
bool readSide(const Statement& s, const char* name, const std::map<long, const Statement*>& gr,
              const Model& model, Diagnostics& diags, std::vector<ContactSolid>& out, int& part) {
  const Argument* a = s.find(name);
  if (!a) return false;  // required by the schema: the reader reported it
  bool ok = true;
  for (const language::Value& v : a->values) {
    const long id = static_cast<long>(v.number);
    const auto it = gr.find(id);
    if (it == gr.end()) {
      diags.error(
          v.where, s.subject(),
          std::string(name) + " names GRAPHICS/" + std::to_string(id) + ", which does not exist",
          "Use the id of a GRAPHICS statement of this data set.");
      ok = false;
      continue;
    }
    ContactSolid solid;
    if (!readSolid(*it->second, model, v.where, s.subject(), diags, solid)) {
      ok = false;
      continue;
    }
    if (part >= 0 && solid.part != part) {
      diags.error(v.where, s.subject(),
                  std::string(name) + " solids lie on different parts (PART/" +
                      std::to_string(model.parts[part].id) + " and PART/" +
                      std::to_string(model.parts[solid.part].id) + ")",
                  "Name the solids of one part in each of IGEOM and JGEOM; write one CONTACT "
                  "per pair of parts.");
      ok = false;
      continue;
    }
    part = solid.part;
    out.push_back(solid);
  }
  return ok && !out.empty();
}

void readNormalLaw(StatementArguments& a, Contact& c) {
  const Statement& s = a.statement();
  const bool impact = s.has("IMPACT"), poisson = s.has("POISSON");
  if (s.has("NORMAL_FUNCTION")) {
    // CNFSUB gives the whole normal force (contact_user_laws.cpp).
    c.law = Contact::NormalLaw::User;
    for (const char* other : {"IMPACT", "POISSON", "STIFFNESS", "DAMPING", "DMAX", "EXPONENT",
                              "PENALTY", "RESTITUTION_COEFFICIENT"})
      if (const Argument* x = a.find(other))
        a.error(*x,
                std::string(other) +
                    " with NORMAL_FUNCTION=USER(...): CNFSUB gives the "
                    "whole normal force",
                std::string("Remove ") + other + ", or NORMAL_FUNCTION to use the built-in law.");
    return;
  }
  if (impact == poisson) {
    a.error(s.where,
            impact ? "give only one of IMPACT and POISSON" : "the normal force law is missing",
            "Add IMPACT (STIFFNESS, DAMPING, DMAX, EXPONENT) or POISSON (PENALTY, "
            "RESTITUTION_COEFFICIENT).");
    return;
  }
  auto nonNegative = [&](const char* name, double& out, bool positive) {
    a.require(name, positive ? "a positive number" : "a number >= 0");
    const std::optional<double> v = a.real(name);
    if (!v) return;
    if (*v < 0.0 || (positive && *v == 0.0)) {
      a.error(*a.find(name),
              std::string(name) + " = " + std::to_string(*v) +
                  (positive ? " must be positive" : " must not be negative"),
              std::string("Give ") + name + (positive ? " > 0." : " >= 0."));
      return;
    }
    out = *v;
  };
  if (impact) {
    c.law = Contact::NormalLaw::Impact;
    nonNegative("STIFFNESS", c.stiffness, false);
    nonNegative("DAMPING", c.damping, false);
    nonNegative("DMAX", c.dmax, true);
    nonNegative("EXPONENT", c.exponent, true);
    for (const char* other : {"PENALTY", "RESTITUTION_COEFFICIENT"})
      if (const Argument* x = a.find(other))
        a.error(*x, std::string(other) + " belongs to POISSON, not IMPACT", "Remove it.");
  } else {
    c.law = Contact::NormalLaw::Poisson;
    nonNegative("PENALTY", c.penalty, true);
    a.require("RESTITUTION_COEFFICIENT", "a number from 0 to 1");
    if (const Argument* r = a.find("RESTITUTION_COEFFICIENT"))
      a.within(*r, 0.0, 1.0, "from 0 to 1", c.restitution);
    for (const char* other : {"STIFFNESS", "DAMPING", "DMAX", "EXPONENT"})
      if (const Argument* x = a.find(other))
        a.error(*x, std::string(other) + " belongs to IMPACT, not POISSON", "Remove it.");
  }
}

void readFriction(StatementArguments& a, Contact& c) {
  const std::string mode = a.word("COULOMB_FRICTION").value_or("OFF");
  c.friction = mode == "ON"              ? Contact::Friction::On
               : mode == "DYNAMICS_ONLY" ? Contact::Friction::DynamicsOnly
                                         : Contact::Friction::Off;
  if (const Argument* f = a.find("FRICTION_FUNCTION")) {
    // CFFSUB gives the friction force (contact_user_laws.cpp); COULOMB_FRICTION only says when
    // it acts (ON when omitted).
    if (!a.find("COULOMB_FRICTION")) c.friction = Contact::Friction::On;
    if (c.friction == Contact::Friction::Off)
      a.error(*f, "FRICTION_FUNCTION=USER(...) with COULOMB_FRICTION = OFF",
              "Remove one of them: OFF turns friction off.");
    for (const char* other : {"MU_STATIC", "MU_DYNAMIC", "STICTION_TRANSITION_VELOCITY",
                              "FRICTION_TRANSITION_VELOCITY"})
      if (const Argument* x = a.find(other))
        a.error(*x,
                std::string(other) +
                    " with FRICTION_FUNCTION=USER(...): CFFSUB gives the "
                    "whole friction force",
                std::string("Remove ") + other +
                    ", or FRICTION_FUNCTION to use the built-in Coulomb law.");
    return;
  }
  if (c.friction == Contact::Friction::Off) return;
  auto value = [&](const char* name, double& out) {
    a.require(name, "a number >= 0");
    const std::optional<double> v = a.real(name);
    if (v && *v < 0.0)
      a.error(*a.find(name), std::string(name) + " must not be negative",
              std::string("Give ") + name + " >= 0.");
    else if (v)
      out = *v;
  };
  value("MU_STATIC", c.muStatic);
  value("MU_DYNAMIC", c.muDynamic);
  value("STICTION_TRANSITION_VELOCITY", c.stictionVelocity);
  value("FRICTION_TRANSITION_VELOCITY", c.frictionVelocity);
  if (a.ok() && !(c.stictionVelocity > 0.0 && c.frictionVelocity > c.stictionVelocity))
    a.error(a.statement().where,
            "the transition velocities must satisfy 0 < STICTION_TRANSITION_VELOCITY < "
            "FRICTION_TRANSITION_VELOCITY",
            "Give a positive stiction velocity smaller than the friction velocity.");
}

void rejectUnsupported(StatementArguments& a) {
  for (const char* name : {"ICURVE", "JCURVE", "AUGMENTED_LAGRANGIAN_FORMULATION"})
    if (const Argument* x = a.find(name))
      a.unsupported(*x,
                    "Remove it: contact of the GRAPHICS in IGEOM and JGEOM (3-D solids, or 2-D "
                    "CIRCLE, ARC, POINT and CURVE geometry, flipped by IFLIP_GEOMETRY and "
                    "JFLIP_GEOMETRY) with IMPACT, POISSON or a user normal law and Coulomb or "
                    "user friction is what the solver simulates.");
  for (const auto& [routine, function] : {std::pair{"NORMAL_ROUTINE", "NORMAL_FUNCTION"},
                                          std::pair{"FRICTION_ROUTINE", "FRICTION_FUNCTION"}})
    if (const Argument* x = a.find(routine); x && !a.find(function))
      a.error(*x, std::string(routine) + " without " + function + "=USER(...)",
              std::string("Add ") + function + "=USER(r1[,...,r30]), or remove " + routine + ".");
  if (const std::optional<std::string> type = a.word("TYPE"); type && *type != "SOLID_TO_SOLID")
    a.unsupported(*a.find("TYPE"), "Only TYPE = SOLID_TO_SOLID is supported.");
}

// The GRAPHICS kind a torus is refused against, with its article, for the message.
std::string shapeName(ContactSolid::Shape s) {
  using S = ContactSolid::Shape;
  if (s == S::Frustum) return "a CYLINDER or FRUSTUM";
  if (s == S::Ellipsoid) return "an ELLIPSOID of unequal scales";
  return "a 2-D geometry";
}

// Every I solid against every J solid must be a pair the narrow phase covers (theory §6c):
// not two PLANE solids, and a TORUS only against a PLANE, a sphere, a BOX, a mesh or a TORUS;
// one located message per pair.
bool pairsSupported(const Statement& s, const Contact& c, Diagnostics& diags) {
  using S = ContactSolid::Shape;
  bool ok = true;
  for (const ContactSolid& a : c.iSolids)
    for (const ContactSolid& b : c.jSolids) {
      const std::string pair = "GRAPHICS/" + std::to_string(a.graphicsId) + " against GRAPHICS/" +
                               std::to_string(b.graphicsId);
      if (a.shape == S::Plane && b.shape == S::Plane) {
        diags.error(s.where, s.subject(),
                    pair + ": two half-spaces (PLANE or OUTLINE) cannot be in contact",
                    "Replace one of the planes by a BOX, ELLIPSOID, CYLINDER or FRUSTUM.");
        ok = false;
        continue;
      }
      const bool torusA = a.shape == S::Torus, torusB = b.shape == S::Torus;
      if (!torusA && !torusB) continue;
      const ContactSolid& other = torusA ? b : a;
      if (other.shape == S::Plane || other.shape == S::Sphere || other.shape == S::Box ||
          other.shape == S::Mesh || other.shape == S::Torus)
        continue;
      diags.error(s.where, s.subject(),
                  pair +
                      ": a TORUS is in contact with a PLANE, a sphere (ELLIPSOID of equal "
                      "scales), a BOX, an EXTERNAL shell or a TORUS only, not with " +
                      shapeName(other.shape) + " (no analytic closest points for that pair)",
                  "Model the other solid as a PLANE, a sphere, a BOX, a TORUS or an EXTERNAL "
                  "shell (.shl, .stl).");
      ok = false;
    }
  return ok;
}

// A pair that needs FCL: the module must open (only such a model opens it), else the CONTACT is
// refused naming the pair and the paths tried (docs/architecture.md, "FCL module").
bool fclModuleAvailable(const Statement& s, const Contact& c, Diagnostics& diags) {
  for (const ContactSolid& a : c.iSolids)
    for (const ContactSolid& b : c.jSolids) {
      if (!libraryPair(a, b)) continue;
      std::string why;
      if (user::fclModuleEntry(why)) return true;
      diags.error(s.where, s.subject(),
                  "GRAPHICS/" + std::to_string(a.graphicsId) + " against GRAPHICS/" +
                      std::to_string(b.graphicsId) +
                      " needs the FCL narrow phase, whose module did not load: " + why,
                  "Build the openmss_fcl target (or install it in LIBDIR/openmss), or set "
                  "OPENMSS_FCL_MODULE to its path.");
      return false;
    }
  return true;
}

}  // namespace

void buildContacts(const std::vector<const Statement*>& statements,
                   const language::Dataset& dataset, Model& model, Diagnostics& diags,
                   const std::function<void(const Statement&)>& done) {
  if (statements.empty()) return;
  std::map<long, const Statement*> graphics;
  for (const Statement& g : dataset.statements)
    if (g.name == "GRAPHICS" && g.id) graphics.emplace(*g.id, &g);
  // One allocation for the 500,500 CONTACTs of the 1000-sphere pile, not a doubling array
  // whose last growth holds the old and the new one at once (docs/performance.md).
  model.contacts.reserve(model.contacts.size() + statements.size());
  for (size_t k = 0; k < statements.size(); ++k) {
    // The statement before this one is finished with, whichever way its iteration ended.
    if (done && k > 0) done(*statements[k - 1]);
    const Statement* s = statements[k];
    StatementArguments a(*s, diags);
    Contact c;
    c.id = s->id.value_or(0);
    c.where = s->where;
    rejectUnsupported(a);
    readNormalLaw(a, c);
    readFriction(a, c);
    if (const Argument* f = a.find("FACETING_TOLERANCE"))
      diags.warning(f->where, s->subject(),
                    "FACETING_TOLERANCE has no effect: the solids are exact, not faceted",
                    "Remove it to silence this warning.");
    const bool iOk = readSide(*s, "IGEOM", graphics, model, diags, c.iSolids, c.iPart);
    const bool jOk = readSide(*s, "JGEOM", graphics, model, diags, c.jSolids, c.jPart);
    if (!iOk || !jOk || !a.ok()) continue;
    if (c.iPart == c.jPart) {
      diags.error(s->where, s->subject(),
                  "IGEOM and JGEOM are on the same part (PART/" +
                      std::to_string(model.parts[c.iPart].id) + "): it cannot touch itself",
                  "Name the solids of two different parts.");
      continue;
    }
    if (!checkPlanarContact(*s, c, model, diags)) continue;
    if (!pairsSupported(*s, c, diags)) continue;
    if (!fclModuleAvailable(*s, c, diags)) continue;
    if (!bindContactUserLaws(*s, model, c, diags)) continue;
    c.iMarker = c.iSolids.front().marker;
    c.jMarker = c.jSolids.front().marker;
    model.contacts.push_back(std::move(c));
  }
  if (done) done(*statements.back());
}

bool libraryPair(const ContactSolid& a, const ContactSolid& b) {
  using S = ContactSolid::Shape;
  if (planarShape(a.shape) || planarShape(b.shape)) return false;
  for (S s : {a.shape, b.shape})
    if (s == S::Plane || s == S::Torus) return false;
  auto curved = [](S s) { return s == S::Ellipsoid || s == S::Mesh; };
  if (curved(a.shape) || curved(b.shape)) return true;
  return a.shape == S::Frustum && b.shape == S::Frustum &&
         std::max(frustumHalfAngle(a), frustumHalfAngle(b)) > kMaxFrustumPairHalfAngle;
}

int findContact(const Model& model, long id) {
  for (size_t k = 0; k < model.contacts.size(); ++k)
    if (model.contacts[k].id == id) return static_cast<int>(k);
  return -1;
}

}  // namespace openmss::model
