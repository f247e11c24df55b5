#include "model/model_builder.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "model/contact_builder.hpp"
#include "model/coupling_builder.hpp"
#include "model/data_element_builder.hpp"
#include "model/force_element_builder.hpp"
#include "model/friction_builder.hpp"
#include "model/force_read_back_check.hpp"
#include "model/general_constraint_builder.hpp"
#include "model/user_constraint_builder.hpp"
#include "model/graphics_builder.hpp"
#include "model/joint_builder.hpp"
#include "model/material_builder.hpp"
#include "model/motion_builder.hpp"
#include "model/part_builder.hpp"
#include "model/releasing_build.hpp"
#include "model/point_curve_builder.hpp"
#include "model/curve_curve_builder.hpp"
#include "model/request_builder.hpp"
#include "model/sensor_builder.hpp"
#include "model/sforce_builder.hpp"
#include "model/solver_preferences.hpp"
#include "model/statement_arguments.hpp"
#include "model/units_table.hpp"
#include "model/user_equation_builder.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

const std::set<std::string>& supportedStatements() {
  static const std::set<std::string> s = {"UNITS",  "PART",     "MARKER",  "JOINT",
                                          "MOTION", "SFORCE",   "ACCGRAV", "REQUEST",
                                          "GRAPHICS", "OUTPUT", "END",     "TITLE",
                                          "EQUILIBRIUM", "IC", "KINEMATICS", "JPRIM",
                                          // force elements (force_element_builder.cpp)
                                          "SPRINGDAMPER", "BUSHING", "FIELD", "BEAM",
                                          "VFORCE", "VTORQUE", "GFORCE", "NFORCE",
                                          // joint couplings (coupling_builder.cpp)
                                          "COUPLER", "GEAR",
                                          // general constraints (general_constraint_builder)
                                          "GCON",
                                          // user constraints (user_constraint_builder.cpp)
                                          "UCON",
                                          // point-to-curve (point_curve_builder.cpp)
                                          "PTCV",
                                          // curve-to-curve (curve_curve_builder.cpp)
                                          "CVCV",
                                          // joint friction (friction_builder.cpp)
                                          "FRICTION",
                                          // user equations (user_equation_builder.cpp)
                                          "VARIABLE", "DIFF", "ARRAY", "LSE", "TFSISO",
                                          "PINPUT", "POUTPUT", "GSE",
                                          // integrator diagnostics (DEBUG/EPRINT)
                                          "DEBUG",
                                          // events (sensor_builder.cpp)
                                          "SENSOR",
                                          // 3-D contact (contact_builder.cpp)
                                          "CONTACT",
                                          // the .res file (results_arguments.cpp)
                                          "RESULTS",
                                          // integrator choice (analysis_settings.cpp)
                                          "INTEGRATOR",
                                          // solver internals: warn (solver_preferences.cpp)
                                          "PREFERENCES", "LSOLVER", "ENVIRONMENT",
                                          // data only (material_builder.cpp)
                                          "MATERIAL"};
  return s;
}

// The statements of each element family, in data-set order, for the passes that need other
// families built first.
struct StatementGroups {
  std::vector<const Statement*> joints, jprims, motions, sforces, requests;
  std::vector<const Statement*> forceElements;  // SPRINGDAMPER ... GFORCE
  std::vector<const Statement*> userEquations;  // VARIABLE, DIFF, ARRAY, LSE, TFSISO, ...
  std::vector<const Statement*> couplings;      // COUPLER, GEAR
  std::vector<const Statement*> gcons;          // GCON
  std::vector<const Statement*> ucons;          // UCON
  std::vector<const Statement*> ptcvs;          // PTCV
  std::vector<const Statement*> cvcvs;          // CVCV
  std::vector<const Statement*> frictions;      // FRICTION
  std::vector<const Statement*> contacts;       // CONTACT
};

// OUTPUT statement: REQSAVE, GRSAVE, NOPRINT and (NO)SEPARATOR are supported; the others warn.
void applyOutputArguments(const Statement& s, OutputSettings& output, Diagnostics& diags) {
  for (const Argument& arg : s.args) {
    if (arg.name == "REQSAVE")
      output.reqsave = true;
    else if (arg.name == "NOSEPARATOR")
      output.noseparator = true;
    else if (arg.name == "SEPARATOR")
      output.noseparator = false;
    else if (arg.name == "GRSAVE")  // <prefix>.gra (docs/output-files.md)
      output.grsave = true;
    else if (arg.name == "NOPRINT")  // no <prefix>.out: read by model/results_arguments.cpp
      continue;
    else
      diags.warning(arg.where, s.subject(),
                    arg.name + " is not supported yet and has no effect on this run",
                    "Remove it to silence this warning.");
  }
}

