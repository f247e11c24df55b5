// StatementArguments (model/statement_arguments.hpp), the one argument reader of the builders
// and settings: every read returns the value written, and every ill-formed value is reported
// once, at the argument's file:line:column, with the statement's subject and what to write.
// Statements are built by hand here so that the forms the language reader's schema already
// refuses can still reach these guards.

#include "model/statement_arguments.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;
using language::Value;

Value number(double x, int column) {
  Value v;
  v.kind = Value::Kind::Number;
  v.number = x;
  v.text = std::to_string(x);
  v.where = {"a.adm", 3, column};
  return v;
}

Value word(const std::string& w, int column) {
  Value v;
  v.kind = Value::Kind::Word;
  v.text = w;
  v.where = {"a.adm", 3, column};
  return v;
}

// PART/7 on line 3; argument k starts at column 10 * (k + 1).
Statement statement(std::vector<std::pair<std::string, std::vector<Value>>> args) {
  Statement s;
  s.name = "PART";
  s.id = 7;
  s.where = {"a.adm", 3, 1};
  int column = 10;
  for (auto& [name, values] : args) {
    Argument a;
    a.name = name;
    a.values = std::move(values);
    a.where = {"a.adm", 3, column};
    column += 10;
    s.args.push_back(std::move(a));
  }
  return s;
}

std::vector<std::string> formatted(const Diagnostics& diags) {
  std::vector<std::string> out;
  for (const auto& d : diags.all()) out.push_back(format(d));
  return out;
}

TEST(StatementArguments, ReadsWellFormedValues) {
  const Statement s = statement({{"MASS", {number(2.5, 15)}},
                                 {"QG", {number(1, 25), number(-2, 27), number(3.5, 29)}},
                                 {"CM", {number(20, 35)}},
                                 {"NS", {number(0, 45)}},
                                 {"TYPE", {word("LINEAR", 55)}},
                                 {"K", {number(1, 65), number(2, 67)}},
                                 {"VALUES", {number(4, 75), number(5, 77)}}});
  Diagnostics diags;
  StatementArguments a(s, diags);
  EXPECT_EQ(a.real("MASS"), 2.5);
  EXPECT_EQ(a.vec3("QG"), Eigen::Vector3d(1, -2, 3.5));
  EXPECT_EQ(a.id("CM"), 20);
  EXPECT_EQ(a.integer("NS", /*allowZero=*/true), 0);
  EXPECT_EQ(a.word("TYPE"), "LINEAR");
  EXPECT_EQ(a.numbers("K", 2), (std::vector<double>{1, 2}));
  EXPECT_EQ(a.numbers(*s.find("VALUES")), (std::vector<double>{4, 5}));
  EXPECT_EQ(a.firstNumber("K"), 1.0);
  // Absent arguments: no value and no diagnostic (the caller chooses the default).
  EXPECT_FALSE(a.real("IP"));
  EXPECT_FALSE(a.vec3("IP"));
  EXPECT_FALSE(a.id("IM"));
  EXPECT_FALSE(a.firstNumber("IM"));
  double positive = 0, within = 0;
  int count = 0;
  EXPECT_TRUE(a.positive(*s.find("MASS"), positive));
  EXPECT_TRUE(a.count(*s.find("CM"), count));
  EXPECT_TRUE(a.within(*s.find("MASS"), 2.5, 3.0, "from 2.5 to 3", within));
  EXPECT_EQ(positive, 2.5);
  EXPECT_EQ(count, 20);
  EXPECT_EQ(within, 2.5);  // the bounds belong to the range
  EXPECT_TRUE(a.ok());
  EXPECT_TRUE(diags.all().empty());
}

