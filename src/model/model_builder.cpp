#include "model/model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/rotation.hpp"
#include "language/schema.hpp"
#include "model/coupling_builder.hpp"
#include "model/general_constraint_builder.hpp"
#include "model/data_element_builder.hpp"
#include "model/force_element_builder.hpp"
#include "model/sensor_builder.hpp"
#include "model/units_table.hpp"
#include "model/user_equation_builder.hpp"

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

}  // namespace

// DEBUG statement and command: EPRINT is supported; the other dumps warn and have no effect.
void applyDebugArguments(const Statement& s, DebugSettings& debug, Diagnostics& diags) {
  for (const Argument& arg : s.args) {
    if (arg.name == "EPRINT") debug.eprint = true;
    else if (arg.name != "LIST")
      diags.warning(arg.where, s.subject(),
                    arg.name + " is not supported yet and has no effect on this run",
                    "Only DEBUG/EPRINT is supported; remove " + arg.name +
                        " to silence this warning.");
  }
}

namespace {

const std::set<std::string>& supportedStatements() {
  static const std::set<std::string> s = {"UNITS",  "PART",     "MARKER",  "JOINT",
                                          "MOTION", "SFORCE",   "ACCGRAV", "REQUEST",
                                          "GRAPHICS", "OUTPUT", "END",     "TITLE",
                                          "EQUILIBRIUM", "IC", "JPRIM",
                                          // force elements (force_element_builder.cpp)
                                          "SPRINGDAMPER", "BUSHING", "FIELD", "BEAM",
                                          "VFORCE", "VTORQUE", "GFORCE",
                                          // joint couplings (coupling_builder.cpp)
                                          "COUPLER", "GEAR",
                                          // general constraints (general_constraint_builder)
                                          "GCON",
                                          // user equations (user_equation_builder.cpp)
                                          "VARIABLE", "DIFF", "ARRAY", "LSE", "TFSISO",
                                          "PINPUT", "POUTPUT", "GSE",
                                          // integrator diagnostics (DEBUG/EPRINT)
                                          "DEBUG",
                                          // events (sensor_builder.cpp)
                                          "SENSOR",
                                          // results-file request: warns (no .res writer yet)
                                          "RESULTS",
                                          // integrator choice (analysis_settings.cpp)
                                          "INTEGRATOR"};
  return s;
}

}  // namespace

// The analysis variables (docs/expressions.md, "Analysis variables"). Returns false when `name`
// is not one. MODE is accepted everywhere: it is constant through an analysis. The integrator
// statistics change inside a step, between the residual evaluations of one Newton matrix, so
// they are read by REQUEST functions only (at output steps, where they equal the .msg's
// numbers). CPU is refused: CPU time differs from run to run and would break reproducibility.
template <class Fail>
bool bindAnalysisVariable(const std::string& name, bool forRequest, Measure& m, Fail&& fail) {
  static const std::map<std::string, MeasureKind> variables = {
      {"MODE", MeasureKind::AnalysisMode},   {"HSIZE", MeasureKind::StepSize},
      {"ORDER", MeasureKind::IntegratorOrder}, {"NJAC", MeasureKind::JacobianCount},
      {"NRHS", MeasureKind::ResidualCount}};
  if (name == "CPU") {
    fail("CPU time is not available: it differs from run to run, and OpenMSS keeps its outputs "
         "bit-identical across runs",
         "Remove CPU; NRHS (residual evaluations) or NJAC measure the solver's effort "
         "reproducibly.");
    return true;
  }
  const auto it = variables.find(name);
  if (it == variables.end()) return false;
  m.kind = it->second;
  if (!forRequest && m.kind != MeasureKind::AnalysisMode)
    fail("the integrator statistics HSIZE, ORDER, NJAC and NRHS are supported in REQUEST "
         "functions only so far (they change within an integrator step)",
         "Read it in a REQUEST F1..F8 function; MODE may be used in any function but MOTION.");
  return true;
}