// The first pass, in data-set order (so are its diagnostics): statements that set the model
// directly (UNITS, ACCGRAV, OUTPUT, the analysis settings), the raw PART and MARKER data, and
// the element statements grouped for the later passes.
void readStatements(const language::Dataset& dataset, Model& model, PartBuilder& parts,
                    StatementGroups& groups, Diagnostics& diags) {
  for (const Statement& s : dataset.statements) {
    if (s.name == "MREQUEST") {  // docs/language.md, "MREQUEST"
      diags.error(s.where, s.subject(),
                  "MREQUEST is not supported: its full argument list is not documented in the "
                  "sources OpenMSS follows, so its outputs cannot be reproduced faithfully",
                  "Write one REQUEST per part, joint or force instead (e.g. REQUEST/id, "
                  "DISPLACEMENT, I=<cm marker>): the .req and .out get the same kind of columns.");
      continue;
    }
    if (!supportedStatements().count(s.name) && !isDataElementStatement(s.name)) {
      diags.error(s.where, s.subject(), s.name + " is not supported yet by the solver",
                  "Remove the statement, or run it with a tool that supports it; README.md "
                  "lists what is supported.");
      continue;
    }
    if (s.name == "UNITS") {
      applyUnits(s, model.units, diags);
    } else if (s.name == "PART") {
      parts.readPart(s, diags);
    } else if (s.name == "MARKER") {
      parts.readMarker(s, diags);
    } else if (s.name == "JOINT") {
      groups.joints.push_back(&s);
    } else if (s.name == "MOTION") {
      groups.motions.push_back(&s);
    } else if (s.name == "JPRIM") {
      groups.jprims.push_back(&s);
    } else if (s.name == "SFORCE") {
      groups.sforces.push_back(&s);
    } else if (isForceElementStatement(s.name)) {
      groups.forceElements.push_back(&s);
    } else if (isUserEquationStatement(s.name)) {
      groups.userEquations.push_back(&s);
    } else if (isCouplingStatement(s.name)) {
      groups.couplings.push_back(&s);
    } else if (s.name == "GCON") {
      groups.gcons.push_back(&s);
    } else if (s.name == "UCON") {
      groups.ucons.push_back(&s);
    } else if (s.name == "PTCV") {
      groups.ptcvs.push_back(&s);
    } else if (s.name == "CVCV") {
      groups.cvcvs.push_back(&s);
    } else if (s.name == "FRICTION") {
      groups.frictions.push_back(&s);
    } else if (s.name == "CONTACT") {
      groups.contacts.push_back(&s);
    } else if (s.name == "REQUEST") {
      groups.requests.push_back(&s);
    } else if (s.name == "EQUILIBRIUM") {
      applyEquilibriumArguments(s, model.equilibrium, diags);
    } else if (s.name == "IC") {
      applyInitialConditionArguments(s, model.initialConditions, diags);
    } else if (s.name == "KINEMATICS") {
      applyKinematicArguments(s, model.kinematics, diags);
    } else if (s.name == "INTEGRATOR") {
      applyIntegratorArguments(s, model.integrator, diags);
    } else if (s.name == "ACCGRAV") {
      StatementArguments a(s, diags);
      model.gravity = Eigen::Vector3d(a.real("IGRAV").value_or(0.0), a.real("JGRAV").value_or(0.0),
                                      a.real("KGRAV").value_or(0.0));
    } else if (s.name == "DEBUG") {
      applyDebugArguments(s, model.debug, diags);
    } else if (s.name == "PREFERENCES" || s.name == "LSOLVER" || s.name == "ENVIRONMENT") {
      applySolverPreferences(s, diags);
    } else if (s.name == "OUTPUT") {
      applyOutputArguments(s, model.output, diags);
    }
    // RESULTS (and REQUEST's CNAMES): read for the .res writer by readResultsSettings
    // (results_arguments.hpp), not part of the model.
    // GRAPHICS: built after the markers by buildGraphics (graphics_builder.cpp).
  }
}

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

