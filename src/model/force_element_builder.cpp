#include "model/force_element_builder.hpp"

#include <cmath>
#include <optional>

#include "model/beam_stiffness.hpp"
#include "model/model_builder.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// A stiffness or damping coefficient: zero when not given, never negative.
double coefficient(StatementArguments& a, const char* name) {
  const double v = a.real(name).value_or(0.0);
  if (v < 0.0)
    a.error(*a.find(name), std::string(name) + " must not be negative",
            std::string("Give ") + name + " >= 0.");
  return v;
}

Eigen::Vector3d triple(StatementArguments& a, const char* name, bool nonNegative) {
  const Eigen::Vector3d out = a.vec3(name).value_or(Eigen::Vector3d::Zero());
  if (nonNegative && out.minCoeff() < 0.0)
    a.error(*a.find(name), std::string(name) + " must not be negative",
            std::string("Give three values >= 0 for ") + name + ".");
  return out;
}

// A 6x6 matrix entered by columns, top to bottom, then left to right (36 values).
Matrix6d matrixByColumns(const std::vector<double>& v) {
  Matrix6d m;
  for (int k = 0; k < 36; ++k) m(k % 6, k / 6) = v[k];
  return m;
}

// A symmetric 6x6 matrix from its upper triangle entered by columns (21 values).
Matrix6d symmetricFromUpperColumns(const std::vector<double>& v) {
  Matrix6d m;
  int k = 0;
  for (int c = 0; c < 6; ++c)
    for (int r = 0; r <= c; ++r) m(r, c) = m(c, r) = v[k++];
  return m;
}

struct GroundPose {
  Eigen::Vector3d p;
  Eigen::Matrix3d a;
};

// A marker's pose in ground at the data set's configuration.
GroundPose dataSetPose(const Model& model, int marker) {
  const Marker& mk = model.markers[marker];
  const Part& part = model.parts[mk.part];
  return {part.position + part.orientation * mk.position, part.orientation * mk.orientation};
}

bool samePart(const Model& model, int i, int j) {
  return model.markers[i].part == model.markers[j].part;
}

void rejectSamePart(const Statement& s, const Model& model, int i, int j, const char* jName,
                    Diagnostics& diags) {
  if (i < 0 || j < 0 || !samePart(model, i, j)) return;
  diags.error(s.where, s.subject(),
              std::string("I and ") + jName + " are on the same part (PART/" +
                  std::to_string(model.parts[model.markers[i].part].id) +
                  "): the force and its reaction cancel",
              std::string("Put I and ") + jName + " on the two parts the element connects.");
}

void buildSpringDamper(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  SpringDamper sd;
  sd.id = *s.id;
  sd.where = s.where;
  sd.iMarker = markerReference(model, s, "I", diags);
  sd.jMarker = markerReference(model, s, "J", diags);
  const bool translational = s.has("TRANSLATIONAL"), rotational = s.has("ROTATIONAL");
  if (translational == rotational) {
    diags.error(s.where, s.subject(), "give exactly one of TRANSLATIONAL and ROTATIONAL",
                "Add TRANSLATIONAL (K, C, LENGTH, FORCE) or ROTATIONAL (KT, CT, ANGLE, "
                "TORQUE).");
    return;
  }
  sd.rotational = rotational;
  static const char* kTranslational[4] = {"K", "C", "LENGTH", "FORCE"};
  static const char* kRotational[4] = {"KT", "CT", "ANGLE", "TORQUE"};
  const char* const* own = rotational ? kRotational : kTranslational;
  const char* const* other = rotational ? kTranslational : kRotational;
  for (int k = 0; k < 4; ++k)
    if (const Argument* arg = s.find(other[k]))
      diags.error(arg->where, s.subject(),
                  std::string(other[k]) + " belongs to a " +
                      (rotational ? "TRANSLATIONAL" : "ROTATIONAL") + " spring-damper",
                  std::string("Use ") + own[k] + " with " +
                      (rotational ? "ROTATIONAL" : "TRANSLATIONAL") + ".");
  sd.stiffness = coefficient(a, own[0]);
  sd.damping = coefficient(a, own[1]);
  sd.freeValue = a.real(own[2]).value_or(0.0);
  sd.preload = a.real(own[3]).value_or(0.0);
  if (sd.iMarker < 0 || sd.jMarker < 0) return;
  rejectSamePart(s, model, sd.iMarker, sd.jMarker, "J", diags);
  const GroundPose pi = dataSetPose(model, sd.iMarker), pj = dataSetPose(model, sd.jMarker);
  if (!rotational && (pi.p - pj.p).norm() == 0.0)
    diags.error(s.where, s.subject(),
                "I and J coincide at the data set's configuration: the direction of the force "
                "is undefined",
                "Place the I and J markers apart along the spring's line of action.");
  if (rotational) {
    const Eigen::Vector3d zi = pi.a.col(2), zj = pj.a.col(2);
    // The torque acts about z_J; ADAMS requires z_I along z_J (a revolute or cylindrical joint
    // usually keeps them so). 1e-6 rad tolerates round-off in data-set angles.
    if (zi.cross(zj).norm() > 1e-6 || zi.dot(zj) <= 0.0)
      diags.error(s.where, s.subject(),
                  "the z axes of I and J must be parallel and point the same way for a "
                  "ROTATIONAL spring-damper",
                  "Orient both markers with z along the axis of rotation.");
  }
  model.springDampers.push_back(sd);
}

