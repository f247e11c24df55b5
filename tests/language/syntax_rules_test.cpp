// The syntax rules of data sets and commands (docs/language.md, "Reading rules, as implemented")
// that dataset_reader_test.cpp and command_reader_test.cpp do not cover yet: one test per rule,
// with the exact diagnostics.

#include <gtest/gtest.h>

#include <numbers>

#include "language/command_reader.hpp"
#include "language/reader.hpp"

namespace openmss::language {
namespace {

using Lines = std::vector<std::string>;

struct ReadResult {
  Dataset dataset;
  Lines diagnostics;
  const Statement& at(size_t k) const { return dataset.statements.at(k); }
};

// `text` is the whole data set, title line included.
ReadResult readText(const std::string& text) {
  ReadResult r;
  Diagnostics diags;
  readDatasetText(text, "t.adm", r.dataset, diags);
  for (const auto& d : diags.all()) r.diagnostics.push_back(format(d));
  return r;
}

ReadResult read(const std::string& body) { return readText("Title line\n" + body); }

struct CommandResult {
  std::vector<Statement> commands;
  Lines diagnostics;
};

// Commands typed at the prompt, one line at a time.
CommandResult type(const Lines& lines) {
  CommandReader reader("<stdin>");
  for (const auto& l : lines) reader.feedLine(l);
  reader.finish();
  CommandResult r;
  r.commands = reader.takeCommands();
  const Diagnostics diags = reader.takeDiagnostics();
  for (const auto& d : diags.all()) r.diagnostics.push_back(format(d));
  return r;
}

// §4.3.9: a statement must begin in one of the first five columns.
TEST(SyntaxRules, AStatementMayStartInColumnsOneToFive) {
  auto r = read("    PART/1, GROUND\n     PART/2, MASS=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 1u);  // column 6 is a comment
  EXPECT_EQ(*r.at(0).id, 1);
}

// Line ends: a lone carriage return (classic Mac files) ends a line too.
TEST(SyntaxRules, ALoneCarriageReturnEndsALine) {
  auto r = readText("Title\rPART/1, GROUND\rMARKER/2, PART=1\rEND\r");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 2u);
  EXPECT_EQ(r.at(1).where.line, 3);
}

// §4.3.5: an ampersand after a comment does not continue the line.
TEST(SyntaxRules, AnAmpersandAfterACommentDoesNotContinue) {
  auto r = read("MARKER/1, PART=1 ! note &\nQP=1,2,3\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:3:1: error: MARKER/1: this line continues a statement "
                                 "without a continuation mark. End the previous line with '&' or "
                                 "put ',' in column 1 of this line"});
  EXPECT_FALSE(r.at(0).has("QP"));
}

// §4.3.5: "If you break the statement before a comma within an assignment argument, use only
// one comma" — a comma left at the end of the line as well is read as the same delimiter.
TEST(SyntaxRules, ACommaBeforeTheBreakAndTheContinuationCommaAreOneDelimiter) {
  auto r = read("MARKER/1, PART=1, QP=1,\n, 2, 3\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("QP")->values.size(), 3u);
}

TEST(SyntaxRules, AValueListMayStartOnTheContinuationLine) {
  auto r = read("MARKER/1, PART=1, QP=\n, 1, 2, 3\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("QP")->values.at(2).number, 3.0);
}

// ADAMS writes keyword lists in parentheses, e.g. FRICTION's INPUTS=(PRELOAD:REACTION_FORCE):
// the parentheses group the values; an unclosed list is an error at its end.
TEST(SyntaxRules, AValueListMayBeParenthesised) {
  auto r = read("FRICTION/1, JOINT=1, INPUTS=(PRELOAD:REACTION_FORCE), MU_STATIC=0.2\n"
                "MARKER/1, PART=1, QP=( 1, 2 ,3 )\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const auto* inputs = r.at(0).find("INPUTS");
  ASSERT_NE(inputs, nullptr);
  ASSERT_EQ(inputs->values.size(), 2u);
  EXPECT_EQ(inputs->values[0].text, "PRELOAD");
  EXPECT_EQ(inputs->values[1].text, "REACTION_FORCE");
  EXPECT_EQ(r.at(0).find("MU_STATIC")->values.at(0).number, 0.2);
  EXPECT_EQ(r.at(1).find("QP")->values.at(2).number, 3.0);
  auto bad = read("FRICTION/1, JOINT=1, INPUTS=(PRELOAD:REACTION_FORCE\nEND\n");
  ASSERT_EQ(bad.diagnostics.size(), 1u);
  EXPECT_NE(bad.diagnostics[0].find("t.adm:2:52: error: FRICTION/1: the list of INPUTS values "
                                    "is not closed"),
            std::string::npos)
      << bad.diagnostics[0];
}

// §4.3.4: a comment may sit in the middle of an argument.
TEST(SyntaxRules, ACommentLineMaySitInsideAnArgument) {
  auto r = read("MARKER/1, PART=1, QP=1,\n! the y and z coordinates\n, 2, 3\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("QP")->values.size(), 3u);
  EXPECT_EQ(r.at(0).lastLine, 4);
}

// §4.3.2: an ambiguous argument abbreviation is an error (statements: DatasetReader test).
TEST(SyntaxRules, AnAmbiguousArgumentAbbreviationIsAnError) {
  auto r = read("MARKER/1, PART=1, R=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:19: error: MARKER/1: ambiguous abbreviation 'R' "
                                 "matches REULER, RM. Write more letters of the argument name"});
}

TEST(SyntaxRules, StatementAndArgumentNamesMayBeAbbreviated) {
  auto r = read("MARK/1, PAR=1, REU=90D,0,0\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).name, "MARKER");
  EXPECT_TRUE(r.at(0).has("PART"));
  EXPECT_DOUBLE_EQ(r.at(0).find("REULER")->values.at(0).number, std::numbers::pi / 2);
}

// §4.3.8: integers are accepted where reals are expected; signs are optional.
TEST(SyntaxRules, RealArgumentsAcceptIntegersAndSignedNumbers) {
  auto r = read("MARKER/1, PART=1, QP=+1,-2,+3E+2\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const auto& qp = r.at(0).find("QP")->values;
  EXPECT_TRUE(qp[0].isInteger);
  EXPECT_EQ(qp[1].number, -2.0);
  EXPECT_EQ(qp[2].number, 300.0);
  EXPECT_FALSE(qp[2].isInteger);
}

// §4.3.1 with §4.3.2: D scales an angle, so a value in degrees is never an integer.
TEST(SyntaxRules, AnIntegerArgumentRejectsDegrees) {
  auto r = read("MARKER/1, PART=1D\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:16: error: MARKER/1: PART expects an integer; 1D is an "
                                 "angle in degrees. Write a whole number without D"});
}

// §4.3.8: numbers must not contain blanks. The value is cut at the blank and what follows
// cannot be read as arguments; every piece is located.
TEST(SyntaxRules, ANumberCannotContainBlanks) {
  auto r = read("MARKER/1, PART=1, QP=1 0,0,0\nEND\n");
  const std::string stray =
      ": error: MARKER/1: expected an argument name, found '0'. Arguments are names such as "
      "PART=1 or GROUND; check for a missing name or an extra ','";
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:2:19: error: MARKER/1: QP expects 3 values; 1 given",
                   "t.adm:2:24" + stray, "t.adm:2:26" + stray, "t.adm:2:28" + stray}));
}

// §4.3.6: two delimiters where one is allowed.
TEST(SyntaxRules, TwoCommasBetweenArgumentsAreAnError) {
  auto r = read("MARKER/1,, PART=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:10: error: MARKER/1: two delimiters in a row. Remove "
                                 "one of them; arguments are separated by a single ','"});
  EXPECT_TRUE(r.at(0).has("PART"));
}

// §4.3.6: ';' separates statements; an empty statement after the last ';' is harmless.
TEST(SyntaxRules, ATrailingSemicolonIsHarmless) {
  auto r = read("PART/1, GROUND;\nPART/2, MASS=1; MARKER/3, PART=2;\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.dataset.statements.size(), 3u);
}

// §4.3.4: nothing beyond END is read, not even the rest of its line.
TEST(SyntaxRules, TheRestOfTheEndLineIsNotRead) {
  auto r = read("PART/1, GROUND\nEND; PART/2, MASS=1\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.dataset.statements.size(), 1u);
}

// A continuation straight after the title continues the title record (never a statement):
// skipped with a warning (docs/language.md, "Lines"), as in the corpus's bipendolo.adm whose
// line 1 holds a MATERIAL statement.
TEST(SyntaxRules, AContinuationLineAfterTheTitleIsSkippedWithAWarning) {
  auto r = read(", PART=1\n, MASS=2\n!\nPART/1, GROUND\nEND\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:2:1: warning: continuation line after the title continues the title "
                   "(line 1 is never a statement); it is skipped. If line 1 was meant as a "
                   "statement, insert a title line before it",
                   "t.adm:3:1: warning: continuation line after the title continues the title "
                   "(line 1 is never a statement); it is skipped. If line 1 was meant as a "
                   "statement, insert a title line before it"}));
  ASSERT_EQ(r.dataset.statements.size(), 1u);
  EXPECT_EQ(r.dataset.statements[0].name, "PART");
}

TEST(SyntaxRules, AnAmpersandOnTheLastLineIsAnError) {
  auto r = read("PART/1, GROUND &\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:2:16: error: the statement ends with '&' but no line follows. Remove "
                   "the '&' or add the rest of the statement",
                   "t.adm:2: warning: the data set has no END statement. Add END as the last "
                   "statement"}));
}