TEST(StatementArguments, EveryIllFormedValueIsReportedAtItsArgument) {
  const Statement s = statement({{"MASS", {number(1, 15), number(2, 17)}},
                                 {"QG", {number(1, 25), word("A", 27), number(3, 29)}},
                                 {"CM", {number(2.5, 35)}},
                                 {"NS", {number(-1, 45)}},
                                 {"TYPE", {number(3, 55)}},
                                 {"K", {number(1, 65)}},
                                 {"VALUES", {number(4, 75), word("B", 77)}},
                                 {"IM", {number(0, 85)}}});
  Diagnostics diags;
  StatementArguments a(s, diags);
  EXPECT_FALSE(a.real("MASS"));
  EXPECT_FALSE(a.vec3("QG"));
  EXPECT_FALSE(a.id("CM"));
  EXPECT_FALSE(a.integer("NS", true));
  EXPECT_FALSE(a.word("TYPE"));
  EXPECT_FALSE(a.numbers("K", 2));
  EXPECT_FALSE(a.numbers(*s.find("VALUES")));
  EXPECT_FALSE(a.id("IM"));
  EXPECT_FALSE(a.ok());
  EXPECT_EQ(formatted(diags),
            (std::vector<std::string>{
                "a.adm:3:10: error: PART/7: MASS needs one number. Write MASS=<number>.",
                "a.adm:3:20: error: PART/7: QG needs three numbers. Write QG=x,y,z.",
                "a.adm:3:30: error: PART/7: CM needs one positive identifier. Write CM=<id>.",
                "a.adm:3:40: error: PART/7: NS needs one non-negative integer. Write "
                "NS=<integer>.",
                "a.adm:3:50: error: PART/7: TYPE needs one word",
                "a.adm:3:60: error: PART/7: K needs 2 numbers. Write K=r1,...,r2.",
                // the word itself is located, not its argument
                "a.adm:3:77: error: PART/7: VALUES needs numbers, found 'B'. Write numeric "
                "constants.",
                "a.adm:3:80: error: PART/7: IM needs one positive identifier. Write IM=<id>."}));
}

TEST(StatementArguments, SettingsChecksKeepTheDefaultAndSayWhatToWrite) {
  const Statement s = statement({{"ERROR", {number(0, 15)}},
                                 {"MAXIT", {number(0.5, 25)}},
                                 {"ALPHA", {number(0.1, 35)}},
                                 {"SI1", {}}});
  Diagnostics diags;
  StatementArguments a(s, diags);
  double error = 1e-3, alpha = -0.3;
  int maxit = 25;
  EXPECT_FALSE(a.positive(s.args[0], error));
  EXPECT_FALSE(a.count(s.args[1], maxit));
  EXPECT_FALSE(a.within(s.args[2], -1.0 / 3.0, 0.0, "between -1/3 and 0", alpha));
  a.unsupported(s.args[3], "Use I3 or SI2.");
  EXPECT_EQ(error, 1e-3);  // unchanged: the defaults stay when a value is refused
  EXPECT_EQ(maxit, 25);
  EXPECT_EQ(alpha, -0.3);
  EXPECT_FALSE(a.ok());
  EXPECT_EQ(formatted(diags),
            (std::vector<std::string>{
                "a.adm:3:10: error: PART/7: ERROR must be a positive number. Write "
                "ERROR=<value > 0>.",
                "a.adm:3:20: error: PART/7: MAXIT must be a positive whole number. Write "
                "MAXIT=<count >= 1>.",
                "a.adm:3:30: error: PART/7: ALPHA must be between -1/3 and 0. Write "
                "ALPHA=<value between -1/3 and 0>.",
                "a.adm:3:40: error: PART/7: SI1 is not supported yet. Use I3 or SI2."}));
}

TEST(StatementArguments, RequireReportsOnlyWhatTheSchemaDoesNot) {
  // The schema does not require a PART's CM: the builder's requirement is reported at the
  // statement.
  Statement part = statement({});
  Diagnostics diags;
  StatementArguments a(part, diags);
  a.require("CM", "<marker id>");
  EXPECT_FALSE(a.ok());
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "a.adm:3:1: error: PART/7: missing required argument CM. Add CM=<marker id>.");
  // Present: nothing to report.
  Statement withCm = statement({{"CM", {number(20, 15)}}});
  Diagnostics quiet;
  StatementArguments b(withCm, quiet);
  b.require("CM", "<marker id>");
  EXPECT_TRUE(b.ok());
  EXPECT_TRUE(quiet.all().empty());
  // SFORCE's FUNCTION is required by the schema: the language reader reported it already.
  Statement sforce = statement({});
  sforce.name = "SFORCE";
  StatementArguments c(sforce, quiet);
  c.require("FUNCTION", "<expression>");
  EXPECT_TRUE(c.ok());
  EXPECT_TRUE(quiet.all().empty());
}

TEST(StatementArguments, FirstNumberIsSilent) {
  // The command interpreter's END=, STEPS=, ... : a word gives no number and no diagnostic.
  const Statement s = statement({{"END", {word("X", 15)}}, {"STEPS", {number(10, 25)}}});
  Diagnostics diags;
  const StatementArguments a(s, diags);
  EXPECT_FALSE(a.firstNumber("END"));
  EXPECT_EQ(a.firstNumber("STEPS"), 10.0);
  EXPECT_TRUE(diags.all().empty());
}

}  // namespace
}  // namespace openmss::model