void buildBushing(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  LinearField f;
  f.id = *s.id;
  f.kind = LinearField::Kind::Bushing;
  f.where = s.where;
  f.iMarker = markerReference(model, s, "I", diags);
  f.jMarker = markerReference(model, s, "J", diags);
  const Eigen::Vector3d k = triple(a, "K", true), c = triple(a, "C", true);
  const Eigen::Vector3d kt = triple(a, "KT", true), ct = triple(a, "CT", true);
  Vector6d stiffness, damping;
  stiffness << k, kt;
  damping << c, ct;
  f.stiffness = stiffness.asDiagonal();
  f.damping = damping.asDiagonal();
  f.preload << triple(a, "FORCE", false), triple(a, "TORQUE", false);
  if (f.iMarker < 0 || f.jMarker < 0) return;
  rejectSamePart(s, model, f.iMarker, f.jMarker, "J", diags);
  model.linearFields.push_back(f);
}

// CMATRIX (n values) or CRATIO times the stiffness: the damping of FIELD and BEAM.
void dampingOf(StatementArguments& a, int nValues, LinearField& f, Diagnostics& diags) {
  const Statement& s = a.statement();
  if (s.has("CMATRIX") && s.has("CRATIO")) {
    diags.error(s.find("CRATIO")->where, s.subject(), "give CMATRIX or CRATIO, not both",
                "Keep CMATRIX (the damping matrix) or CRATIO (damping = CRATIO * stiffness).");
    return;
  }
  if (auto c = a.numbers("CMATRIX", static_cast<size_t>(nValues)))
    f.damping = nValues == 36 ? matrixByColumns(*c) : symmetricFromUpperColumns(*c);
  if (s.has("CRATIO")) {
    const double ratio = coefficient(a, "CRATIO");
    f.damping = ratio * f.stiffness;
  }
}

void buildField(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  LinearField f;
  f.id = *s.id;
  f.kind = LinearField::Kind::Field;
  f.where = s.where;
  f.iMarker = markerReference(model, s, "I", diags);
  f.jMarker = markerReference(model, s, "J", diags);
  if (s.has("FUNCTION")) {  // FIESUB (docs/user-subroutines.md)
    if (f.iMarker < 0 || f.jMarker < 0) return;
    rejectSamePart(s, model, f.iMarker, f.jMarker, "J", diags);
    if (bindUserField(model, s, f, diags)) model.linearFields.push_back(f);
    return;
  }
  if (auto k = a.numbers("KMATRIX", 36)) {
    f.stiffness = matrixByColumns(*k);
  } else if (!s.has("KMATRIX")) {
    diags.error(s.where, s.subject(), "missing required argument KMATRIX",
                "Add KMATRIX=r1,...,r36 (the 6x6 stiffness by columns).");
  }
  dampingOf(a, 36, f, diags);
  if (auto l = a.numbers("LENGTH", 6)) f.reference = Vector6d(l->data());
  if (auto p = a.numbers("FORCE", 6)) f.preload = Vector6d(p->data());
  if (f.iMarker < 0 || f.jMarker < 0) return;
  rejectSamePart(s, model, f.iMarker, f.jMarker, "J", diags);
  model.linearFields.push_back(f);
}

