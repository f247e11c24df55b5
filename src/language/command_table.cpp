// The command table (.acf files and the interactive prompt): the commands of the ADAMS/Solver
// Reference Manual (docs/language.md, "Commands"). A command that shares its name with a statement
// redefines or lists that statement's data, so it takes the statement's arguments plus LIST; none
// of them is mandatory in a command because a command changes only what it names.

#include <algorithm>
#include <string>
#include <utility>

#include "language/schema_builder.hpp"
#include "language/statement_table.hpp"

namespace openmss::language {

using namespace schema_builder;

namespace {

// Commands that redefine or list the statement of the same name.
const std::vector<std::string> kStatementCommands = {
    "PART",         "MARKER",      "FLEX_BODY",   "JOINT",      "MOTION",     "GCON",    "UCON",
    "ACCGRAV",      "BEAM",        "BUSHING",     "FIELD",      "FRICTION",   "GFORCE",  "SFORCE",
    "SPRINGDAMPER", "VFORCE",      "VTORQUE",     "ARRAY",      "SPLINE",     "STRING",  "VARIABLE",
    "DIFF",
    "DEBUG",        "EQUILIBRIUM", "IC",          "INTEGRATOR", "KINEMATICS", "LSOLVER", "SENSOR",
    "OUTPUT",       "REQUEST",     "ENVIRONMENT", "PREFERENCES"};

// Element kinds that ACTIVATE and DEACTIVATE switch.
const std::vector<std::string> kSwitchableElements = {
    "BEAM",   "BUSHING",      "CONTACT", "CLEARANCE", "COUPLER",  "CVCV",   "DIFF",
    "FIELD",  "FRICTION",     "GCON",    "GEAR",      "GFORCE",   "GSE",    "JOINT",
    "JPRIM",  "LSE",          "MFORCE",  "MOTION",    "NFORCE",   "PTCV",   "REQUEST", "SENSOR",
    "SFORCE", "SPRINGDAMPER", "TFSISO",  "UCON",      "VARIABLE", "VFORCE", "VTORQUE"};

StatementSpec elementSwitch(std::string name) {
  std::vector<ArgumentSpec> a;
  for (const auto& e : kSwitchableElements) a.push_back(flag(e));
  a.push_back(integers("ID"));
  a.push_back(integer("RANGE", 2, 2));
  return statement(std::move(name), IdRule::NotAllowed, a);
}

// The FORTRAN-era integrator commands GSTIFF/WSTIFF/DSTIFF set the parameters of one method.
StatementSpec integratorMethod(std::string name) {
  return statement(std::move(name), IdRule::NotAllowed,
                   {real("ERROR"), real("HINIT"), real("HMAX"), real("HMIN"), integer("KMAX"),
                    integer("MAXIT"), word("PATTERN", {"T", "F", "TRUE", "FALSE"}, 1, 10),
                    word("INTERPOLATE", {"ON", "OFF"}), flag("DEFAULT"), flag("LIST")});
}

// What each command does, in one line for HELP (docs/language.md, "Commands"). Statement commands
// are described by kStatementCommands instead.
const std::vector<std::pair<std::string, std::string>> kCommandSummaries = {
    {"GSTIFF", "sets the error tolerance and steps of the GSTIFF integrator"},
    {"WSTIFF", "sets the error tolerance and steps of the WSTIFF integrator"},
    {"DSTIFF", "sets the error tolerance and steps of the DASSL integrator"},
    {"ACTIVATE", "switches elements back on for the next SIMULATE"},
    {"DEACTIVATE", "switches elements off for the next SIMULATE"},
    {"CONTROL", "passes control to a user control subroutine (ROUTINE=)"},
    {"FILE", "loads a data set (MODEL=) or runs a command file (COMMAND=)"},
    {"LINEAR", "linear analysis: eigenvalues or state matrices"},
    {"RELOAD", "restores the model and state written by SAVE"},
    {"SAVE", "saves the model and state (STATES, SYSTEM) to a file"},
    {"SIMULATE", "runs an analysis: KINEMATICS, STATICS, DYNAMICS or TRANSIENT"},
    {"STOP", "closes the output files and ends the session"},
    {"HELP", "lists the commands and whether the solver supports them yet"},
    {"INFO", "lists position, velocity, acceleration or force of a marker"},
    {"MENU", "lists the command menu"},
    {"SHOW", "shows CPU time, graphics options, simulation status or time"},
    {"TIME", "shows the simulation time, step size and step counts"},
    {"AINIT", "resets the graphics display to its original orientation"},
    {"AUTOSCALE", "recenters and rescales the graphics display"},
    {"BACKUP", "shrinks the graphics display to a rectangle"},
    {"ZOOM", "enlarges a rectangle of the graphics display"},
    {"CENTER", "picks a new center for the graphics display"},
    {"DRAW", "redraws the graphics display"},
    {"SET", "sets graphics display options"},
    {"RETURN", "leaves graphics input and continues the simulation"},
    {"ERASE", "turns off the graphics of up to three GRAPHICS statements"},
    {"RESTORE", "turns on the graphics of up to three GRAPHICS statements"},
    {"PLOT", "plots the output of a REQUEST"},
};

// Every command gets its HELP line here, so a command added to the table without one shows
// up in Schema.EveryCommandHasASummary.
void describeCommands(std::vector<StatementSpec>& table) {
  for (auto& c : table) {
    if (std::find(kStatementCommands.begin(), kStatementCommands.end(), c.name) !=
        kStatementCommands.end()) {
      c.summary = "redefines or lists " + c.name + " statement data";
      continue;
    }
    for (const auto& [name, summary] : kCommandSummaries)
      if (name == c.name) c.summary = summary;
  }
}

}  // namespace

std::vector<StatementSpec> buildCommandTable(const std::vector<StatementSpec>& statements) {
  std::vector<StatementSpec> t;
  for (const auto& name : kStatementCommands) {
    auto it = std::find_if(statements.begin(), statements.end(),
                           [&](const StatementSpec& s) { return s.name == name; });
    if (it == statements.end()) continue;
    StatementSpec c = *it;
    for (auto& a : c.arguments) a.required = false;
    c.arguments.push_back(flag("LIST"));
    t.push_back(std::move(c));
  }
  const auto N = IdRule::NotAllowed;
  t.push_back(integratorMethod("GSTIFF"));
  t.push_back(integratorMethod("WSTIFF"));
  t.push_back(integratorMethod("DSTIFF"));

  // Simulation.
  t.push_back(elementSwitch("ACTIVATE"));
  t.push_back(elementSwitch("DEACTIVATE"));
  t.push_back(statement("CONTROL", N, {expression("FUNCTION"), word("ROUTINE")}));
  t.push_back(statement("FILE", N, {word("COMMAND"), word("MODEL"), word("OUTPUT_PREFIX")}));
  t.push_back(statement(
      "LINEAR", N,
      {flag("EIGENSOL"), flag("STATEMAT"), flag("MKB"), flag("EXPORT"), integer("PINPUT"),
       integer("POUTPUT"), integer("PSTATE"), flag("NODAMPIN"), word("FORMAT"), word("FILE"),
       integers("COORDS"), flag("ENERGY"), flag("DISSIPAT"), flag("KINETIC"), flag("NOVECTOR")}));
  t.push_back(statement(
      "RELOAD", N,
      {flag("STATES"), flag("SYSTEM"), word("FILE"), word("OUTPUT_PREFIX"), text("TITLE")}));
  t.push_back(statement("SAVE", N, {flag("STATES"), flag("SYSTEM"), word("FILE")}));
  t.push_back(statement(
      "SIMULATE", N,
      {flag("DYNAMICS"), flag("KINEMATICS"), flag("STATICS"), flag("TRANSIENT"),
       flag("INITIAL_CONDITIONS"), flag("DISPLACEMENT"), flag("VELOCITY"), flag("ACCELERATION"),
       real("END"), real("DURATION"), integer("STEPS"), real("DTOUT")}));
  t.push_back(statement("STOP", N, {}));

  // Information.
  t.push_back(statement("HELP", N, {}));
  t.push_back(statement("INFO", N,
                        {flag("DISPLACEMENT"), flag("VELOCITY"), flag("ACCELERATION"),
                         flag("FORCE"), integer("I"), integer("J"), integer("RM")}));
  t.push_back(statement("MENU", N, {}));
  t.push_back(statement("SHOW", N, {flag("CPU"), flag("GRAPHICS"), flag("STATUS"), flag("TIME")}));
  t.push_back(statement("TIME", N, {}));

  // Interactive graphics (the ADAMS/Solver Overview, "Information" and graphics commands).
  for (const char* name :
       {"AINIT", "AUTOSCALE", "BACKUP", "ZOOM", "CENTER", "DRAW", "SET", "RETURN"})
    t.push_back(statement(name, N, {}));
  t.push_back(statement("ERASE", N, {integer("ID", 1, 3)}));
  t.push_back(statement("RESTORE", N, {integer("ID", 1, 3)}));
  t.push_back(statement("PLOT", N, {integer("REQUEST"), integer("COMPONENT")}));
  describeCommands(t);
  return t;
}

}  // namespace openmss::language