// DX ... ROLL (i [,j] [,k] [,l]), ORIENT(code, component, i [,j]) and INCANG(i, j, k): fills
// `m` and returns true when `call` is one of them. marker(k, allowZero) resolves argument k
// (-1 when absent, -2 after `fail` when unknown).
template <class MarkerOf, class Fail>
bool bindGeometricMeasure(const expr::HostCall& call, Measure& m, MarkerOf&& marker, Fail&& fail) {
  static const std::map<std::string, MeasureKind> kinematic = {
      {"DX", MeasureKind::DX},     {"DY", MeasureKind::DY},       {"DZ", MeasureKind::DZ},
      {"DM", MeasureKind::DM},     {"VX", MeasureKind::VX},       {"VY", MeasureKind::VY},
      {"VZ", MeasureKind::VZ},     {"VM", MeasureKind::VM},       {"VR", MeasureKind::VR},
      {"WX", MeasureKind::WX},     {"WY", MeasureKind::WY},       {"WZ", MeasureKind::WZ},
      {"WM", MeasureKind::WM},     {"ACCX", MeasureKind::ACCX},   {"ACCY", MeasureKind::ACCY},
      {"ACCZ", MeasureKind::ACCZ}, {"ACCM", MeasureKind::ACCM},   {"WDTX", MeasureKind::WDTX},
      {"WDTY", MeasureKind::WDTY}, {"WDTZ", MeasureKind::WDTZ},   {"WDTM", MeasureKind::WDTM},
      {"PSI", MeasureKind::PSI},   {"THETA", MeasureKind::THETA}, {"AX", MeasureKind::AX},
      {"AY", MeasureKind::AY},     {"AZ", MeasureKind::AZ},       {"PHI", MeasureKind::PHI},
      {"YAW", MeasureKind::YAW},   {"PITCH", MeasureKind::PITCH}, {"ROLL", MeasureKind::ROLL}};
  if (auto it = kinematic.find(call.name); it != kinematic.end()) {
    m.kind = it->second;
    // Argument pattern F(i [,j] [,k] [,l]): l is the frame in which time derivatives are
    // taken (docs/theory.md §11b); measures without a time derivative take no l.
    m.i = marker(0, false);
    m.j = marker(1, true);
    bool usesK =
        !(m.kind == MeasureKind::DM || m.kind == MeasureKind::VM || m.kind == MeasureKind::VR ||
          m.kind == MeasureKind::WM || m.kind == MeasureKind::ACCM || m.kind == MeasureKind::WDTM ||
          (m.kind >= MeasureKind::AX && m.kind <= MeasureKind::ROLL));
    if (usesK) m.k = marker(2, true);
    const size_t lPos = usesK ? 3 : 2;
    // WX..WM, displacements and angles have no l (the expression layer checks their arity).
    const bool takesL = (m.kind >= MeasureKind::VX && m.kind <= MeasureKind::VR) ||
                        (m.kind >= MeasureKind::ACCX && m.kind <= MeasureKind::WDTM);
    if (takesL) {
      m.l = marker(lPos, true);
    } else if (call.args.size() > lPos && call.args[lPos] != 0) {
      fail(call.name + " has no time derivative, so it takes no derivative frame (l) argument",
           "Remove the argument after " + std::string(usesK ? "k" : "j") + ".");
    }
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
  } else {
    return false;
  }
  return true;
}

}  // namespace

// DEBUG statement and command: EPRINT is supported; the other dumps warn and have no effect.
void applyDebugArguments(const Statement& s, DebugSettings& debug, Diagnostics& diags) {
  for (const Argument& arg : s.args) {
    if (arg.name == "EPRINT")
      debug.eprint = true;
    else if (arg.name != "LIST")
      diags.warning(
          arg.where, s.subject(), arg.name + " is not supported yet and has no effect on this run",
          "Only DEBUG/EPRINT is supported; remove " + arg.name + " to silence this warning.");
  }
}

bool bindExpression(const Model& model, const std::string& text, const SourceLocation& where,
                    const std::string& subject, bool forForces, Diagnostics& diags,
                    BoundExpression& out, bool forConstraint, bool forRequest) {
  if (!expr::Expression::parse(text, where, subject, diags, out.expression)) return false;
  if (!bindDataCalls(model, out.expression, where, subject, diags)) return false;
  return bindParsedExpression(model, where, subject, forForces, diags, out, forConstraint,
                              forRequest);
}

