// Exact diagnostic texts: each names the column inside the expression, and the file column is
// the expression's start column plus that offset.

#include <string>
#include <vector>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

// The expression starts at line 12, column 20 of model.adm.
std::vector<std::string> errorsOf(const std::string& text) {
  Diagnostics diags;
  Expression e;
  const bool ok = Expression::parse(text, {"model.adm", 12, 20}, "SFORCE/104", diags, e);
  EXPECT_FALSE(ok) << text;
  EXPECT_EQ(diags.errorCount(), static_cast<int>(diags.all().size()));
  std::vector<std::string> out;
  for (const Diagnostic& d : diags.all()) out.push_back(format(d));
  return out;
}

std::string errorOf(const std::string& text) {
  const std::vector<std::string> all = errorsOf(text);
  EXPECT_EQ(all.size(), 1u) << text;
  return all.empty() ? "" : all.front();
}

TEST(ExpressionDiagnostics, UnknownFunction) {
  EXPECT_EQ(errorOf("STEP(TIME,0,0,1,1) + FOO(2)"),
            "model.adm:12:41: error: SFORCE/104: unknown function 'FOO' at column 22 of the "
            "expression. See docs/expressions.md for the functions available.");
  EXPECT_EQ(errorOf("stpe(TIME,0,0,1,1)"),
            "model.adm:12:20: error: SFORCE/104: unknown function 'STPE' at column 1 of the "
            "expression. Did you mean STEP?");
}

TEST(ExpressionDiagnostics, UnknownName) {
  EXPECT_EQ(errorOf("2*TIEM"),
            "model.adm:12:22: error: SFORCE/104: unknown name 'TIEM' at column 3 of the "
            "expression. Did you mean TIME?");
  EXPECT_EQ(errorOf("XYZZY"),
            "model.adm:12:20: error: SFORCE/104: unknown name 'XYZZY' at column 1 of the "
            "expression. The names without arguments are PI, DTOR, RTOD, TIME, MODE, HSIZE, "
            "ORDER, NJAC, NRHS and CPU; a function call needs '(' right after its name.");
}

TEST(ExpressionDiagnostics, WrongArgumentCountSaysTheValidCounts) {
  EXPECT_EQ(errorOf("STEP(TIME,0,0,1)"),
            "model.adm:12:20: error: SFORCE/104: STEP at column 1 of the expression has 4 "
            "arguments, but STEP takes 5. Write STEP(x, x0, h0, x1, h1).");
  EXPECT_EQ(errorOf("1 + DM(1,2,3)"),
            "model.adm:12:24: error: SFORCE/104: DM at column 5 of the expression has 3 "
            "arguments, but DM takes 1 to 2. Write DM(i[, j]).");
  EXPECT_EQ(errorOf("DX()"),
            "model.adm:12:20: error: SFORCE/104: DX at column 1 of the expression has 0 "
            "arguments, but DX takes 1 to 3. Write DX(i[, j][, k]).");
  EXPECT_EQ(errorOf("JOINT(1,0,2)"),
            "model.adm:12:20: error: SFORCE/104: JOINT at column 1 of the expression has 3 "
            "arguments, but JOINT takes 4. Write JOINT(id, jflag, comp, rm).");
  EXPECT_EQ(errorOf("VARVAL(1,2)"),
            "model.adm:12:20: error: SFORCE/104: VARVAL at column 1 of the expression has 2 "
            "arguments, but VARVAL takes 1. Write VARVAL(id).");
  EXPECT_EQ(errorOf("POLY(TIME)"),
            "model.adm:12:20: error: SFORCE/104: POLY at column 1 of the expression has 1 "
            "argument, but POLY takes 3 to 33. Write POLY(x, x0, a0[, a1, ..., a30]).");
}