void buildBeam(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  LinearField f;
  f.id = *s.id;
  f.kind = LinearField::Kind::Beam;
  f.where = s.where;
  f.iMarker = markerReference(model, s, "I", diags);
  f.jMarker = markerReference(model, s, "J", diags);
  if (const Argument* form = s.find("FORMULATION");
      form && !form->values.empty() && form->values[0].text != "LINEAR")
    diags.error(form->where, s.subject(),
                "FORMULATION=" + form->values[0].text + " is not supported yet",
                "Use FORMULATION=LINEAR (the linear Timoshenko beam, the default).");
  BeamSection b;
  bool ok = true;
  auto positive = [&](const char* name, double& out) {
    auto v = a.real(name);
    if (!v) {
      if (!s.has(name))
        diags.error(s.where, s.subject(), std::string("missing required argument ") + name,
                    std::string("Add ") + name + "=<value > 0>.");
      ok = false;
    } else if (*v <= 0.0) {
      diags.error(s.find(name)->where, s.subject(), std::string(name) + " must be positive",
                  std::string("Give ") + name + " > 0.");
      ok = false;
    }
    out = v.value_or(0.0);
  };
  positive("LENGTH", b.length);
  positive("AREA", b.area);
  positive("IXX", b.ixx);
  positive("IYY", b.iyy);
  positive("IZZ", b.izz);
  positive("EMODULUS", b.emodulus);
  positive("GMODULUS", b.gmodulus);
  b.asy = coefficient(a, "ASY");
  b.asz = coefficient(a, "ASZ");
  if (!ok) return;
  f.stiffness = beamStiffness(b);
  f.reference(0) = b.length;
  dampingOf(a, 21, f, diags);
  if (f.iMarker < 0 || f.jMarker < 0) return;
  rejectSamePart(s, model, f.iMarker, f.jMarker, "J", diags);
  // The undeformed beam runs from J along x_J to I at LENGTH with I's axes those of J. Say so
  // when the data set starts elsewhere: the beam then starts loaded.
  const GroundPose pi = dataSetPose(model, f.iMarker), pj = dataSetPose(model, f.jMarker);
  const Eigen::Vector3d offset = pj.a.transpose() * (pi.p - pj.p) - Eigen::Vector3d(b.length, 0, 0);
  const double turn = (pj.a.transpose() * pi.a - Eigen::Matrix3d::Identity()).norm();
  if (offset.norm() > 1e-6 * b.length || turn > 1e-6)
    diags.warning(s.where, s.subject(),
                  "the beam is deformed at the data set's configuration (I is not at LENGTH "
                  "along x_J with J's axes): it starts loaded",
                  "Place I on the x axis of J at distance LENGTH, axes parallel to J's, for an "
                  "unloaded start.");
  model.linearFields.push_back(f);
}

