#include "language/schema.hpp"

#include <gtest/gtest.h>

#include "language/name_resolution.hpp"

namespace openmss::language {
namespace {

std::vector<NameCandidate> argumentCandidates(const StatementSpec& s) {
  std::vector<NameCandidate> c;
  for (const auto& a : s.arguments) c.push_back({a.name, a.minAbbreviation, &a.aliases});
  return c;
}

std::string resolveArgument(const char* statement, const char* written, bool command = false) {
  const StatementSpec* s = command ? findCommandSpec(statement) : findStatementSpec(statement);
  if (!s) return "<no statement>";
  auto r = resolveName(written, argumentCandidates(*s));
  if (r.status == NameResolution::Status::Ambiguous) return "<ambiguous>";
  if (r.status == NameResolution::Status::Unknown) return "<unknown>";
  return s->arguments[r.index].name;
}

std::string resolveCommand(const char* written) {
  std::vector<NameCandidate> c;
  for (const auto& s : commandSchema()) c.push_back({s.name, s.minAbbreviation, nullptr});
  auto r = resolveName(written, c);
  return r.status == NameResolution::Status::Resolved ? commandSchema()[r.index].name : "<none>";
}

// Every statement of the ADAMS/Solver Reference Manual (docs/language.md, "Statements").
TEST(Schema, CoversTheReferenceManualStatements) {
  for (const char* name :
       {"END",        "TITLE",      "FE_PART", "FLEX_BODY",   "MATERIAL",     "PART",
        "POINT_MASS", "GRAPHICS",   "MARKER",  "COUPLER",     "CVCV",         "GEAR",
        "GCON",       "JOINT",      "JPRIM",   "MOTION",      "PTCV",         "ACCGRAV",
        "BEAM",       "BUSHING",    "CONTACT", "FE_LOAD",     "FIELD",        "FRICTION",
        "GFORCE",     "MFORCE",     "NFORCE",  "SFORCE",      "SPRINGDAMPER", "VFORCE",
        "VTORQUE",    "DIFF",       "GSE",     "LSE",         "TFSISO",       "VARIABLE",
        "ARRAY",      "CURVE",      "MATRIX",  "PINPUT",      "POUTPUT",      "SPLINE",
        "STRING",     "SURFACE",    "DEBUG",   "ENVIRONMENT", "EQUILIBRIUM",  "IC",
        "INTEGRATOR", "KINEMATICS", "LSOLVER", "PREFERENCES", "SENSOR",       "UNITS",
        "FEMDATA",    "LIST",       "NOLIST",  "MREQUEST",    "OUTPUT",       "REQUEST",
        "RESULTS",    "UCON",       "SECTION", "FE_NODE",     "CLEARANCE"})
    EXPECT_NE(findStatementSpec(name), nullptr) << name;
}

TEST(Schema, CoversTheCommandList) {
  for (const char* name :
       {"PART",        "MARKER",     "FLEX_BODY",    "JOINT",       "MOTION",      "GCON",
        "UCON",        "ACCGRAV",    "BEAM",         "BUSHING",     "FIELD",       "FRICTION",
        "GFORCE",      "SFORCE",     "SPRINGDAMPER", "VFORCE",      "VTORQUE",     "ARRAY",
        "SPLINE",      "STRING",     "VARIABLE",     "DEBUG",       "EQUILIBRIUM", "IC",
        "INTEGRATOR",  "KINEMATICS", "LSOLVER",      "SENSOR",      "OUTPUT",      "REQUEST",
        "ACTIVATE",    "CONTROL",    "DEACTIVATE",   "ENVIRONMENT", "FILE",        "LINEAR",
        "PREFERENCES", "RELOAD",     "SAVE",         "SIMULATE",    "STOP",        "HELP",
        "INFO",        "MENU",       "SHOW",         "TIME",        "DSTIFF",      "GSTIFF",
        "WSTIFF",      "AINIT",      "AUTOSCALE",    "BACKUP",      "ZOOM",        "CENTER",
        "ERASE",       "RESTORE",    "PLOT",         "RETURN"})
    EXPECT_NE(findCommandSpec(name), nullptr) << name;
}

TEST(Schema, MarksWhatTheSolverSupports) {
  EXPECT_TRUE(findStatementSpec("MARKER")->solverSupported);
  EXPECT_TRUE(findStatementSpec("END")->solverSupported);
  for (const char* built : {"NFORCE", "JPRIM", "GCON", "UCON", "PTCV", "CVCV", "FRICTION", "SENSOR"})
    EXPECT_TRUE(findStatementSpec(built)->solverSupported) << built;
  EXPECT_FALSE(findStatementSpec("FLEX_BODY")->solverSupported);
  EXPECT_TRUE(findStatementSpec("CONTACT")->solverSupported);
  EXPECT_TRUE(findCommandSpec("SIMULATE")->solverSupported);
  EXPECT_TRUE(findCommandSpec("LINEAR")->solverSupported);
  EXPECT_TRUE(findCommandSpec("SAVE")->solverSupported);
  EXPECT_FALSE(findCommandSpec("AUTOSCALE")->solverSupported);
  EXPECT_TRUE(findCommandSpec("PART")->solverSupported);  // redefines PART (issue 15)
  EXPECT_FALSE(findCommandSpec("FLEX_BODY")->solverSupported);
}

// Every name written at its minimum abbreviation must resolve to itself.
TEST(Schema, MinimumAbbreviationsAreUnambiguous) {
  for (const auto* table : {&statementSchema(), &commandSchema()}) {
    std::vector<NameCandidate> names;
    for (const auto& s : *table) names.push_back({s.name, s.minAbbreviation, nullptr});
    for (const auto& s : *table) {
      auto r = resolveName(s.name.substr(0, s.minAbbreviation), names);
      ASSERT_EQ(r.status, NameResolution::Status::Resolved) << s.name;
      EXPECT_EQ((*table)[r.index].name, s.name);
      auto args = argumentCandidates(s);
      for (const auto& a : s.arguments) {
        auto ra = resolveName(a.name.substr(0, a.minAbbreviation), args);
        ASSERT_EQ(ra.status, NameResolution::Status::Resolved) << s.name << " " << a.name;
        EXPECT_EQ(s.arguments[ra.index].name, a.name) << s.name;
      }
    }
  }
}

TEST(Schema, RealSpellingsResolve) {
  EXPECT_EQ(resolveArgument("REQUEST", "D"), "DISPLACEMENT");
  EXPECT_EQ(resolveArgument("REQUEST", "V"), "VELOCITY");
  EXPECT_EQ(resolveArgument("REQUEST", "A"), "ACCELERATION");
  EXPECT_EQ(resolveArgument("REQUEST", "F"), "FORCE");
  EXPECT_EQ(resolveArgument("REQUEST", "C"), "COMMENT");
  EXPECT_EQ(resolveArgument("REQUEST", "F2"), "F2");
  EXPECT_EQ(resolveArgument("REQUEST", "FU"), "FUNCTION");
  EXPECT_EQ(resolveArgument("REQUEST", "CN"), "CNAMES");
  EXPECT_EQ(resolveArgument("GRAPHICS", "COR"), "CORNER");
  EXPECT_EQ(resolveArgument("GRAPHICS", "XS"), "XSCALE");
  EXPECT_EQ(resolveArgument("GRAPHICS", "YS"), "YSCALE");
  EXPECT_EQ(resolveArgument("GRAPHICS", "ZS"), "ZSCALE");
  EXPECT_EQ(resolveArgument("GRAPHICS", "X"), "X");
  EXPECT_EQ(resolveArgument("MARKER", "EU"), "REULER");
  EXPECT_EQ(resolveArgument("PART", "EU"), "REULER");
  EXPECT_EQ(resolveArgument("SFORCE", "TRANSLATIONAL"), "TRANSLATION");
  EXPECT_EQ(resolveArgument("SFORCE", "ROTATIONAL"), "ROTATION");
  EXPECT_EQ(resolveArgument("EQUILIBRIUM", "STAB", true), "STABILITY");
  EXPECT_EQ(resolveArgument("EQUILIBRIUM", "IMBAL", true), "IMBALANCE");
  EXPECT_EQ(resolveArgument("EQUILIBRIUM", "ERR", true), "ERROR");
  EXPECT_EQ(resolveArgument("EQUILIBRIUM", "TLIM", true), "TLIMIT");
  EXPECT_EQ(resolveArgument("EQUILIBRIUM", "ALIM", true), "ALIMIT");
  EXPECT_EQ(resolveArgument("SIMULATE", "STAT", true), "STATICS");
  EXPECT_EQ(resolveArgument("SIMULATE", "DYN", true), "DYNAMICS");
  EXPECT_EQ(resolveArgument("SIMULATE", "DUR", true), "DURATION");
  EXPECT_EQ(resolveArgument("INTEGRATOR", "ERR", true), "ERROR");
  EXPECT_EQ(resolveArgument("VARIABLE", "FUNC", true), "FUNCTION");
  EXPECT_EQ(resolveCommand("SIM"), "SIMULATE");
  EXPECT_EQ(resolveCommand("EQUIL"), "EQUILIBRIUM");
  EXPECT_EQ(resolveCommand("INT"), "INTEGRATOR");
  EXPECT_EQ(resolveCommand("ACCG"), "ACCGRAV");
}

// HELP prints one line per command from the schema: none may be left without a description.
TEST(Schema, EveryCommandHasASummary) {
  for (const auto& c : commandSchema()) {
    EXPECT_FALSE(c.summary.empty()) << c.name;
    EXPECT_LE(c.summary.size(), 64u) << c.name << ": keep HELP within 80 columns";
  }
  EXPECT_TRUE(findCommandSpec("HELP")->solverSupported);
}

}  // namespace
}  // namespace openmss::language