TEST(ExpressionDiagnostics, UnbalancedParentheses) {
  EXPECT_EQ(errorOf("STEP(TIME,0,0,1,1"),
            "model.adm:12:24: error: SFORCE/104: unbalanced parentheses: '(' at column 5 of "
            "the expression is never closed. Add the missing ')'.");
  EXPECT_EQ(errorOf("(TIME+1))"),
            "model.adm:12:28: error: SFORCE/104: unbalanced parentheses: ')' at column 9 of "
            "the expression has no matching '('. Remove it or add the missing '('.");
}

TEST(ExpressionDiagnostics, BlankBetweenNameAndParenthesis) {
  EXPECT_EQ(errorOf("STEP (TIME,0,0,1,1)"),
            "model.adm:12:24: error: SFORCE/104: blank between STEP and '(' at column 5 of the "
            "expression. ADAMS does not accept a blank between a function name and its '('; "
            "write STEP(...).");
  EXPECT_EQ(errorOf("2*dm  (1,2)"),
            "model.adm:12:24: error: SFORCE/104: blank between DM and '(' at column 5 of the "
            "expression. ADAMS does not accept a blank between a function name and its '('; "
            "write DM(...).");
}

TEST(ExpressionDiagnostics, EmptyExpression) {
  const std::string expected =
      "model.adm:12:20: error: SFORCE/104: the expression is empty. Write a number or a "
      "function expression, e.g. 0.";
  EXPECT_EQ(errorOf(""), expected);
  EXPECT_EQ(errorOf("   "), expected);
}

TEST(ExpressionDiagnostics, HostCallArgumentsMustBeIntegerConstants) {
  EXPECT_EQ(errorOf("DM(1, TIME)"),
            "model.adm:12:26: error: SFORCE/104: DM argument 2 at column 7 of the expression "
            "must be an integer constant. Arguments of DM are ids and flags: write integers, "
            "with 0 as the placeholder for an omitted one.");
  EXPECT_EQ(errorOf("DM(1, 2.5)"),
            "model.adm:12:26: error: SFORCE/104: DM argument 2 at column 7 of the expression "
            "is 2.5, not an integer. Arguments of DM are ids and flags: write integers, with 0 "
            "as the placeholder for an omitted one.");
  EXPECT_EQ(errorOf("VARVAL(PI)"),
            "model.adm:12:27: error: SFORCE/104: VARVAL argument 1 at column 8 of the "
            "expression must be an integer constant. Arguments of VARVAL are ids and flags: "
            "write integers, with 0 as the placeholder for an omitted one.");
  EXPECT_EQ(errorOf("DX(1+1)").substr(0, 80),
            "model.adm:12:23: error: SFORCE/104: DX argument 1 at column 4 of the expression ");
}

TEST(ExpressionDiagnostics, FunctionsStillNotSupported) {
  // AO's definition was not found (docs/expressions.md); DELAY is supported now and its
  // input errors are tested in delay_test.cpp.
  for (const char* name : {"AO", "FXFREQ", "FXMODE"}) {
    const std::string message = errorOf(std::string(name) + "(1, 2)");
    EXPECT_NE(message.find(std::string(name) + " at column 1 of the expression is not "
                                               "supported yet"),
              std::string::npos)
        << message;
  }
}

