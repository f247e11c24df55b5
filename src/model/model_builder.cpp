#include "model/model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/rotation.hpp"
#include "language/schema.hpp"
#include "model/units_table.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// Typed access to a statement's arguments with diagnostics. The reader already checked value
// types and counts against the schema; these checks guard the model's own requirements.
class Args {
 public:
  Args(const Statement& s, Diagnostics& d) : s_(s), d_(d) {}

  bool has(const char* name) const { return s_.has(name); }

  std::optional<double> real(const char* name) const {
    const Argument* a = s_.find(name);
    if (!a) return std::nullopt;
    if (a->values.size() != 1 || a->values[0].kind != language::Value::Kind::Number) {
      d_.error(a->where, s_.subject(), std::string(name) + " needs one number",
               "Write " + std::string(name) + "=<number>.");
      return std::nullopt;
    }
    return a->values[0].number;
  }

  std::optional<Eigen::Vector3d> vec3(const char* name) const {
    const Argument* a = s_.find(name);
    if (!a) return std::nullopt;
    if (a->values.size() != 3 || !allNumbers(*a)) {
      d_.error(a->where, s_.subject(), std::string(name) + " needs three numbers",
               "Write " + std::string(name) + "=x,y,z.");
      return std::nullopt;
    }
    return Eigen::Vector3d(a->values[0].number, a->values[1].number, a->values[2].number);
  }

  // An identifier argument (I=, J=, PART=, ...).
  std::optional<long> id(const char* name) const {
    const Argument* a = s_.find(name);
    if (!a) return std::nullopt;
    if (a->values.size() != 1 || a->values[0].kind != language::Value::Kind::Number ||
        a->values[0].number != std::floor(a->values[0].number) || a->values[0].number <= 0) {
      d_.error(a->where, s_.subject(), std::string(name) + " needs one positive identifier",
               "Write " + std::string(name) + "=<id>.");
      return std::nullopt;
    }
    return static_cast<long>(a->values[0].number);
  }

  std::optional<std::string> word(const char* name) const {
    const Argument* a = s_.find(name);
    if (!a) return std::nullopt;
    if (a->values.size() != 1 || a->values[0].kind != language::Value::Kind::Word) {
      d_.error(a->where, s_.subject(), std::string(name) + " needs one word");
      return std::nullopt;
    }
    return a->values[0].text;
  }

  void require(const char* name, const char* what) const {
    // The reader already reports arguments its schema marks as required.
    if (const language::StatementSpec* spec = language::findStatementSpec(s_.name))
      for (const auto& arg : spec->arguments)
        if (arg.name == name && arg.required) return;
    if (!s_.has(name))
      d_.error(s_.where, s_.subject(), std::string("missing required argument ") + name,
               std::string("Add ") + name + "=" + what + ".");
  }

 private:
  static bool allNumbers(const Argument& a) {
    for (const auto& v : a.values)
      if (v.kind != language::Value::Kind::Number) return false;
    return true;
  }
  const Statement& s_;
  Diagnostics& d_;
};

// Orientation from REULER or ZP/XP (in the reference frame), with the position origin.
Eigen::Matrix3d orientationOf(const Statement& s, const Args& a, const char* zName,
                              const char* xName, const Eigen::Vector3d& origin,
                              Diagnostics& diags) {
  if (auto e = a.vec3("REULER")) return matrixFromEuler313((*e)(0), (*e)(1), (*e)(2));
  auto z = a.vec3(zName);
  auto x = a.vec3(xName);
  if (!z && !x) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d m;
  if (!matrixFromAxisPoints(origin, z.value_or(origin), x.value_or(origin), z.has_value(),
                            x.has_value(), &m)) {
    diags.error(s.where, s.subject(),
                std::string("the ") + zName + "/" + xName +
                    " points do not define a frame (a point coincides with the origin, or the "
                    "x point lies on the z axis)",
                "Move the points so that z is along the origin->ZP line and XP is off that line.");
    return Eigen::Matrix3d::Identity();
  }
  return m;
}