// `forForces` no longer restricts anything (force read-backs are allowed in every function,
// docs/theory.md §4d); the parameter stays for the callers' sake.
bool bindParsedExpression(const Model& model, const SourceLocation& where,
                          const std::string& subject, bool /*forForces*/, Diagnostics& diags,
                          BoundExpression& out, bool forConstraint, bool forRequest) {
  const expr::UserCall* user = out.expression.userCall();
  if (user) {
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
    // A read-back of an element that is not in the model: either the data set has no such
    // statement, or its statement was refused (its own errors are reported at its line).
    auto failMissingElement = [&](const std::string& function, long eid) {
      const std::string statement = function == "SPDP"    ? "SPRINGDAMPER"
                                    : function == "BUSH"  ? "BUSHING"
                                    : function == "VTORQ" ? "VTORQUE"
                                                          : function;
      const std::string subjectText = statement + "/" + std::to_string(eid);
      const auto line = model.statementLines.find({statement, eid});
      if (line != model.statementLines.end())
        fail(subjectText + " (line " + std::to_string(line->second) +
                 ") was not built: its statement has errors, reported at its line",
             "Correct " + subjectText + "; this reference then needs no change.");
      else
        fail(subjectText + " does not exist",
             "Use the id of a " + statement + " statement of this data set.");
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
    if (bindGeometricMeasure(call, m, marker, fail)) {
      // DX ... ROLL, ORIENT, INCANG
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
      if (found < 0) failMissingElement(call.name, eid);
      m.element = found;
      if (m.atJ != 0 && m.atJ != 1) fail("the second argument must be 0 (at I) or 1 (at J)", "");
      if (m.component < 1 || m.component > 8)
        fail("the component must be 1 to 8", "1 |F|, 2-4 Fx Fy Fz, 5 |T|, 6-8 Tx Ty Tz.");
    } else if (bindUserMeasure(model, call, m, fail)) {
      // VARVAL, DIF, DIF1, ARYVAL, PINVAL, POUVAL (user_equation_builder.cpp)
    } else if (bindSensorMeasure(model, call, m, fail)) {
      // SENVAL (sensor_builder.cpp)
    } else if (bindFrictionMeasure(model, call, m, fail)) {
      // FRICTION(id, index) (friction_builder.cpp)
    } else if (bindAnalysisVariable(call.name, forRequest, m, fail)) {
      // MODE, HSIZE, ORDER, NJAC, NRHS; CPU refused (model/analysis_status.hpp)
    } else if (call.name == "NFORCE") {
      // NFORCE(id, marker, comp, rm): the force on one of its markers (an I marker or J).
      m.kind = MeasureKind::NForceForce;
      const long eid = call.args.empty() ? 0 : call.args[0];
      for (size_t q = 0; q < model.nforces.size(); ++q)
        if (model.nforces[q].id == eid) m.element = static_cast<int>(q);
      m.i = marker(1, false);
      m.component = call.args.size() > 2 ? static_cast<int>(call.args[2]) : 0;
      m.k = marker(3, true);
      if (m.element < 0) {
        failMissingElement("NFORCE", eid);
      } else if (m.i >= 0) {
        const MultiPointForce& nf = model.nforces[m.element];
        if (m.i != nf.jMarker &&
            std::find(nf.iMarkers.begin(), nf.iMarkers.end(), m.i) == nf.iMarkers.end())
          fail("marker " + std::to_string(call.args[1]) + " is not a marker of NFORCE/" +
                   std::to_string(eid),
               "Give one of its IMARKERS or its J marker.");
      }
      if (m.component < 1 || m.component > 8)
        fail("the component must be 1 to 8", "1 |F|, 2-4 Fx Fy Fz, 5 |T|, 6-8 Tx Ty Tz.");
    } else if (call.name == "PTCV") {
      // ADAMS too reads PTCV reactions only in REQUESTs and SENSORs (docs/theory.md §5d).
      fail("reads the reaction of a PTCV, which functions may not read yet",
           "Read it with REQUEST/id, FORCE, I=<the PTCV's I>, J=<its RM or JFLOAT>.");
      continue;
    } else if (call.name == "CVCV") {
      // ADAMS too reads CVCV reactions only in REQUESTs and SENSORs (docs/theory.md §5e).
      fail("reads the reaction of a CVCV, which functions may not read yet",
           "Read it with REQUEST/id, FORCE, I=<the CVCV's IRM>, J=<its JRM or JFLOAT>.");
      continue;
    } else {
      fail("this function is not supported yet by the solver",
           "Remove it or replace it by a supported function; see README.md for the list.");
      continue;
    }
    // Accelerations, reactions, ORIENT and force read-backs are read in force, VARIABLE and
    // DIFF functions (docs/theory.md §4b, §4d); cycles of read-backs are refused once every
    // function is bound (force_read_back_check.hpp).
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

namespace {

bool build(const language::Dataset& dataset, Model& model, Diagnostics& diags,
           const std::function<void(const Statement&)>& contactDone) {
  const int errorsBefore = diags.errorCount();
  model = Model{};
  model.title = dataset.title;
  model.file = dataset.file;
  for (const Statement& s : dataset.statements)
    if (s.id) model.statementLines.emplace(std::make_pair(s.name, *s.id), s.where.line);
  buildDataElements(dataset, model, diags);  // SPLINE, CURVE, MATRIX, STRING first
  buildSensors(dataset, model, diags);       // before any expression: SENVAL(id) reads them

  PartBuilder parts;
  StatementGroups groups;
  readStatements(dataset, model, parts, groups, diags);
  parts.build(dataset, model, diags);  // parts and markers: every other element names them
  readMaterials(dataset, diags);  // MATERIAL (data only, checked) and PART's MATERIAL=
  buildJoints(groups.joints, model, diags);
  buildJointPrimitives(groups.jprims, model, diags);
  buildMotions(groups.motions, groups.userEquations, model, diags);  // after the joints they drive
  buildFrictions(groups.frictions, model, diags);  // FRICTION (friction_builder.cpp)
  // User equations (user_equation_builder.cpp): before any function is bound, since every
  // function may read them (VARVAL, DIF, ARYVAL, ...).
  buildUserEquations(groups.userEquations, dataset, model, diags);
  buildSForces(groups.sforces, model, diags);
  // COUPLER and GEAR (coupling_builder.cpp): after every joint and marker exists.
  buildCouplings(groups.couplings, model, diags);
  // GCON (general_constraint_builder.cpp): after every marker exists.
  buildGeneralConstraints(groups.gcons, model, diags);
  buildUserConstraints(groups.ucons, model, diags);  // UCON (user_constraint_builder.cpp)
  buildPointCurves(groups.ptcvs, model, diags);  // PTCV (point_curve_builder.cpp)
  buildCurveCurves(groups.cvcvs, model, diags);  // CVCV (curve_curve_builder.cpp)
  // SPRINGDAMPER, BUSHING, FIELD, BEAM, VFORCE, VTORQUE, GFORCE (force_element_builder.cpp).
  buildForceElements(groups.forceElements, model, diags);
  // GRAPHICS (graphics_builder.cpp): checked here, after every marker (errors and the kinds
  // not drawn); the viewer's scene builds them again for their geometry.
  (void)buildGraphics(dataset, model, diags);
  // CONTACT (contact_builder.cpp): reads the GRAPHICS solids, after every marker exists.
  buildContacts(groups.contacts, dataset, model, diags, contactDone);

  // Functions, once every element they may read exists (a force may read another's force).
  bindSForceFunctions(groups.sforces, model, diags);
  bindForceElementFunctions(groups.forceElements, model, diags);
  checkForceReadBackCycles(model, diags);  // a force reading its own force (§4d)
  bindUserEquationFunctions(groups.userEquations, model, diags);
  bindSensorFunctions(dataset, model, diags);
  buildRequests(groups.requests, model, diags);  // last: a request may read every element
  return diags.errorCount() == errorsBefore;
}

}  // namespace

bool buildModel(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  return build(dataset, model, diags, {});
}

bool buildModelReleasingContacts(language::Dataset& dataset, Model& model, Diagnostics& diags) {
  // Nothing after the CONTACT builder reads a CONTACT statement's arguments (requests and
  // functions read the contacts). The statements are the caller's, not const: casting the
  // const away to release them is defined.
  return build(dataset, model, diags, [](const Statement& s) {
    std::vector<language::Argument>().swap(const_cast<Statement&>(s).args);
  });
}

}  // namespace openmss::model