TEST(ExpressionDiagnostics, VectorMisuse) {
  EXPECT_EQ(errorOf("DXYZ(1,2)"),
            "model.adm:12:20: error: SFORCE/104: the expression is a vector at column 1 of the "
            "expression, but a function must be a scalar. Reduce it to a scalar with MAG(v), a "
            "dot product v*w, or a component function (DX, VX, ...).");
  // UVX is a vector now (a marker axis): alone it is the "vector function" error, and its
  // arguments are marker ids, so a vector or a fraction there is refused at its column.
  EXPECT_EQ(errorOf("UVX(1)").substr(0, 94),
            "model.adm:12:20: error: SFORCE/104: the expression is a vector at column 1 of the "
            "expression, ");
  EXPECT_NE(errorOf("UVX(1)*TRANS(DXYZ(1), [1,0,0])")
                .find("TRANS argument 2 at column 23 of the expression is a vector, but it must "
                      "be a marker id"),
            std::string::npos);
  EXPECT_NE(errorOf("UVY(1.5)*DXYZ(1)").find("UVY argument 1 at column 5"), std::string::npos);
  EXPECT_NE(errorOf("TRANS(1, 2)*DXYZ(1)")
                .find("TRANS argument 1 at column 7 of the expression is a scalar, but TRANS "
                      "takes a vector"),
            std::string::npos);
  EXPECT_NE(errorOf("UVZ(1, 2, 3)*DXYZ(1)").find("UVZ takes 1 to 2"), std::string::npos);
  EXPECT_EQ(errorOf("DX(1)%DX(2)"),
            "model.adm:12:25: error: SFORCE/104: '%' needs a vector on both sides at column 6 of "
            "the expression. '%' is the cross product of two vectors; use '*' for scalars.");
  EXPECT_EQ(errorOf("SIN(DXYZ(1))"),
            "model.adm:12:24: error: SFORCE/104: SIN argument 1 at column 5 of the expression is "
            "a vector, but SIN takes scalars. Pass a scalar: MAG(v), a dot product v*w, or a "
            "component function.");
  EXPECT_EQ(errorOf("MAG(DX(1))").substr(0, 104),
            "model.adm:12:24: error: SFORCE/104: MAG argument 1 at column 5 of the expression is "
            "a scalar, but MAG ta");
  EXPECT_NE(errorOf("MAG(DXYZ(1.5))").find("DXYZ argument 1 at column 10 of the expression is "
                                           "1.5, not an integer"),
            std::string::npos);
  EXPECT_NE(errorOf("1/[1,2,3]").find("'/' by a vector at column 2"), std::string::npos);
  EXPECT_NE(errorOf("[1,2,3]**2").find("'**' with a vector operand"), std::string::npos);
  EXPECT_NE(errorOf("TIME+[1,2,3]").find("'+' between a scalar and a vector"), std::string::npos);
  EXPECT_NE(errorOf("MAG([1,2])").find("expected ','"), std::string::npos);
}

TEST(ExpressionDiagnostics, UserMustBeTheWholeConstantFunction) {
  EXPECT_EQ(errorOf("2*USER(1.05, 0.005)"),
            "model.adm:12:22: error: SFORCE/104: USER at column 3 of the expression must be the "
            "whole function. Write FUNCTION=USER(r1, ..., r30) on its own; the subroutine "
            "computes the value.");
  EXPECT_NE(errorOf("USER(TIME)").find("USER argument 1 at column 6 of the expression must be a "
                                       "constant"),
            std::string::npos);
}

TEST(ExpressionDiagnostics, IfNeedsAColonAfterItsFirstArgument) {
  EXPECT_EQ(errorOf("IF(TIME, 1, 2, 3)"),
            "model.adm:12:27: error: SFORCE/104: IF at column 1 of the expression needs ':' "
            "after its first argument. Write IF(e1 : e2, e3, e4).");
  EXPECT_EQ(errorOf("STEP(TIME:0,0,1,1)"),
            "model.adm:12:29: error: SFORCE/104: ':' at column 10 of the expression is only "
            "allowed after the first argument of IF. Separate arguments with ','.");
  EXPECT_EQ(errorOf("IF(TIME: 1, 2)"),
            "model.adm:12:20: error: SFORCE/104: IF at column 1 of the expression has 3 "
            "arguments, but IF takes 4. Write IF(e1 : e2, e3, e4).");
}

TEST(ExpressionDiagnostics, FunctionsNeedParenthesesAndConstantsTakeNone) {
  EXPECT_EQ(errorOf("STEP + 1"),
            "model.adm:12:20: error: SFORCE/104: STEP at column 1 of the expression needs its "
            "arguments in parentheses. Write STEP(x, x0, h0, x1, h1), with no blank before "
            "'('.");
  EXPECT_EQ(errorOf("PI(2)"),
            "model.adm:12:20: error: SFORCE/104: PI at column 1 of the expression takes no "
            "arguments. Write PI without parentheses.");
  EXPECT_EQ(errorOf("MODE()"),
            "model.adm:12:20: error: SFORCE/104: MODE at column 1 of the expression takes no "
            "arguments. Write MODE without parentheses.");
}