struct RawPart {
  const Statement* s = nullptr;
  Eigen::Vector3d qg = Eigen::Vector3d::Zero();
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();  // BCS in ground
  std::optional<long> cm, im;
  Eigen::Vector3d ip = Eigen::Vector3d::Zero();
  Eigen::Vector3d products = Eigen::Vector3d::Zero();
};

struct RawMarker {
  const Statement* s = nullptr;
  long part = 0;
  Eigen::Vector3d qp = Eigen::Vector3d::Zero();  // in BCS
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  std::optional<long> rm;
};

const std::set<std::string>& supportedStatements() {
  static const std::set<std::string> s = {"UNITS",  "PART",     "MARKER",  "JOINT",
                                          "MOTION", "SFORCE",   "ACCGRAV", "REQUEST",
                                          "GRAPHICS", "OUTPUT", "END",     "TITLE"};
  return s;
}

}  // namespace

bool bindExpression(const Model& model, const std::string& text, const SourceLocation& where,
                    const std::string& subject, bool forForces, Diagnostics& diags,
                    BoundExpression& out) {
  if (!expr::Expression::parse(text, where, subject, diags, out.expression)) return false;
  bool ok = true;
  out.measures.clear();
  for (const auto& call : out.expression.hostCalls()) {
    SourceLocation at = where;
    if (call.column > 0) at.column = where.column > 0 ? where.column + call.column - 1 : 0;
    auto fail = [&](const std::string& msg, const std::string& hint) {
      diags.error(at, subject, call.name + ": " + msg, hint);
      ok = false;
    };
    auto marker = [&](size_t k, bool allowZero) -> int {
      if (k >= call.args.size()) return -1;
      long idv = call.args[k];
      if (idv == 0 && allowZero) return -1;
      auto it = model.markerIndex.find(idv);
      if (it == model.markerIndex.end()) {
        fail("marker " + std::to_string(idv) + " does not exist",
             "Use the id of a MARKER statement of this data set.");
        return -2;
      }
      return it->second;
    };
    Measure m;
    static const std::map<std::string, MeasureKind> kinematic = {
        {"DX", MeasureKind::DX},       {"DY", MeasureKind::DY},
        {"DZ", MeasureKind::DZ},       {"DM", MeasureKind::DM},
        {"VX", MeasureKind::VX},       {"VY", MeasureKind::VY},
        {"VZ", MeasureKind::VZ},       {"VM", MeasureKind::VM},
        {"VR", MeasureKind::VR},       {"WX", MeasureKind::WX},
        {"WY", MeasureKind::WY},       {"WZ", MeasureKind::WZ},
        {"WM", MeasureKind::WM},       {"ACCX", MeasureKind::ACCX},
        {"ACCY", MeasureKind::ACCY},   {"ACCZ", MeasureKind::ACCZ},
        {"ACCM", MeasureKind::ACCM},   {"WDTX", MeasureKind::WDTX},
        {"WDTY", MeasureKind::WDTY},   {"WDTZ", MeasureKind::WDTZ},
        {"WDTM", MeasureKind::WDTM},   {"PSI", MeasureKind::PSI},     {"THETA", MeasureKind::THETA},
        {"PHI", MeasureKind::PHI},     {"YAW", MeasureKind::YAW},
        {"PITCH", MeasureKind::PITCH}, {"ROLL", MeasureKind::ROLL}};
    if (auto it = kinematic.find(call.name); it != kinematic.end()) {
      m.kind = it->second;
      // Argument pattern F(i [,j] [,k] [,l]); l (the derivative frame) must be ground for now.
      m.i = marker(0, false);
      m.j = marker(1, true);
      bool usesK = !(m.kind == MeasureKind::DM || m.kind == MeasureKind::VM ||
                     m.kind == MeasureKind::VR || m.kind == MeasureKind::WM ||
                     m.kind == MeasureKind::ACCM || m.kind == MeasureKind::WDTM ||
                     (m.kind >= MeasureKind::AX && m.kind <= MeasureKind::ROLL));
      if (usesK) m.k = marker(2, true);
      size_t lPos = usesK ? 3 : 2;
      if (call.args.size() > lPos && call.args[lPos] != 0)
        fail("time derivatives in a moving frame (the l argument) are not supported yet",
             "Omit the last argument or give 0 so derivatives are taken in ground.");
      if (m.i == -1) fail("the first marker is required", "Give the id of the measured marker.");
    } else if (call.name == "ORIENT") {
      m.kind = MeasureKind::Orient;
      m.code = call.args.size() > 0 ? static_cast<int>(call.args[0]) : 0;
      m.component = call.args.size() > 1 ? static_cast<int>(call.args[1]) : 0;
      m.i = marker(2, false);
      m.j = marker(3, true);
      const bool known = m.code == 27 && m.component >= 1 && m.component <= 4;
      if (!known)
        fail("orientation code " + std::to_string(m.code) + " component " +
                 std::to_string(m.component) + " is not supported yet",
             "Use code 27 (Euler parameters, components 1-4).");
    } else if (call.name == "JOINT" || call.name == "MOTION" || call.name == "SFORCE") {
      m.kind = call.name == "JOINT" ? MeasureKind::JointForce
               : call.name == "MOTION" ? MeasureKind::MotionForce
                                        : MeasureKind::SForceForce;
      long eid = call.args.size() > 0 ? call.args[0] : 0;
      m.atJ = call.args.size() > 1 ? static_cast<int>(call.args[1]) : 0;
      m.component = call.args.size() > 2 ? static_cast<int>(call.args[2]) : 0;
      m.k = marker(3, true);
      int found = -1;
      if (m.kind == MeasureKind::JointForce) {
        if (auto ji = model.jointIndex.find(eid); ji != model.jointIndex.end()) found = ji->second;
      } else if (m.kind == MeasureKind::MotionForce) {
        for (size_t q = 0; q < model.motions.size(); ++q)
          if (model.motions[q].id == eid) found = static_cast<int>(q);
      } else {
        for (size_t q = 0; q < model.sforces.size(); ++q)
          if (model.sforces[q].id == eid) found = static_cast<int>(q);
      }
      if (found < 0)
        fail(call.name + "/" + std::to_string(eid) + " does not exist",
             "Use the id of a " + call.name + " statement of this data set.");
      m.element = found;
      if (m.atJ != 0 && m.atJ != 1) fail("the second argument must be 0 (at I) or 1 (at J)", "");
      if (m.component < 1 || m.component > 8)
        fail("the component must be 1 to 8", "1 |F|, 2-4 Fx Fy Fz, 5 |T|, 6-8 Tx Ty Tz.");
    } else {
      fail("this function is not supported yet by the solver",
           "Remove it or replace it by a supported function; see README.md for the list.");
      continue;
    }
    if (forForces && (m.needsDynamics() || m.kind == MeasureKind::Orient))
      fail("functions of accelerations, reaction forces or ORIENT are not supported yet in "
           "force functions",
           "Use it in a REQUEST, or express the force through displacements and velocities.");
    out.measures.push_back(m);
  }
  return ok;
}