void buildVectorForce(const Statement& s, Model& model, Diagnostics& diags) {
  VectorForce v;
  v.id = *s.id;
  v.where = s.where;
  v.kind = s.name == "VFORCE"    ? VectorForce::Kind::VForce
           : s.name == "VTORQUE" ? VectorForce::Kind::VTorque
                                 : VectorForce::Kind::GForce;
  v.iMarker = markerReference(model, s, "I", diags);
  if (s.has("RM")) {
    v.rmMarker = markerReference(model, s, "RM", diags);
  } else {
    diags.error(s.where, s.subject(), "missing required argument RM",
                "Add RM=<marker id>: the axes that resolve the components.");
  }
  // JFLOAT: a floating marker on the part that takes the reaction.
  if (const Argument* a = s.find("JFLOAT")) {
    const long id = a->values.empty() ? 0 : static_cast<long>(a->values[0].number);
    auto it = model.markerIndex.find(id);
    if (it == model.markerIndex.end()) {
      diags.error(a->where, s.subject(),
                  "JFLOAT=" + std::to_string(id) + ": marker " + std::to_string(id) +
                      " does not exist",
                  "Use the id of a FLOATING MARKER on the part that takes the reaction.");
    } else if (!model.markers[it->second].floating) {
      diags.error(a->where, s.subject(),
                  "JFLOAT=" + std::to_string(id) + " must be a FLOATING marker",
                  "Write MARKER/" + std::to_string(id) + ", PART=<id>, FLOATING.");
    } else {
      v.jFloat = it->second;
    }
  }
  bool any = false;
  for (const char* name : {"FX", "FY", "FZ", "TX", "TY", "TZ"}) any = any || s.has(name);
  // FUNCTION=USER(...): the components come from VFOSUB/VTOSUB/GFOSUB, bound with the other
  // functions (bindForceElementFunctions).
  if (const Argument* fn = s.find("FUNCTION")) {
    if (fn->expression.rfind("USER", 0) != 0 || any) {
      diags.error(fn->where, s.subject(),
                  any ? "FUNCTION=USER(...) and component expressions exclude each other"
                      : "FUNCTION= must be USER(r1[,...,r30])",
                  "Give either the components (FX=, ...) or FUNCTION=USER(...) with ROUTINE=.");
      return;
    }
    any = true;
  } else if (const Argument* r = s.find("ROUTINE")) {
    diags.error(r->where, s.subject(), "ROUTINE= without FUNCTION=USER(...)",
                "Add FUNCTION=USER(r1[,...,r30]) or remove ROUTINE=.");
  }
  if (!any && !s.has("FUNCTION"))
    diags.error(s.where, s.subject(), "no component is given",
                std::string("Give ") +
                    (v.kind == VectorForce::Kind::VForce    ? "FX=, FY=, FZ="
                     : v.kind == VectorForce::Kind::VTorque ? "TX=, TY=, TZ="
                                                            : "FX= ... TZ=") +
                    " (an omitted component is zero).");
  if (v.iMarker < 0 || v.jFloat < 0 || v.rmMarker < 0 || !any) return;
  rejectSamePart(s, model, v.iMarker, v.jFloat, "JFLOAT", diags);
  model.vectorForces.push_back(std::move(v));
}

}  // namespace

bool isForceElementStatement(const std::string& name) {
  return name == "SPRINGDAMPER" || name == "BUSHING" || name == "FIELD" || name == "BEAM" ||
         name == "VFORCE" || name == "VTORQUE" || name == "GFORCE" || name == "NFORCE";
}

void buildForceElements(const std::vector<const Statement*>& statements, Model& model,
                        Diagnostics& diags) {
  for (const Statement* s : statements) {
    if (!s->id) continue;
    if (s->name == "SPRINGDAMPER")
      buildSpringDamper(*s, model, diags);
    else if (s->name == "BUSHING")
      buildBushing(*s, model, diags);
    else if (s->name == "FIELD")
      buildField(*s, model, diags);
    else if (s->name == "BEAM")
      buildBeam(*s, model, diags);
    else if (s->name == "NFORCE")
      buildNForce(*s, model, diags);  // nforce_builder.cpp
    else
      buildVectorForce(*s, model, diags);
  }
}

