#include "model/contact_builder.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include "model/contact_user_laws.hpp"
#include "model/graphics_builder.hpp"
#include "model/statement_arguments.hpp"

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

// One GRAPHICS solid for a CONTACT; false after a diagnostic at `where` (the IGEOM/JGEOM value).
bool readSolid(const Statement& g, const Model& model, const SourceLocation& where,
               const std::string& subject, Diagnostics& diags, ContactSolid& out) {
  const std::string kind = graphicsKind(g);
  out.graphicsId = g.id.value_or(0);
  out.where = g.where;
  if (kind == "ELLIPSOID") {
    const double x = graphicsNumber(g, "XSCALE"), y = graphicsNumber(g, "YSCALE"),
                 z = graphicsNumber(g, "ZSCALE");
    if (!(x > 0.0) || x != y || x != z) {
      diags.error(where, subject,
                  graphicsAt(g) + " is an ELLIPSOID with scales " + std::to_string(x) + ", " +
                      std::to_string(y) + ", " + std::to_string(z) +
                      ": only spheres (three equal positive scales) are supported as contact "
                      "geometry so far",
                  "Give XSCALE = YSCALE = ZSCALE (the diameter), or model the contact with "
                  "spheres.");
      return false;
    }
    out.shape = ContactSolid::Shape::Sphere;
    out.size = Eigen::Vector3d(0.5 * x, 0.0, 0.0);
    out.boundingRadius = 0.5 * x;
    out.marker = graphicsMarker(g, "CM", model, where, subject, diags);
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
    const Argument* f = g.find("FILE");
    const std::string file = f && !f->values.empty() ? f->values[0].written : "";
    const std::filesystem::path path =
        std::filesystem::path(model.file).parent_path() / std::filesystem::path(file);
    if (file.empty() || !std::filesystem::exists(path)) {
      diags.error(where, subject,
                  graphicsAt(g) + " reads its shell from the file '" + file +
                      "', which is missing (" + path.string() + ")",
                  "Put the file next to the data set, or replace the EXTERNAL geometry by "
                  "ELLIPSOID, BOX, CYLINDER or FRUSTUM solids.");
    } else {
      diags.error(where, subject,
                  graphicsAt(g) + " is an EXTERNAL shell (" + file +
                      "): shell and Parasolid files are not read yet",
                  "Replace it by ELLIPSOID (sphere), BOX, CYLINDER or FRUSTUM solids.");
    }
    return false;
  } else if (kind == "CYLINDER" || kind == "FRUSTUM") {
    if (!readFrustum(g, kind, model, where, subject, diags, out)) return false;
  } else if (kind == "PLANE") {
    if (!readPlane(g, model, where, subject, diags, out)) return false;
  } else if (kind == "TORUS") {
    diags.error(where, subject,
                graphicsAt(g) + " is a " + kind + ": contact with it is not supported yet",
                "Use ELLIPSOID (sphere), BOX, CYLINDER, FRUSTUM or PLANE solids.");
    return false;
  } else {
    diags.error(where, subject,
                graphicsAt(g) + " is " +
                    (kind.empty() ? "no solid" : "a " + kind + ", not a solid") +
                    ": CONTACT needs solids (a volume)",
                "Name ELLIPSOID (sphere), BOX, CYLINDER, FRUSTUM or PLANE GRAPHICS in IGEOM and "
                "JGEOM.");
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
  for (const char* name :
       {"ICURVE", "JCURVE", "IFLIP_GEOMETRY", "JFLIP_GEOMETRY", "AUGMENTED_LAGRANGIAN_FORMULATION"})
    if (const Argument* x = a.find(name))
      a.unsupported(*x,
                    "Remove it: 3-D solid contact (IGEOM, JGEOM) with IMPACT, POISSON or a "
                    "user normal law and Coulomb or user friction is what the solver "
                    "simulates.");
  for (const auto& [routine, function] : {std::pair{"NORMAL_ROUTINE", "NORMAL_FUNCTION"},
                                          std::pair{"FRICTION_ROUTINE", "FRICTION_FUNCTION"}})
    if (const Argument* x = a.find(routine); x && !a.find(function))
      a.error(*x, std::string(routine) + " without " + function + "=USER(...)",
              std::string("Add ") + function + "=USER(r1[,...,r30]), or remove " + routine + ".");
  if (const std::optional<std::string> type = a.word("TYPE"); type && *type != "SOLID_TO_SOLID")
    a.unsupported(*a.find("TYPE"), "Only TYPE = SOLID_TO_SOLID is supported.");
}

// Every I solid against every J solid must be a pair the narrow phase covers (theory §6c):
// two solids of revolution (CYLINDER, FRUSTUM) only with sides of half-angle up to
// kMaxFrustumPairHalfAngle; one located message per pair.
bool pairsSupported(const Statement& s, const Contact& c, Diagnostics& diags) {
  bool ok = true;
  for (const ContactSolid& a : c.iSolids)
    for (const ContactSolid& b : c.jSolids) {
      if (a.shape == ContactSolid::Shape::Plane && b.shape == ContactSolid::Shape::Plane) {
        diags.error(s.where, s.subject(),
                    "GRAPHICS/" + std::to_string(a.graphicsId) + " against GRAPHICS/" +
                        std::to_string(b.graphicsId) +
                        ": two PLANE solids (half-spaces) cannot be in contact",
                    "Replace one of the planes by a BOX, ELLIPSOID, CYLINDER or FRUSTUM.");
        ok = false;
        continue;
      }
      if (a.shape != ContactSolid::Shape::Frustum || b.shape != ContactSolid::Shape::Frustum)
        continue;
      const ContactSolid& steep = frustumHalfAngle(a) >= frustumHalfAngle(b) ? a : b;
      const double angle = frustumHalfAngle(steep);
      if (angle <= kMaxFrustumPairHalfAngle) continue;
      diags.error(s.where, s.subject(),
                  "GRAPHICS/" + std::to_string(a.graphicsId) + " against GRAPHICS/" +
                      std::to_string(b.graphicsId) +
                      ": contact between two CYLINDER/FRUSTUM solids needs sides within 5 "
                      "degrees of their axes (GRAPHICS/" +
                      std::to_string(steep.graphicsId) + " has " +
                      std::to_string(angle * 180.0 / M_PI) + " degrees)",
                  "Model the steep FRUSTUM as a CYLINDER, or one of the two as ELLIPSOID "
                  "(sphere) or BOX solids.");
      ok = false;
    }
  return ok;
}

}  // namespace

void buildContacts(const std::vector<const Statement*>& statements,
                   const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  if (statements.empty()) return;
  std::map<long, const Statement*> graphics;
  for (const Statement& g : dataset.statements)
    if (g.name == "GRAPHICS" && g.id) graphics.emplace(*g.id, &g);
  for (const Statement* s : statements) {
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
    if (!pairsSupported(*s, c, diags)) continue;
    if (!bindContactUserLaws(*s, model, c, diags)) continue;
    c.iMarker = c.iSolids.front().marker;
    c.jMarker = c.jSolids.front().marker;
    model.contacts.push_back(c);
  }
}

int findContact(const Model& model, long id) {
  for (size_t k = 0; k < model.contacts.size(); ++k)
    if (model.contacts[k].id == id) return static_cast<int>(k);
  return -1;
}

}  // namespace openmss::model