TEST(SyntaxRules, AnEmptyDataSetIsAnError) {
  auto r = readText("");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm: error: the data set is empty. Line 1 is the title; "
                                 "statements follow and END closes the data set"});
}

// §4.3.4: five blanks end the line except in expressions — and, as decided in
// docs/language.md, in text arguments such as COMMENT.
TEST(SyntaxRules, FiveBlanksAreKeptInsideATextArgument) {
  auto r = read("REQUEST/1, DISPLACEMENT, I=1, J=2, C=top     of the rod\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("COMMENT")->values.at(0).text, "top     of the rod");
}

// §6.5.1: D means degrees in commands too.
TEST(SyntaxRules, CommandsReadDegrees) {
  auto r = type({"marker/1, reuler=90d, 0, 0"});
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.commands.size(), 1u);
  EXPECT_DOUBLE_EQ(r.commands[0].find("REULER")->values.at(0).number, std::numbers::pi / 2);
}

// §6.5.2: the argument errors of a command are reported with the command's line.
TEST(SyntaxRules, CommandArgumentErrorsAreReported) {
  auto r = type({"simulate/trans, end=1, steps=2.5", "mar/2, r=1", "integrator/error=1 2",
                 "output/reqsave=1"});
  EXPECT_EQ(r.diagnostics,
            (Lines{"<stdin>:1:30: error: SIMULATE: STEPS expects an integer; 2.5 is not a whole "
                   "number. Write a whole number such as 2 or 2.0",
                   "<stdin>:2:8: error: MARKER/2: ambiguous abbreviation 'R' matches REULER, RM. "
                   "Write more letters of the argument name",
                   "<stdin>:3:20: error: INTEGRATOR: expected an argument name, found '2'. "
                   "Arguments are names such as PART=1 or GROUND; check for a missing name or an "
                   "extra ','",
                   "<stdin>:4:8: error: OUTPUT: REQSAVE takes no value. Remove the '=' and the "
                   "value after REQSAVE"}));
}

// §6.5.3: '&' continues a command; an '&' after a '!' comment does not.
TEST(SyntaxRules, ACommandContinuesOnlyAfterAnAmpersandBeforeAnyComment) {
  auto r = type({"simulate/transient, end=1, & ! then the steps &", "  steps=10", "stop"});
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.commands.size(), 2u);
  EXPECT_TRUE(r.commands[0].has("STEPS"));
  EXPECT_EQ(r.commands[0].lastLine, 2);
  EXPECT_EQ(r.commands[1].name, "STOP");
}

}  // namespace
}  // namespace openmss::language