TEST(ExpressionDiagnostics, LexicalErrors) {
  EXPECT_EQ(errorOf("TIME # 2"),
            "model.adm:12:25: error: SFORCE/104: character '#' at column 6 of the expression "
            "is not part of the expression language. Expressions use numbers, names, ( ) , : "
            "and the operators + - * / **.");
  EXPECT_EQ(errorOf("1.0D0 + TIME"),
            "model.adm:12:20: error: SFORCE/104: number '1.0D0' at column 1 of the expression "
            "uses a D exponent, but a trailing D means degrees in ADAMS. Write 1.0E0 for a "
            "power of ten; for an angle in degrees followed by more of the expression, put a "
            "blank after the D.");
  EXPECT_EQ(errorOf("2TIME"),
            "model.adm:12:20: error: SFORCE/104: malformed number '2TIME' at column 1 of the "
            "expression. Write numbers as 1, 1., .5, 1.5E-3 or 90D (degrees), with no blank or "
            "letter inside, and an operator between a number and a name.");
  EXPECT_NE(errorOf("1.E").find("malformed number '1.E' at column 1"), std::string::npos);
}

TEST(ExpressionDiagnostics, MissingOperandsAndOperators) {
  EXPECT_EQ(errorOf("TIME +"),
            "model.adm:12:26: error: SFORCE/104: expected a number, a name or '(' at column 7 "
            "of the expression, found the end of the expression. An operand is missing here.");
  EXPECT_EQ(errorOf("()"),
            "model.adm:12:21: error: SFORCE/104: expected a number, a name or '(' at column 2 "
            "of the expression, found ')'. An operand is missing here.");
  EXPECT_EQ(errorOf("2 TIME"),
            "model.adm:12:22: error: SFORCE/104: expected an operator at column 3 of the "
            "expression, found 'TIME'. Put an operator such as * between two operands; blanks "
            "do not multiply.");
  EXPECT_EQ(errorOf("1, 2"),
            "model.adm:12:21: error: SFORCE/104: ',' at column 2 of the expression is outside "
            "any argument list. Separators belong inside a function's parentheses.");
  EXPECT_EQ(errorOf("STEP(TIME,0,0,1 1)"),
            "model.adm:12:36: error: SFORCE/104: expected ',' or ')' at column 17 of the "
            "expression, found '1'. Separate the arguments of STEP with ','.");
}

TEST(ExpressionDiagnostics, SeveralNameErrorsAreReportedTogether) {
  const std::vector<std::string> all = errorsOf("FOO(1) + DM(1,2,3) + BAR");
  ASSERT_EQ(all.size(), 3u);
  EXPECT_NE(all[0].find("unknown function 'FOO' at column 1"), std::string::npos);
  EXPECT_NE(all[1].find("DM at column 10"), std::string::npos);
  EXPECT_NE(all[2].find("unknown name 'BAR' at column 22"), std::string::npos);
}

TEST(ExpressionDiagnostics, UnknownFileColumnLeavesTheColumnUnset) {
  Diagnostics diags;
  Expression e;
  EXPECT_FALSE(Expression::parse("FOO(1)", {"model.adm", 12, 0}, "VARIABLE/3", diags, e));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].where.column, 0);
  EXPECT_EQ(format(diags.all()[0]),
            "model.adm:12: error: VARIABLE/3: unknown function 'FOO' at column 1 of the "
            "expression. See docs/expressions.md for the functions available.");
}

TEST(ExpressionDiagnostics, AFailedParseLeavesTheOutputUnchanged) {
  Diagnostics diags;
  Expression e;
  ASSERT_TRUE(Expression::parse("TIME", {}, "", diags, e));
  EXPECT_FALSE(Expression::parse("TIME +", {}, "", diags, e));
  EXPECT_EQ(e.text(), "TIME");
}

}  // namespace
}  // namespace openmss::expr