bool bindExpression(const Model& model, const std::string& text, const SourceLocation& where,
                    const std::string& subject, bool forForces, Diagnostics& diags,
                    BoundExpression& out, bool forConstraint, bool forRequest) {
  if (!expr::Expression::parse(text, where, subject, diags, out.expression)) return false;
  if (!bindDataCalls(model, out.expression, where, subject, diags)) return false;
  if (const expr::UserCall* user = out.expression.userCall()) {
    // USER(...) keeps its constants (expr4); evaluating it needs a loaded subroutine.
    SourceLocation at = where;
    if (where.column > 0) at.column = where.column + user->column - 1;
    diags.error(at, subject,
                "USER(...) at column " + std::to_string(user->column) +
                    " of the expression needs a user subroutine, and none is loaded for it",
                "Write the function as an expression, or load the subroutine library that "
                "defines it (ROUTINE=).");
    return false;
  }
  bool ok = true;
  if (forConstraint && out.expression.delayCount() > 0) {
    // DELAY reads the run's history (expression_run_state.hpp); a constraint equation must
    // be a function of the configuration alone, and its second derivatives need jets.
    diags.error(where, subject, "DELAY is not supported in GCON functions yet",
                "Constrain a VARIABLE-free geometric expression; DELAY is supported in forces, "
                "VARIABLE, DIFF, REQUEST and SENSOR functions.");
    ok = false;
  }
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
      if (model.markers[it->second].floating) {
        fail("marker " + std::to_string(idv) + " is FLOATING and has no pose of its own",
             "Measure a fixed marker.");
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
        {"AX", MeasureKind::AX},       {"AY", MeasureKind::AY},       {"AZ", MeasureKind::AZ},
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
      // AX, AY, AZ: cumulative outside GCON (the run state counts the turns,
      // mechanics/expression_run_state.hpp); principal values in a GCON.
    } else if (call.name == "ORIENT") {
      m.kind = MeasureKind::Orient;
      m.code = call.args.size() > 0 ? static_cast<int>(call.args[0]) : 0;
      m.component = call.args.size() > 1 ? static_cast<int>(call.args[1]) : 0;
      m.i = marker(2, false);
      m.j = marker(3, true);
      const bool known = (m.code == 27 && m.component >= 1 && m.component <= 4) ||
                         (m.code == 29 && m.component >= 1 && m.component <= 9) ||
                         (m.code >= 1 && m.code <= 28 && m.component >= 1 && m.component <= 3);
      if (!known)
        fail("orientation code " + std::to_string(m.code) + " component " +
                 std::to_string(m.component) + " is not supported yet",
             "Use codes 1-12 (body-fixed sequences 1-2-3, 2-3-1, 3-1-2, 1-3-2, 2-1-3, 3-2-1, "
             "1-2-1, 1-3-1, 2-1-2, 2-3-2, 3-1-3, 3-2-3), 13-24 (the same sequences space-fixed), "
             "25 (AX, AY, AZ principal values), 26 (YAW, PITCH, ROLL), all with components 1-3, "
             "27 (Euler parameters, 1-4), 28 (Rodriguez parameters, 1-3) or 29 (direction "
             "cosines, 1-9).");
    } else if (call.name == "INCANG") {
      m.kind = MeasureKind::IncludedAngle;
      m.i = marker(0, false);
      m.j = marker(1, false);
      m.k = marker(2, false);
    } else if (call.name.size() == 2 && (call.name[0] == 'F' || call.name[0] == 'T') &&
               std::string("XYZM").find(call.name[1]) != std::string::npos) {
      // FX FY FZ FM TX TY TZ TM (i[, j][, k]): the net force or torque on marker i.
      m.kind = MeasureKind::NetForce;
      const int axis = static_cast<int>(std::string("XYZM").find(call.name[1]));
      m.component = call.name[0] == 'F' ? (axis == 3 ? 1 : 2 + axis) : (axis == 3 ? 5 : 6 + axis);
      m.i = marker(0, false);
      m.j = marker(1, true);
      m.k = marker(2, true);
    } else if (call.name == "JOINT" || call.name == "MOTION" || call.name == "SFORCE" ||
               call.name == "JPRIM" || forceElementReadBack(call.name, nullptr)) {
      m.kind = forceElementReadBack(call.name, &m.kind) ? m.kind
               : call.name == "JOINT"  ? MeasureKind::JointForce
               : call.name == "MOTION" ? MeasureKind::MotionForce
               : call.name == "JPRIM"  ? MeasureKind::JPrimForce
                                       : MeasureKind::SForceForce;
      long eid = call.args.size() > 0 ? call.args[0] : 0;
      m.atJ = call.args.size() > 1 ? static_cast<int>(call.args[1]) : 0;
      m.component = call.args.size() > 2 ? static_cast<int>(call.args[2]) : 0;
      m.k = marker(3, true);
      int found = -1;
      if (m.kind == MeasureKind::JointForce) {
        if (auto ji = model.jointIndex.find(eid); ji != model.jointIndex.end()) found = ji->second;
      } else if (m.kind == MeasureKind::JPrimForce) {
        if (auto pi = model.jprimIndex.find(eid); pi != model.jprimIndex.end()) found = pi->second;
      } else if (m.kind == MeasureKind::MotionForce) {
        for (size_t q = 0; q < model.motions.size(); ++q)
          if (model.motions[q].id == eid) found = static_cast<int>(q);
      } else if (forceElementReadBack(call.name, nullptr)) {
        found = findForceElement(model, m.kind, eid);
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
    } else if (bindUserMeasure(model, call, m, fail)) {
      // VARVAL, DIF, DIF1, ARYVAL, PINVAL, POUVAL (user_equation_builder.cpp)
    } else if (bindSensorMeasure(model, call, m, fail)) {
      // SENVAL (sensor_builder.cpp)
    } else if (bindAnalysisVariable(call.name, forRequest, m, fail)) {
      // MODE, HSIZE, ORDER, NJAC, NRHS; CPU refused (model/analysis_status.hpp)
    } else if (call.name == "NFORCE" || call.name == "PTCV" || call.name == "CVCV" ||
               call.name == "FRICTION" || call.name == "CONTACT") {
      // Read-backs of elements the solver rejects at input (expr4): name the missing element.
      const long eid = call.args.empty() ? 0 : call.args[0];
      fail("reads the force of " + call.name + "/" + std::to_string(eid) + ", but " + call.name +
               " elements are not supported by the solver (their statements are rejected at "
               "input), so there is no force to read",
           "Remove the " + call.name + " read-back, or model the element with SFORCE, VFORCE or "
           "GFORCE and read that element instead.");
      continue;
    } else {
      fail("this function is not supported yet by the solver",
           "Remove it or replace it by a supported function; see README.md for the list.");
      continue;
    }
    // Accelerations, JOINT/JPRIM/MOTION reactions and ORIENT are read in force and VARIABLE
    // functions (docs/theory.md §4b); read-backs of force elements and FX..TM not yet.
    if (forForces && m.needsDynamics() && !readsAccelerationOrReaction(m.kind))
      fail("force read-backs (SFORCE, SPDP, BUSH, FIELD, BEAM, VFORCE, VTORQ, GFORCE, FX..TM) "
           "are not supported yet in force, VARIABLE or DIFF functions",
           "Use it in a REQUEST; JOINT, JPRIM and MOTION reactions and accelerations are "
           "supported here.");
    // The run records DELAY arguments at accepted states from the measures force functions
    // can read (expression_run_state.cpp), so an expression with DELAY may not read forces.
    if (out.expression.delayCount() > 0 && m.needsDynamics() &&
        !readsAccelerationOrReaction(m.kind))
      fail("force read-backs are not supported yet in an expression with DELAY",
           "Read the force in a VARIABLE-free expression, or delay a JOINT/JPRIM/MOTION "
           "reaction or an acceleration instead.");
    out.measures.push_back(m);
  }
  return ok;
}