void bindForceElementFunctions(const std::vector<const Statement*>& statements, Model& model,
                               Diagnostics& diags) {
  static const char* kNames[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};
  for (const Statement* s : statements) {
    if (!s->id || !(s->name == "VFORCE" || s->name == "VTORQUE" || s->name == "GFORCE"))
      continue;
    const MeasureKind kind = s->name == "VFORCE"    ? MeasureKind::VForceForce
                             : s->name == "VTORQUE" ? MeasureKind::VTorqueForce
                                                    : MeasureKind::GForceForce;
    const int index = findForceElement(model, kind, *s->id);
    if (index < 0) continue;  // rejected while building
    VectorForce& v = model.vectorForces[index];
    if (const Argument* fn = s->find("FUNCTION")) {
      user::ElementData e;
      e.i = model.markers[static_cast<size_t>(v.iMarker)].id;
      e.jfloat = model.markers[static_cast<size_t>(v.jFloat)].id;
      e.rm = model.markers[static_cast<size_t>(v.rmMarker)].id;
      std::vector<BoundExpression> b(6);
      const int first = s->name == "VTORQUE" ? 3 : 0, count = s->name == "GFORCE" ? 6 : 3;
      std::vector<BoundExpression*> outputs;
      for (int c = 0; c < count; ++c) outputs.push_back(&b[static_cast<size_t>(first + c)]);
      const user::RoutineKind routine = s->name == "VFORCE"    ? user::RoutineKind::Vfosub
                                        : s->name == "VTORQUE" ? user::RoutineKind::Vtosub
                                                               : user::RoutineKind::Gfosub;
      if (bindUserRoutine(model, *s, *fn, routine, e, outputs, true, diags))
        for (int c = first; c < first + count; ++c)
          v.components[static_cast<size_t>(c)] = std::move(b[static_cast<size_t>(c)]);
      continue;
    }
    for (int c = 0; c < 6; ++c) {
      const Argument* a = s->find(kNames[c]);
      if (!a) continue;
      BoundExpression b;
      if (bindExpression(model, a->expression, a->valueWhere, s->subject(), true, diags, b))
        v.components[c] = std::move(b);
    }
  }
}

bool forceElementReadBack(const std::string& function, MeasureKind* kind) {
  static const std::pair<const char*, MeasureKind> kFunctions[] = {
      {"SPDP", MeasureKind::SpringDamperForce}, {"BUSH", MeasureKind::BushingForce},
      {"FIELD", MeasureKind::FieldForce},       {"BEAM", MeasureKind::BeamForce},
      {"VFORCE", MeasureKind::VForceForce},     {"VTORQ", MeasureKind::VTorqueForce},
      {"GFORCE", MeasureKind::GForceForce},     {"CONTACT", MeasureKind::ContactForce}};
  for (const auto& [name, k] : kFunctions)
    if (function == name) {
      if (kind) *kind = k;
      return true;
    }
  return false;
}

int findForceElement(const Model& model, MeasureKind kind, long id) {
  auto find = [id](const auto& elements, auto matches) {
    for (size_t k = 0; k < elements.size(); ++k)
      if (elements[k].id == id && matches(elements[k])) return static_cast<int>(k);
    return -1;
  };
  auto fieldOf = [&](LinearField::Kind lk) {
    return find(model.linearFields, [lk](const LinearField& f) { return f.kind == lk; });
  };
  auto vectorOf = [&](VectorForce::Kind vk) {
    return find(model.vectorForces, [vk](const VectorForce& v) { return v.kind == vk; });
  };
  switch (kind) {
    case MeasureKind::SpringDamperForce:
      return find(model.springDampers, [](const SpringDamper&) { return true; });
    case MeasureKind::BushingForce: return fieldOf(LinearField::Kind::Bushing);
    case MeasureKind::FieldForce: return fieldOf(LinearField::Kind::Field);
    case MeasureKind::BeamForce: return fieldOf(LinearField::Kind::Beam);
    case MeasureKind::VForceForce: return vectorOf(VectorForce::Kind::VForce);
    case MeasureKind::VTorqueForce: return vectorOf(VectorForce::Kind::VTorque);
    case MeasureKind::GForceForce: return vectorOf(VectorForce::Kind::GForce);
    case MeasureKind::ContactForce:
      return find(model.contacts, [](const Contact&) { return true; });
    default: return -1;
  }
}

}  // namespace openmss::model