bool buildModel(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  const int errorsBefore = diags.errorCount();
  model = Model{};
  model.title = dataset.title;
  model.file = dataset.file;

  std::vector<RawPart> rawParts;
  std::vector<RawMarker> rawMarkers;
  std::vector<const Statement*> joints, motions, sforces, requests;
  long lastPartId = 0;

  for (const Statement& s : dataset.statements) {
    Args a(s, diags);
    if (!supportedStatements().count(s.name)) {
      diags.error(s.where, s.subject(), s.name + " is not supported yet by the solver",
                  "Remove the statement, or run it with a tool that supports it; README.md "
                  "lists what is supported.");
      continue;
    }
    if (s.name == "UNITS") {
      applyUnits(s, model.units, diags);
    } else if (s.name == "PART") {
      RawPart p;
      p.s = &s;
      if (!s.id) continue;
      lastPartId = *s.id;
      p.qg = a.vec3("QG").value_or(Eigen::Vector3d::Zero());
      p.a = orientationOf(s, a, "ZG", "XG", p.qg, diags);
      p.cm = a.id("CM");
      p.im = a.id("IM");
      if (const Argument* ip = s.find("IP")) {
        if (ip->values.size() != 3 && ip->values.size() != 6) {
          diags.error(ip->where, s.subject(), "IP needs 3 or 6 numbers",
                      "Write IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz].");
        } else {
          for (int k = 0; k < 3; ++k) p.ip(k) = ip->values[k].number;
          if (ip->values.size() == 6)
            for (int k = 0; k < 3; ++k) p.products(k) = ip->values[3 + k].number;
        }
      }
      for (const char* unsupported : {"VM", "WM", "EXACT", "IM"}) {
        if (a.has(unsupported) && std::string(unsupported) != "IM")
          diags.error(s.find(unsupported)->where, s.subject(),
                      std::string(unsupported) + " is not supported yet",
                      "Remove it; initial velocities refer to the CM marker.");
      }
      rawParts.push_back(p);
    } else if (s.name == "MARKER") {
      if (!s.id) continue;
      RawMarker m;
      m.s = &s;
      if (auto part = a.id("PART")) {
        m.part = *part;
      } else if (lastPartId != 0) {
        m.part = lastPartId;  // ADAMS: PART defaults to the preceding PART statement
      } else {
        a.require("PART", "<part id>");
        continue;
      }
      for (const char* unsupported : {"FLOATING", "POINT_MASS", "FLEX_BODY", "NODE", "FE_PART",
                                      "NODE_LABEL", "USEXP"})
        if (a.has(unsupported))
          diags.error(s.find(unsupported)->where, s.subject(),
                      std::string(unsupported) + " markers are not supported yet",
                      "Use a fixed marker on a rigid PART.");
      m.qp = a.vec3("QP").value_or(Eigen::Vector3d::Zero());
      m.a = orientationOf(s, a, "ZP", "XP", m.qp, diags);
      m.rm = a.id("RM");
      rawMarkers.push_back(m);
    } else if (s.name == "JOINT") {
      joints.push_back(&s);
    } else if (s.name == "MOTION") {
      motions.push_back(&s);
    } else if (s.name == "SFORCE") {
      sforces.push_back(&s);
    } else if (s.name == "REQUEST") {
      requests.push_back(&s);
    } else if (s.name == "ACCGRAV") {
      model.gravity = Eigen::Vector3d(a.real("IGRAV").value_or(0.0), a.real("JGRAV").value_or(0.0),
                                      a.real("KGRAV").value_or(0.0));
    } else if (s.name == "OUTPUT") {
      for (const Argument& arg : s.args) {
        if (arg.name == "REQSAVE") model.output.reqsave = true;
        else if (arg.name == "NOSEPARATOR") model.output.noseparator = true;
        else if (arg.name == "SEPARATOR") model.output.noseparator = false;
        else if (arg.name == "GRSAVE")
          diags.warning(arg.where, s.subject(),
                        "GRSAVE: the graphics file is not written yet; the run goes on without it",
                        "Remove GRSAVE to silence this warning.");
        else
          diags.warning(arg.where, s.subject(),
                        arg.name + " is not supported yet and has no effect on this run",
                        "Remove it to silence this warning.");
      }
    }
    // GRAPHICS: read and checked by the reader; the solver writes no graphics file yet.
  }

  // Parts.
  std::map<long, size_t> rawPartIndex;
  for (const RawPart& rp : rawParts) {
    Part p;
    p.id = *rp.s->id;
    p.where = rp.s->where;
    p.ground = rp.s->has("GROUND");
    if (model.partIndex.count(p.id)) continue;  // the reader already warned about duplicates
    Args a(*rp.s, diags);
    if (!p.ground) {
      p.mass = a.real("MASS").value_or(0.0);
      const char* v[3] = {"VX", "VY", "VZ"};
      const char* w[3] = {"WX", "WY", "WZ"};
      for (int k = 0; k < 3; ++k) {
        if (auto x = a.real(v[k])) p.velocity[k] = *x;
        if (auto x = a.real(w[k])) p.angularVelocity[k] = *x;
      }
    }
    rawPartIndex[p.id] = model.parts.size();
    model.partIndex[p.id] = static_cast<int>(model.parts.size());
    model.parts.push_back(p);
  }
  std::vector<int> grounds;
  for (size_t k = 0; k < model.parts.size(); ++k)
    if (model.parts[k].ground) grounds.push_back(static_cast<int>(k));
  if (grounds.empty()) {
    diags.error({dataset.file, 0, 0}, "", "the data set has no ground part",
                "Add PART/<id>, GROUND.");
  } else {
    model.groundPart = grounds[0];
    for (size_t k = 1; k < grounds.size(); ++k)
      diags.error(model.parts[grounds[k]].where, "PART/" + std::to_string(model.parts[grounds[k]].id),
                  "a data set may have only one ground part; PART/" +
                      std::to_string(model.parts[grounds[0]].id) + " is ground already",
                  "Remove GROUND from one of them.");
  }

  // Markers: first their pose in ground at the data set's configuration.
  std::map<long, Eigen::Vector3d> markerPos;
  std::map<long, Eigen::Matrix3d> markerRot;
  std::map<long, long> markerPart;
  for (const RawMarker& rm : rawMarkers) {
    long mid = *rm.s->id;
    auto pit = rawPartIndex.find(rm.part);
    if (pit == rawPartIndex.end()) {
      const Argument* pa = rm.s->find("PART");
      diags.error(pa ? pa->where : rm.s->where, rm.s->subject(),
                  "PART/" + std::to_string(rm.part) + " does not exist",
                  "Use the id of a PART statement of this data set.");
      continue;
    }
    const RawPart& part = rawParts[pit->second];
    Eigen::Vector3d qp = rm.qp;
    Eigen::Matrix3d a = rm.a;
    if (rm.rm) {
      // QP and orientation are given in the axes of a reference marker on the same part.
      auto found = std::find_if(rawMarkers.begin(), rawMarkers.end(),
                                [&](const RawMarker& o) { return *o.s->id == *rm.rm; });
      if (found == rawMarkers.end() || found->part != rm.part || found->rm) {
        diags.error(rm.s->find("RM")->where, rm.s->subject(),
                    "RM=" + std::to_string(*rm.rm) +
                        " must be a marker on the same part positioned without RM",
                    "Give a marker of PART/" + std::to_string(rm.part) + ".");
        continue;
      }
      qp = found->qp + found->a * rm.qp;
      a = found->a * rm.a;
    }
    markerPos[mid] = part.qg + part.a * qp;
    markerRot[mid] = part.a * a;
    markerPart[mid] = rm.part;
  }

  // Body frames: origin at the CM marker, its axes (the inertia axes).
  for (size_t k = 0; k < model.parts.size(); ++k) {
    Part& p = model.parts[k];
    const RawPart& rp = rawParts[rawPartIndex[p.id]];
    const std::string subject = "PART/" + std::to_string(p.id);
    if (p.ground) {
      p.position = Eigen::Vector3d::Zero();
      p.orientation = Eigen::Matrix3d::Identity();
      continue;
    }
    if (!rp.cm) {
      diags.error(p.where, subject, "a moving part needs a CM marker",
                  "Add CM=<marker id> naming a marker on this part at its centre of mass.");
      continue;
    }
    if (!markerPart.count(*rp.cm) || markerPart[*rp.cm] != p.id) {
      diags.error(rp.s->find("CM")->where, subject,
                  "CM marker " + std::to_string(*rp.cm) + " is not a marker of this part",
                  "Give a MARKER with PART=" + std::to_string(p.id) + ".");
      continue;
    }
    if (p.mass <= 0.0)
      diags.error(p.where, subject, "a moving part needs a positive MASS",
                  "Give MASS=<value> > 0 (or make the part GROUND).");
    p.position = markerPos[*rp.cm];
    p.orientation = markerRot[*rp.cm];
    // Inertia about the IM marker (default CM) in IM axes; ADAMS products are +integrals.
    Eigen::Matrix3d iim;
    iim << rp.ip(0), -rp.products(0), -rp.products(1), -rp.products(0), rp.ip(1),
        -rp.products(2), -rp.products(1), -rp.products(2), rp.ip(2);
    Eigen::Matrix3d iG;  // in ground axes, about the CM
    if (rp.im && *rp.im != *rp.cm) {
      if (!markerPart.count(*rp.im) || markerPart[*rp.im] != p.id) {
        diags.error(rp.s->find("IM")->where, subject,
                    "IM marker " + std::to_string(*rp.im) + " is not a marker of this part",
                    "Give a MARKER with PART=" + std::to_string(p.id) + ".");
        continue;
      }
      const Eigen::Matrix3d& aim = markerRot[*rp.im];
      Eigen::Vector3d d = markerPos[*rp.im] - p.position;
      // Parallel-axis theorem back from the IM origin to the CM.
      iG = aim * iim * aim.transpose() -
           p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    } else {
      iG = p.orientation * iim * p.orientation.transpose();
    }
    p.inertia = p.orientation.transpose() * iG * p.orientation;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(p.inertia);
    const Eigen::Vector3d pm = eig.eigenvalues();
    if (pm.minCoeff() <= 0.0 || pm(0) + pm(1) < pm(2) * (1 - 1e-9))
      diags.error(rp.s->find("IP") ? rp.s->find("IP")->where : p.where, subject,
                  "the inertia tensor is not physical (principal moments must be positive and "
                  "satisfy the triangle inequality)",
                  "Check IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz].");
    p.body = model.bodyCount();
    model.movingParts.push_back(static_cast<int>(k));
  }

  // Markers relative to their body frames.
  for (const RawMarker& rm : rawMarkers) {
    long mid = *rm.s->id;
    if (!markerPos.count(mid) || model.markerIndex.count(mid)) continue;
    Marker m;
    m.id = mid;
    m.where = rm.s->where;
    m.part = model.partIndex[rm.part];
    const Part& p = model.parts[m.part];
    m.position = p.orientation.transpose() * (markerPos[mid] - p.position);
    m.orientation = p.orientation.transpose() * markerRot[mid];
    model.markerIndex[mid] = static_cast<int>(model.markers.size());
    model.markers.push_back(m);
  }

  auto markerRef = [&](const Statement& s, const char* name) -> int {
    Args a(s, diags);
    auto idv = a.id(name);
    if (!idv) {
      if (!s.has(name)) a.require(name, "<marker id>");
      return -1;
    }
    auto it = model.markerIndex.find(*idv);
    if (it == model.markerIndex.end()) {
      diags.error(s.find(name)->where, s.subject(),
                  std::string(name) + "=" + std::to_string(*idv) + ": marker " +
                      std::to_string(*idv) + " does not exist",
                  "Use the id of a MARKER statement of this data set.");
      return -1;
    }
    return it->second;
  };

  // Joints.
  for (const Statement* s : joints) {
    if (!s->id) continue;
    Joint j;
    j.id = *s->id;
    j.where = s->where;
    static const std::pair<const char*, JointType> types[] = {
        {"REVOLUTE", JointType::Revolute},       {"SPHERICAL", JointType::Spherical},
        {"UNIVERSAL", JointType::Universal},     {"HOOKE", JointType::Hooke},
        {"TRANSLATIONAL", JointType::Translational}, {"CYLINDRICAL", JointType::Cylindrical},
        {"FIXED", JointType::Fixed}};
    int nTypes = 0;
    for (const auto& [name, type] : types)
      if (s->has(name)) { j.type = type; ++nTypes; }
    for (const char* other : {"CONVEL", "PLANAR", "RACKPIN", "SCREW"})
      if (s->has(other)) {
        diags.error(s->where, s->subject(), std::string(other) + " joints are not supported yet",
                    "Supported joint types: REVOLUTE, SPHERICAL, UNIVERSAL, HOOKE, "
                    "TRANSLATIONAL, CYLINDRICAL, FIXED.");
        nTypes = -100;
      }
    if (nTypes == 0)
      diags.error(s->where, s->subject(), "the joint type is missing",
                  "Add one of REVOLUTE, SPHERICAL, UNIVERSAL, HOOKE, TRANSLATIONAL, "
                  "CYLINDRICAL, FIXED.");
    else if (nTypes > 1)
      diags.error(s->where, s->subject(), "more than one joint type is given",
                  "Keep exactly one joint type.");
    j.iMarker = markerRef(*s, "I");
    j.jMarker = markerRef(*s, "J");
    for (const char* ic : {"IC", "ICTRAN", "ICROT"})
      if (s->has(ic))
        diags.error(s->find(ic)->where, s->subject(),
                    std::string(ic) + ": joint initial conditions are not supported yet",
                    "Remove it and set the initial configuration with the markers.");
    if (j.iMarker >= 0 && j.jMarker >= 0 &&
        model.markers[j.iMarker].part == model.markers[j.jMarker].part)
      diags.error(s->where, s->subject(),
                  "I and J markers are on the same part (PART/" +
                      std::to_string(model.parts[model.markers[j.iMarker].part].id) + ")",
                  "A joint connects two parts: put I and J on different parts.");
    if (nTypes == 1 && j.iMarker >= 0 && j.jMarker >= 0) {
      model.jointIndex[j.id] = static_cast<int>(model.joints.size());
      model.joints.push_back(j);
    }
  }

  // Motions.
  for (const Statement* s : motions) {
    if (!s->id) continue;
    Args a(*s, diags);
    Motion m;
    m.id = *s->id;
    m.where = s->where;
    if (s->has("I") || s->has("J")) {
      diags.error(s->where, s->subject(), "MOTION on a marker pair (I=, J=) is not supported yet",
                  "Drive a joint with JOINT=<id>.");
      continue;
    }
    for (const char* kind : {"VELOCITY", "ACCELERATION", "ICDISP", "ICVEL"})
      if (s->has(kind))
        diags.error(s->find(kind)->where, s->subject(),
                    std::string(kind) + " motions are not supported yet",
                    "Give the motion as a displacement function of TIME.");
    auto jid = a.id("JOINT");
    if (!jid) {
      if (!s->has("JOINT")) a.require("JOINT", "<joint id>");
      continue;
    }
    auto it = model.jointIndex.find(*jid);
    if (it == model.jointIndex.end()) {
      diags.error(s->find("JOINT")->where, s->subject(),
                  "JOINT/" + std::to_string(*jid) + " does not exist (or is invalid)",
                  "Use the id of a JOINT statement of this data set.");
      continue;
    }
    m.joint = it->second;
    JointType jt = model.joints[m.joint].type;
    if (jt == JointType::Revolute) m.rotation = true;
    else if (jt == JointType::Translational) m.rotation = false;
    else if (jt == JointType::Cylindrical) {
      if (s->has("TRANSLATION") == s->has("ROTATION")) {
        diags.error(s->where, s->subject(),
                    "a motion on a cylindrical joint needs exactly one of TRANSLATION, ROTATION",
                    "Add TRANSLATION or ROTATION.");
        continue;
      }
      m.rotation = s->has("ROTATION");
    } else {
      diags.error(s->where, s->subject(),
                  std::string("a joint motion needs a revolute, translational or cylindrical "
                              "joint; JOINT/") + std::to_string(*jid) + " is " + jointTypeName(jt),
                  "Drive a revolute, translational or cylindrical joint.");
      continue;
    }
    const Argument* f = s->find("FUNCTION");
    if (!f) {
      a.require("FUNCTION", "<expression of TIME>");
      continue;
    }
    if (f->expression.rfind("USER", 0) == 0) {
      diags.error(f->where, s->subject(), "FUNCTION=USER(...) motions are not supported yet",
                  "Write the motion as a function expression of TIME.");
      continue;
    }
    if (!expr::Expression::parse(f->expression, f->valueWhere, s->subject(), diags, m.function))
      continue;
    if (!m.function.hostCalls().empty()) {
      diags.error(f->valueWhere, s->subject(),
                  "a MOTION function may depend on TIME only, but it calls " +
                      m.function.hostCalls()[0].name,
                  "Rewrite the function in terms of TIME.");
      continue;
    }
    model.motions.push_back(std::move(m));
  }

  // Single-component forces.
  for (const Statement* s : sforces) {
    if (!s->id) continue;
    Args a(*s, diags);
    SForce f;
    f.id = *s->id;
    f.where = s->where;
    f.iMarker = markerRef(*s, "I");
    f.jMarker = markerRef(*s, "J");
    f.rotation = s->has("ROTATION");
    if (s->has("ROTATION") == s->has("TRANSLATION"))
      diags.error(s->where, s->subject(), "give exactly one of TRANSLATION and ROTATION",
                  "Add TRANSLATION (a force along I-J) or ROTATION (a torque about zJ).");
    f.actionOnly = s->has("ACTIONONLY");
    const Argument* fn = s->find("FUNCTION");
    if (!fn) {
      a.require("FUNCTION", "<expression>");
      continue;
    }
    if (f.iMarker < 0 || f.jMarker < 0) continue;
    model.sforces.push_back(std::move(f));
  }
  // Bind SFORCE functions after every SFORCE exists (a function may read another SFORCE).
  {
    size_t k = 0;
    for (const Statement* s : sforces) {
      if (k >= model.sforces.size() || !s->id || model.sforces[k].id != *s->id) continue;
      const Argument* fn = s->find("FUNCTION");
      if (fn->expression.rfind("USER", 0) == 0) {
        diags.error(fn->where, s->subject(), "FUNCTION=USER(...) (SFOSUB) is not supported yet",
                    "Write the force as a function expression.");
      } else {
        bindExpression(model, fn->expression, fn->valueWhere, s->subject(), true, diags,
                       model.sforces[k].function);
      }
      ++k;
    }
  }

  // Requests.
  for (const Statement* s : requests) {
    if (!s->id) continue;
    Request r;
    r.id = *s->id;
    r.where = s->where;
    if (const Argument* c = s->find("COMMENT")) {
      r.comment = c->expression.empty() && !c->values.empty() ? c->values[0].text : c->expression;
    }
    static const std::pair<const char*, Request::Kind> kinds[] = {
        {"DISPLACEMENT", Request::Kind::Displacement},
        {"VELOCITY", Request::Kind::Velocity},
        {"ACCELERATION", Request::Kind::Acceleration},
        {"FORCE", Request::Kind::Force}};
    int nKinds = 0;
    for (const auto& [name, kind] : kinds)
      if (s->has(name)) { r.kind = kind; ++nKinds; }
    bool hasF = false;
    for (int c = 0; c < 8; ++c) hasF |= s->has(("F" + std::to_string(c + 1)).c_str());
    if (s->has("FUNCTION")) {
      diags.error(s->find("FUNCTION")->where, s->subject(),
                  "FUNCTION=USER(...) requests (REQSUB) are not supported yet",
                  "Use F1..F8 expressions or DISPLACEMENT/VELOCITY/ACCELERATION/FORCE.");
      continue;
    }
    if (nKinds > 1 || (nKinds == 1 && hasF)) {
      diags.error(s->where, s->subject(),
                  "DISPLACEMENT, VELOCITY, ACCELERATION, FORCE and F1..F8 exclude each other",
                  "Keep one kind of request per REQUEST statement.");
      continue;
    }
    if (nKinds == 0 && !hasF) {
      diags.error(s->where, s->subject(), "the request asks for nothing",
                  "Add DISPLACEMENT, VELOCITY, ACCELERATION or FORCE with I=, or F2=... "
                  "expressions.");
      continue;
    }
    if (nKinds == 1) {
      r.iMarker = markerRef(*s, "I");
      if (s->has("J")) r.jMarker = markerRef(*s, "J");
      if (s->has("RM")) r.rmMarker = markerRef(*s, "RM");
      if (r.iMarker < 0) continue;
    } else {
      bool ok = true;
      for (int c = 0; c < 8; ++c) {
        const Argument* fa = s->find(("F" + std::to_string(c + 1)).c_str());
        if (!fa) continue;
        BoundExpression b;
        if (bindExpression(model, fa->expression, fa->valueWhere, s->subject(), false, diags, b))
          r.columns[c] = std::move(b);
        else
          ok = false;
      }
      if (!ok) continue;
    }
    model.requests.push_back(std::move(r));
  }

  return diags.errorCount() == errorsBefore;
}

}  // namespace openmss::model