bool buildModel(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  const int errorsBefore = diags.errorCount();
  model = Model{};
  model.title = dataset.title;
  model.file = dataset.file;
  buildDataElements(dataset, model, diags);  // SPLINE, CURVE, MATRIX, STRING first
  buildSensors(dataset, model, diags);       // before any expression: SENVAL(id) reads them

  std::vector<RawPart> rawParts;
  std::vector<RawMarker> rawMarkers;
  std::vector<const Statement*> joints, motions, sforces, requests;
  std::vector<const Statement*> jprimStatements;
  std::vector<const Statement*> forceElementStatements;  // SPRINGDAMPER ... GFORCE
  std::vector<const Statement*> userStatements;  // VARIABLE, DIFF, ARRAY, LSE, TFSISO, ...
  std::vector<const Statement*> couplingStatements;      // COUPLER, GEAR
  std::vector<const Statement*> gconStatements;          // GCON
  long lastPartId = 0;

  for (const Statement& s : dataset.statements) {
    Args a(s, diags);
    if (!supportedStatements().count(s.name) && !isDataElementStatement(s.name)) {
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
      for (const char* unsupported : {"VM", "WM", "IM"}) {
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
      // FLOATING markers are read; only a JFLOAT argument may name one (markerRef below).
      for (const char* unsupported : {"POINT_MASS", "FLEX_BODY", "NODE", "FE_PART",
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
    } else if (s.name == "JPRIM") {
      jprimStatements.push_back(&s);
    } else if (s.name == "SFORCE") {
      sforces.push_back(&s);
    } else if (isForceElementStatement(s.name)) {
      forceElementStatements.push_back(&s);
    } else if (isUserEquationStatement(s.name)) {
      userStatements.push_back(&s);
    } else if (isCouplingStatement(s.name)) {
      couplingStatements.push_back(&s);
    } else if (s.name == "GCON") {
      gconStatements.push_back(&s);
    } else if (s.name == "REQUEST") {
      requests.push_back(&s);
    } else if (s.name == "EQUILIBRIUM") {
      applyEquilibriumArguments(s, model.equilibrium, diags);
    } else if (s.name == "IC") {
      applyInitialConditionArguments(s, model.initialConditions, diags);
    } else if (s.name == "INTEGRATOR") {
      applyIntegratorArguments(s, model.integrator, diags);
    } else if (s.name == "ACCGRAV") {
      model.gravity = Eigen::Vector3d(a.real("IGRAV").value_or(0.0), a.real("JGRAV").value_or(0.0),
                                      a.real("KGRAV").value_or(0.0));
    } else if (s.name == "DEBUG") {
      applyDebugArguments(s, model.debug, diags);
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
    if (s.name == "RESULTS")  // like OUTPUT/GRSAVE: a file request, not part of the model
      diags.warning(s.where, s.subject(),
                    "the results (.res) file is not written yet; the run goes on without it "
                    "(the request file .req is written with OUTPUT/REQSAVE)",
                    "Remove RESULTS to silence this warning.");
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
      // EXACT=X:Y:Z:PSI:THETA:PHI (the reader checked the words).
      if (const Argument* exact = rp.s->find("EXACT")) {
        static const char* kCoordinates[6] = {"X", "Y", "Z", "PSI", "THETA", "PHI"};
        for (const auto& value : exact->values)
          for (int k = 0; k < 6; ++k)
            if (value.text == kCoordinates[k]) p.exact[k] = true;
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
    m.floating = rm.s->has("FLOATING");
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
    if (model.markers[it->second].floating) {
      diags.error(s.find(name)->where, s.subject(),
                  std::string(name) + "=" + std::to_string(*idv) + ": marker " +
                      std::to_string(*idv) + " is FLOATING; only JFLOAT of VFORCE, VTORQUE "
                      "and GFORCE may name a floating marker",
                  "Use a fixed marker (without FLOATING).");
      return -1;
    }
    return it->second;
  };

  // Joints.
  for (const Statement* s : joints) {
    if (!s->id) continue;
    Args a(*s, diags);
    Joint j;
    j.id = *s->id;
    j.where = s->where;
    static const std::pair<const char*, JointType> types[] = {
        {"REVOLUTE", JointType::Revolute},       {"SPHERICAL", JointType::Spherical},
        {"UNIVERSAL", JointType::Universal},     {"HOOKE", JointType::Hooke},
        {"TRANSLATIONAL", JointType::Translational}, {"CYLINDRICAL", JointType::Cylindrical},
        {"FIXED", JointType::Fixed},             {"CONVEL", JointType::Convel},
        {"PLANAR", JointType::Planar},           {"RACKPIN", JointType::RackPin},
        {"SCREW", JointType::Screw}};
    int nTypes = 0;
    for (const auto& [name, type] : types)
      if (s->has(name)) { j.type = type; ++nTypes; }
    if (nTypes == 0)
      diags.error(s->where, s->subject(), "the joint type is missing",
                  "Add one of CONVEL, CYLINDRICAL, FIXED, HOOKE, PLANAR, RACKPIN, REVOLUTE, "
                  "SCREW, SPHERICAL, TRANSLATIONAL, UNIVERSAL.");
    else if (nTypes > 1)
      diags.error(s->where, s->subject(), "more than one joint type is given",
                  "Keep exactly one joint type.");
    j.iMarker = markerRef(*s, "I");
    j.jMarker = markerRef(*s, "J");
    // PD (rack-and-pinion) and PITCH (screw) belong to their joint type and are required there.
    const bool rackPin = nTypes == 1 && j.type == JointType::RackPin;
    const bool screw = nTypes == 1 && j.type == JointType::Screw;
    if (rackPin) {
      a.require("PD", "<pitch diameter of the pinion>");
      j.pitchDiameter = a.real("PD").value_or(0.0);
      if (s->has("PD") && !(j.pitchDiameter > 0.0)) {
        diags.error(s->find("PD")->where, s->subject(), "PD must be positive",
                    "Give the pinion's pitch diameter, PD=<value> > 0.");
        nTypes = -1;
      }
    } else if (s->has("PD")) {
      diags.error(s->find("PD")->where, s->subject(), "PD applies to RACKPIN joints only",
                  "Remove PD.");
    }
    if (screw) {
      a.require("PITCH", "<travel per turn>");
      j.pitch = a.real("PITCH").value_or(0.0);
      if (s->has("PITCH") && j.pitch == 0.0) {
        diags.error(s->find("PITCH")->where, s->subject(), "PITCH must not be zero",
                    "Give the translation per turn, PITCH=<value> (negative: left-handed).");
        nTypes = -1;
      }
    } else if (s->has("PITCH")) {
      diags.error(s->find("PITCH")->where, s->subject(), "PITCH applies to SCREW joints only",
                  "Remove PITCH.");
    }
    if ((rackPin && !s->has("PD")) || (screw && !s->has("PITCH"))) nTypes = -1;
    // Joint initial conditions: IC on revolute (rotation) and translational (translation)
    // joints, ICTRAN and ICROT on cylindrical joints; displacement [, velocity].
    auto icPair = [&](const char* name, std::optional<double>& disp, std::optional<double>& vel) {
      const Argument* ic = s->find(name);
      if (!ic) return;
      if (ic->values.size() >= 1) disp = ic->values[0].number;
      if (ic->values.size() >= 2) vel = ic->values[1].number;
    };
    if (nTypes == 1) {
      const bool icAllowed = j.type == JointType::Revolute || j.type == JointType::Translational;
      if (s->has("IC") && !icAllowed)
        diags.error(s->find("IC")->where, s->subject(),
                    std::string("IC applies to revolute and translational joints; this joint is ") +
                        jointTypeName(j.type),
                    j.type == JointType::Cylindrical ? "Use ICTRAN= and ICROT= on a cylindrical joint."
                                                     : "Remove IC.");
      for (const char* name : {"ICTRAN", "ICROT"})
        if (s->has(name) && j.type != JointType::Cylindrical)
          diags.error(s->find(name)->where, s->subject(),
                      std::string(name) + " applies to cylindrical joints only",
                      j.type == JointType::Revolute || j.type == JointType::Translational
                          ? "Use IC= on a revolute or translational joint."
                          : "Remove it.");
      if (j.type == JointType::Revolute) icPair("IC", j.icRotation, j.icRotationVelocity);
      if (j.type == JointType::Translational)
        icPair("IC", j.icTranslation, j.icTranslationVelocity);
      if (j.type == JointType::Cylindrical) {
        icPair("ICTRAN", j.icTranslation, j.icTranslationVelocity);
        icPair("ICROT", j.icRotation, j.icRotationVelocity);
      }
      // Held by the initial-condition analysis (mechanics/initial_conditions.cpp).
    }
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

  // Joint primitives.
  for (const Statement* s : jprimStatements) {
    if (!s->id) continue;
    JPrim p;
    p.id = *s->id;
    p.where = s->where;
    static const std::pair<const char*, JPrimType> types[] = {
        {"ATPOINT", JPrimType::AtPoint},         {"INLINE", JPrimType::InLine},
        {"INPLANE", JPrimType::InPlane},         {"ORIENTATION", JPrimType::Orientation},
        {"PARALLEL_AXES", JPrimType::ParallelAxes}, {"PERPENDICULAR", JPrimType::Perpendicular}};
    int nTypes = 0;
    for (const auto& [name, type] : types)
      if (s->has(name)) { p.type = type; ++nTypes; }
    if (nTypes != 1)
      diags.error(s->where, s->subject(),
                  nTypes == 0 ? "the joint primitive type is missing"
                              : "more than one joint primitive type is given",
                  "Give exactly one of ATPOINT, INLINE, INPLANE, ORIENTATION, PARALLEL_AXES, "
                  "PERPENDICULAR.");
    p.iMarker = markerRef(*s, "I");
    p.jMarker = markerRef(*s, "J");
    if (p.iMarker >= 0 && p.jMarker >= 0 &&
        model.markers[p.iMarker].part == model.markers[p.jMarker].part) {
      diags.error(s->where, s->subject(),
                  "I and J markers are on the same part (PART/" +
                      std::to_string(model.parts[model.markers[p.iMarker].part].id) + ")",
                  "A joint primitive connects two parts: put I and J on different parts.");
      continue;
    }
    if (nTypes == 1 && p.iMarker >= 0 && p.jMarker >= 0) {
      model.jprimIndex[p.id] = static_cast<int>(model.jprims.size());
      model.jprims.push_back(p);
    }
  }

  // Motions.
  for (const Statement* s : motions) {
    if (!s->id) continue;
    Args a(*s, diags);
    Motion m;
    m.id = *s->id;
    m.where = s->where;
    int nForms = 0;
    for (const auto& [name, form] :
         {std::pair{"DISPLACEMENT", Motion::Form::Displacement},
          std::pair{"VELOCITY", Motion::Form::Velocity},
          std::pair{"ACCELERATION", Motion::Form::Acceleration}})
      if (s->has(name)) { m.form = form; ++nForms; }
    if (nForms > 1) {
      diags.error(s->where, s->subject(), "DISPLACEMENT, VELOCITY and ACCELERATION exclude each other",
                  "Keep one of them (DISPLACEMENT is the default).");
      continue;
    }
    // ADAMS reads these on every motion; they only matter where the function is integrated.
    if (s->has("ICDISP") && m.form == Motion::Form::Displacement)
      diags.warning(s->find("ICDISP")->where, s->subject(),
                    "ICDISP has no effect on a displacement motion (its function gives the "
                    "displacement)",
                    "Remove ICDISP, or make the motion VELOCITY or ACCELERATION.");
    if (s->has("ICVEL") && m.form != Motion::Form::Acceleration)
      diags.warning(s->find("ICVEL")->where, s->subject(),
                    "ICVEL has no effect unless the motion is ACCELERATION",
                    "Remove ICVEL, or make the motion ACCELERATION.");
    m.icDisp = a.real("ICDISP").value_or(0.0);
    m.icVel = a.real("ICVEL").value_or(0.0);
    const bool onJoint = s->has("JOINT");
    if (onJoint == (s->has("I") || s->has("J"))) {
      diags.error(s->where, s->subject(),
                  onJoint ? "JOINT= excludes I= and J=" : "the motion names no joint and no markers",
                  "Give JOINT=<id> (with TRANSLATION or ROTATION on a cylindrical joint), or "
                  "I=<id>, J=<id> with one of X, Y, Z, B1, B2, B3.");
      continue;
    }
    if (onJoint) {
      for (const char* axis : {"X", "Y", "Z", "B1", "B2", "B3"})
        if (s->has(axis))
          diags.error(s->find(axis)->where, s->subject(),
                      std::string(axis) + " applies to marker-pair (I=, J=) motions only",
                      "Remove it; a joint motion acts along or about the joint's z axis.");
      auto jid = a.id("JOINT");
      if (!jid) continue;
      auto it = model.jointIndex.find(*jid);
      if (it == model.jointIndex.end()) {
        diags.error(s->find("JOINT")->where, s->subject(),
                    "JOINT/" + std::to_string(*jid) + " does not exist (or is invalid)",
                    "Use the id of a JOINT statement of this data set.");
        continue;
      }
      m.joint = it->second;
      const Joint& joint = model.joints[m.joint];
      m.iMarker = joint.iMarker;
      m.jMarker = joint.jMarker;
      JointType jt = joint.type;
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
                    "Drive a revolute, translational or cylindrical joint, or use I=, J= with "
                    "X, Y, Z, B1, B2 or B3.");
        continue;
      }
      m.axis = m.rotation ? 5 : 2;
    } else {
      m.iMarker = markerRef(*s, "I");
      m.jMarker = markerRef(*s, "J");
      int nAxes = 0;
      static const char* kAxes[6] = {"X", "Y", "Z", "B1", "B2", "B3"};
      for (int k = 0; k < 6; ++k)
        if (s->has(kAxes[k])) { m.axis = k; ++nAxes; }
      if (nAxes != 1) {
        diags.error(s->where, s->subject(),
                    nAxes == 0 ? "a marker-pair motion needs its direction"
                               : "more than one direction is given",
                    "Give exactly one of X, Y, Z (translation of I in J's axes) or B1, B2, B3 "
                    "(body 1-2-3 rotation angles of I relative to J).");
        continue;
      }
      for (const char* jointOnly : {"TRANSLATION", "ROTATION"})
        if (s->has(jointOnly))
          diags.error(s->find(jointOnly)->where, s->subject(),
                      std::string(jointOnly) + " applies to joint motions only",
                      "Remove it; X, Y, Z, B1, B2 or B3 gives the direction.");
      if (m.iMarker < 0 || m.jMarker < 0) continue;
      if (model.markers[m.iMarker].part == model.markers[m.jMarker].part) {
        diags.error(s->where, s->subject(), "I and J markers are on the same part",
                    "A motion acts between two parts: put I and J on different parts.");
        continue;
      }
      m.rotation = m.axis >= 3;
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
    if (!bindDataCalls(model, m.function, f->valueWhere, s->subject(), diags)) continue;
    if (m.function.delayCount() > 0) {
      // A motion needs exact velocity and acceleration (time jets) of its function; the
      // recorded DELAY history gives neither yet.
      diags.error(f->valueWhere, s->subject(), "DELAY is not supported in MOTION functions yet",
                  "Write the delayed motion directly as a function of TIME (e.g. "
                  "SIN(TIME-0.5) for DELAY(SIN(TIME), 0.5, 0)).");
      continue;
    }
    if (!m.function.hostCalls().empty()) {
      diags.error(f->valueWhere, s->subject(),
                  "a MOTION function may depend on TIME only, but it calls " +
                      m.function.hostCalls()[0].name,
                  "Rewrite the function in terms of TIME.");
      continue;
    }
    model.motions.push_back(std::move(m));
  }

  // User equations (user_equation_builder.cpp): before any function is bound, since every
  // function may read them (VARVAL, DIF, ARYVAL, ...).
  buildUserEquations(userStatements, dataset, model, diags);

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
  // COUPLER and GEAR (coupling_builder.cpp): after every joint and marker exists.
  buildCouplings(couplingStatements, model, diags);
  // GCON (general_constraint_builder.cpp): after every marker exists.
  buildGeneralConstraints(gconStatements, model, diags);
  // SPRINGDAMPER, BUSHING, FIELD, BEAM, VFORCE, VTORQUE, GFORCE (force_element_builder.cpp).
  buildForceElements(forceElementStatements, model, markerRef, diags);
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

  bindForceElementFunctions(forceElementStatements, model, diags);
  bindUserEquationFunctions(userStatements, model, diags);
  bindSensorFunctions(dataset, model, diags);

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
        if (bindExpression(model, fa->expression, fa->valueWhere, s->subject(), false, diags, b,
                           /*forConstraint=*/false, /*forRequest=*/true))
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
