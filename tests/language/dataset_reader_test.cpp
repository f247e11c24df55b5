// One test per data-set syntax rule (docs/language.md, "Reading rules, as implemented"), with
// the exact diagnostics expected.

#include <gtest/gtest.h>

#include <numbers>

#include "language/reader.hpp"

namespace openmss::language {
namespace {

struct ReadResult {
  Dataset dataset;
  std::vector<std::string> diagnostics;

  const Statement& at(size_t k) const { return dataset.statements.at(k); }
};

ReadResult read(const std::string& body, const ReadOptions& options = {}) {
  ReadResult r;
  Diagnostics diags;
  readDatasetText("Title line\n" + body, "t.adm", r.dataset, diags, options);
  for (const auto& d : diags.all()) r.diagnostics.push_back(format(d));
  return r;
}

using Lines = std::vector<std::string>;

TEST(DatasetReader, LineOneIsTheTitleAndIsNotParsed) {
  ReadResult r;
  Diagnostics diags;
  readDatasetText("PART/1, this is only a title!\nPART/1, GROUND\nEND\n", "t.adm", r.dataset,
                  diags);
  EXPECT_TRUE(diags.all().empty());
  EXPECT_EQ(r.dataset.title, "PART/1, this is only a title!");
  ASSERT_EQ(r.dataset.statements.size(), 1u);
  EXPECT_TRUE(r.dataset.sawEnd);
}

TEST(DatasetReader, ExclamationMarkStartsAComment) {
  auto r = read("! a whole-line comment\nMARKER/1, PART=1 ! QP=oops\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 1u);
  EXPECT_FALSE(r.at(0).has("QP"));
}

TEST(DatasetReader, FiveBlanksEndTheStatementTextOfALine) {
  auto r = read("MARKER/15, PART=4, QP=10,0,0     PISTON MARKER\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.at(0).find("QP")->values.size(), 3u);
}

TEST(DatasetReader, FiveBlanksDoNotEndAnExpression) {
  auto r = read("MOTION/1, JOINT=1, FUNCTION=POLY(TIME,     0, 0, 360D)\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("FUNCTION")->expression, "POLY(TIME,     0, 0, 360D)");
}

TEST(DatasetReader, ALineStartingBeyondColumnFiveIsAComment) {
  auto r = read("      PART/9, GROUND\nPART/1, GROUND\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 1u);
  EXPECT_EQ(*r.at(0).id, 1);
}

TEST(DatasetReader, CommaInColumnOneContinuesAnAssignment) {
  auto r = read("MARKER/1, PART=1, QP=1, 2\n! comment between\n, 3\n, REULER=90D, 0, 0\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const Argument* qp = r.at(0).find("QP");
  ASSERT_EQ(qp->values.size(), 3u);
  EXPECT_EQ(qp->values[2].number, 3.0);
  EXPECT_EQ(qp->separators, (std::vector<char>{',', ','}));
  EXPECT_EQ(r.at(0).lastLine, 5);
}

TEST(DatasetReader, ABreakBeforeAColonKeepsTheColon) {
  auto r = read("PART/1, MASS=1, EXACT=X:Y\n,:PSI\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const Argument* exact = r.at(0).find("EXACT");
  ASSERT_EQ(exact->values.size(), 3u);
  EXPECT_EQ(exact->values[2].text, "PSI");
  EXPECT_EQ(exact->separators, (std::vector<char>{':', ':'}));
}

TEST(DatasetReader, AnExpressionContinuesAfterTheContinuationComma) {
  auto r = read(
      "SFORCE/1, I=1, J=2, TRANSLATIONAL, FUNCTION=STEP(TIME,0\n,,0,1,1)\n"
      "SFORCE/2, I=1, J=2, ROTATIONAL, FUNCTION=-2*\n,VR(1, 2)\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("FUNCTION")->expression, "STEP(TIME,0,0,1,1)");
  EXPECT_TRUE(r.at(0).has("TRANSLATION"));
  EXPECT_EQ(r.at(1).find("FUNCTION")->expression, "-2*VR(1, 2)");
  EXPECT_TRUE(r.at(1).has("ROTATION"));
}

TEST(DatasetReader, AContinuationLineStartingWithAnArgumentEndsTheExpression) {
  auto r = read("REQUEST/1, F2=DX(1,2)\n, C=first comment\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("F2")->expression, "DX(1,2)");
  EXPECT_EQ(r.at(0).find("COMMENT")->values.at(0).text, "first comment");
}

TEST(DatasetReader, BackslashEndsAnExpressionAndSemicolonEndsAStatement) {
  auto r =
      read("GFORCE/2, I=14, JFLOAT=2, RM=8, TX=24\\TY=48\\TZ=57\\FX=18; PART/1, GROUND\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 2u);
  EXPECT_EQ(r.at(0).find("TY")->expression, "48");
  EXPECT_EQ(r.at(0).find("FX")->expression, "18");
  EXPECT_EQ(r.at(1).name, "PART");
}

TEST(DatasetReader, AmpersandContinuesAStatement) {
  auto r = read("MARKER/1, PART=1, &\n      QP=1,2,3\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.at(0).find("QP")->values.size(), 3u);
}

TEST(DatasetReader, AmpersandInsideAnExpressionIsAnErrorInADataSet) {
  auto r = read("VARIABLE/1, FUNCTION=1+ &\n2\nEND\n");
  EXPECT_EQ(r.diagnostics,
            Lines{"t.adm:2:25: error: VARIABLE/1: '&' cannot continue a function expression in "
                  "a data set. End the line without '&' and start the next line with ',' in "
                  "column 1"});
  EXPECT_EQ(r.at(0).find("FUNCTION")->expression, "1+2");
}

TEST(DatasetReader, DMeansDegrees) {
  auto r = read("MARKER/1, PART=1, REULER=45D, 45.D, 1.E-3D\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const auto& v = r.at(0).find("REULER")->values;
  EXPECT_DOUBLE_EQ(v[0].number, std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(v[1].number, std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(v[2].number, 1e-3 * std::numbers::pi / 180);
  EXPECT_TRUE(v[2].degrees);
  EXPECT_FALSE(v[0].isInteger);
}

TEST(DatasetReader, IntegerArgumentsAcceptOnlyWholeNumbers) {
  auto r = read("MARKER/1, PART=1.0\nMARKER/2, PART=1E1\nMARKER/3, PART=1.5\nEND\n");
  EXPECT_EQ(r.diagnostics,
            Lines{"t.adm:4:16: error: MARKER/3: PART expects an integer; 1.5 is not a whole "
                  "number. Write a whole number such as 2 or 2.0"});
  EXPECT_EQ(r.at(0).find("PART")->values.at(0).number, 1.0);
  EXPECT_EQ(r.at(1).find("PART")->values.at(0).number, 10.0);
  EXPECT_FALSE(r.at(2).has("PART"));
}

TEST(DatasetReader, IdentifiersArePositiveIntegersOfAtMostEightDigits) {
  auto r = read(
      "PART/01, GROUND\nPART/-2, MASS=1\nPART/2.5, MASS=1\nPART/123456789, MASS=1\n"
      "MARKER, PART=1\nEND\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:3:6: error: PART: identifier '-2' is not a positive integer of at most "
                   "8 digits. Use a whole number from 1 to 99999999",
                   "t.adm:4:6: error: PART: identifier '2.5' is not a positive integer of at most "
                   "8 digits. Use a whole number from 1 to 99999999",
                   "t.adm:5:6: error: PART: identifier '123456789' is not a positive integer of "
                   "at most 8 digits. Use a whole number from 1 to 99999999",
                   "t.adm:6:1: error: MARKER: missing identifier. Write MARKER/id with a "
                   "positive integer id, e.g. MARKER/1",
                   "t.adm:6:9: error: MARKER: missing '/' after MARKER. Write MARKER/ before the "
                   "arguments"}));
  EXPECT_EQ(*r.at(0).id, 1);
}

TEST(DatasetReader, AnIdentifierOnAStatementThatTakesNoneIsIgnoredWithAWarning) {
  auto r = read("ACCGRAV/5, KGRAV=-9.81\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:9: warning: ACCGRAV: ACCGRAV takes no identifier; '5' "
                                 "is ignored. Write ACCGRAV/ without a number"});
  EXPECT_FALSE(r.at(0).id.has_value());
  EXPECT_TRUE(r.at(0).has("KGRAV"));
}

TEST(DatasetReader, ADuplicateStatementWarnsAndTheLastOneWins) {
  auto r = read("PART/2, MASS=1\nMARKER/3, PART=2\nPART/02, MASS=5\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:4:1: warning: PART/2: PART/2 is defined again; the "
                                 "definition at line 2 is ignored. Remove or renumber one of "
                                 "them"});
  ASSERT_EQ(r.dataset.statements.size(), 2u);
  EXPECT_EQ(r.at(0).name, "MARKER");
  EXPECT_EQ(r.at(1).find("MASS")->values.at(0).number, 5.0);
}

TEST(DatasetReader, NothingAfterEndIsRead) {
  auto r = read("PART/1, GROUND\nEND\nthis is not read at all\nFOO/1\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.dataset.statements.size(), 1u);
}

TEST(DatasetReader, MissingEndIsAWarning) {
  auto r = read("PART/1, GROUND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2: warning: the data set has no END statement. Add END "
                                 "as the last statement"});
}

TEST(DatasetReader, CaseAndLineEndingsDoNotMatter) {
  auto r = read("marker/1, part=1, Qp=1,2,3\r\nPart/1, Ground\r\nend\r\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.dataset.statements.size(), 2u);
  EXPECT_EQ(r.at(0).name, "MARKER");
  EXPECT_EQ(r.at(0).spelled, "marker");
  EXPECT_EQ(r.at(0).args.at(1).spelled, "Qp");
}

TEST(DatasetReader, AbbreviationsResolveAndAmbiguityIsReported) {
  auto r = read("REQUEST/1, D, I=2, J=3, C=disp\nMA/2, PART=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:3:1: error: MA/2: 'MA' is an ambiguous abbreviation of "
                                 "MARKER, MATERIAL, MATRIX. Write more letters of the statement "
                                 "name"});
  EXPECT_TRUE(r.at(0).has("DISPLACEMENT"));
}

TEST(DatasetReader, UnknownStatementsAreNamed) {
  auto r = read("WIDGET/1, SIZE=3\n, COLOR=2\nPART/1, GROUND\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:1: error: WIDGET/1: 'WIDGET' is not an ADAMS "
                                 "statement. Check the spelling; docs/language.md lists every "
                                 "statement"});
  ASSERT_EQ(r.dataset.statements.size(), 1u);
}

TEST(DatasetReader, UnknownArgumentsListTheValidNames) {
  auto r = read("ACCGRAV/ HGRAV=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:10: error: ACCGRAV: unknown argument 'HGRAV'. ACCGRAV "
                                 "accepts: IGRAV, JGRAV, KGRAV"});
}

TEST(DatasetReader, ValueTypesCountsAndWordsAreChecked) {
  auto r = read("MARKER/1, PART=ABC, QP=1,2\nUNITS/ FORCE=NEWTONS\nPART/1, GROUND=1, MASS\nEND\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:2:16: error: MARKER/1: PART expects an integer, not 'ABC'. Write a "
                   "whole number, e.g. PART=1",
                   "t.adm:2:21: error: MARKER/1: QP expects 3 values; 2 given",
                   "t.adm:3:14: error: UNITS: 'NEWTONS' is not a valid value of FORCE. Use one "
                   "of: CENTINEWTON, DYNE, KILOGRAM_FORCE, KNEWTON, KPOUND_FORCE, MEGANEWTON, "
                   "MICRONEWTON, MILLINEWTON, NANONEWTON, NEWTON, OUNCE_FORCE, POUND_FORCE, "
                   "POUNDAL",
                   "t.adm:4:9: error: PART/1: GROUND takes no value. Remove the '=' and the value "
                   "after GROUND",
                   "t.adm:4:19: error: PART/1: MASS needs a value. Write MASS=<number>"}));
}

TEST(DatasetReader, MissingDelimitersAreReported) {
  auto r = read("MARKER/1 PART=1, QP=1,2,3 REULER=0,0,0\nEND\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:2:10: error: MARKER/1: missing ',' before 'PART'. Separate arguments "
                   "with ','",
                   "t.adm:2:27: error: MARKER/1: missing ',' before 'REULER'. Separate arguments "
                   "with ','"}));
  EXPECT_TRUE(r.at(0).has("REULER"));
}

TEST(DatasetReader, TwoStatementsOnOneLineNeedASemicolon) {
  auto r = read("PART/1, GROUND MARKER/1, PART=1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:2:16: error: PART/1: a second statement starts on this "
                                 "line without ';'. Put ';' between two statements on one line, "
                                 "or start a new line"});
  ASSERT_EQ(r.dataset.statements.size(), 2u);
  EXPECT_EQ(r.at(1).name, "MARKER");
}

TEST(DatasetReader, AContinuationNeedsAmpersandOrComma) {
  auto r = read("PART/2, MASS=1\nCM=3, IP=1,1,1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{"t.adm:3:1: error: PART/2: this line continues a statement "
                                 "without a continuation mark. End the previous line with '&' or "
                                 "put ',' in column 1 of this line"});
}

TEST(DatasetReader, RequiredArgumentsAreChecked) {
  auto r = read("JOINT/1, REVOLUTE, I=2\nEND\n");
  EXPECT_EQ(r.diagnostics,
            Lines{"t.adm:2:1: error: JOINT/1: missing required argument J. Add J=<integer>"});
}

TEST(DatasetReader, QuotedWordsAndRoutineNamesKeepTheirSpelling) {
  auto r = read(
      "REQUEST/1, CNAMES=\"top disp\", \"\", ROUTINE=lib::MotionOut\n"
      ", FUNCTION=USER(1)\\\n, RESULTS_NAME = Out_1\nEND\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  const Argument* names = r.at(0).find("CNAMES");
  ASSERT_EQ(names->values.size(), 2u);
  EXPECT_EQ(names->values[0].text, "top disp");
  EXPECT_TRUE(names->values[0].quoted);
  EXPECT_EQ(r.at(0).find("ROUTINE")->values.at(0).written, "lib::MotionOut");
  EXPECT_EQ(r.at(0).find("FUNCTION")->expression, "USER(1)");
  EXPECT_EQ(r.at(0).find("RESULTS_NAME")->values.at(0).text, "OUT_1");
}

TEST(DatasetReader, LinesLongerThanEightyColumnsAreReadAndOptionallyWarned) {
  const std::string longLine =
      "REQUEST/5, F2=JOINT(1,0,2,0)\\F3=JOINT(1,0,3,0)\\F4=JOINT(1,0,4,0),C=a long comment "
      "that goes on";
  auto lenient = read(longLine + "\nEND\n");
  EXPECT_EQ(lenient.diagnostics, Lines{});
  ReadOptions strict;
  strict.warnLongLines = true;
  auto warned = read(longLine + "\nEND\n", strict);
  EXPECT_EQ(warned.diagnostics,
            Lines{"t.adm:2:81: warning: line is longer than 80 columns. ADAMS documents 80 "
                  "columns; continue long statements on a new line starting with ','"});
}

TEST(DatasetReader, FiveIndependentErrorsAreAllReported) {
  auto r = read(
      "PART/1, GROUND\n"
      "MARKER/2, PART=1, QP=1,2\n"         // 1: count
      "WIDGET/3\n"                         // 2: unknown statement
      "JOINT/4, REVOLUTE, I=2, J=X\n"      // 3: type
      "SFORCE/5, I=1, J=2, TRANSLATION\n"  // 4: missing FUNCTION
      "MARKER/6, PART=1, QQ=1\n"           // 5: unknown argument
      "END\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.adm:3:19: error: MARKER/2: QP expects 3 values; 2 given",
                   "t.adm:4:1: error: WIDGET/3: 'WIDGET' is not an ADAMS statement. Check the "
                   "spelling; docs/language.md lists every statement",
                   "t.adm:5:27: error: JOINT/4: J expects an integer, not 'X'. Write a whole "
                   "number, e.g. J=1",
                   "t.adm:6:1: error: SFORCE/5: missing required argument FUNCTION. Add "
                   "FUNCTION=<expression>",
                   "t.adm:7:19: error: MARKER/6: unknown argument 'QQ'. MARKER accepts: PART, "
                   "POINT_MASS, FLEX_BODY, NODE, FE_PART, NODE_LABEL, QP, REULER, XP, ZP, USEXP, "
                   "RM, FLOATING"}));
  EXPECT_EQ(r.dataset.statements.size(), 5u);
}

}  // namespace
}  // namespace openmss::language
