// The function-call rules of the expression parser (expr/parser_detail.hpp): builtins, host
// measures, data functions (CUBSPL, AKISPL, CURVE, INTERP, PSD), vector functions, USER and
// DELAY calls, with their argument-count and argument-kind checks.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include "expr/compiler.hpp"
#include "expr/lexer.hpp"
#include "expr/name_catalog.hpp"
#include "expr/parser_detail.hpp"

namespace openmss::expr::parsing {

Value Parser::call(const Token& nameToken, const NameInfo* info) {
  const bool isIf = info != nullptr && info->kind == NameKind::Conditional;
  std::vector<Argument> args = arguments(nameToken, isIf);
  SyntaxNode node;
  node.column = nameToken.column;
  if (!ok_) return scalarValue(std::move(node));
  if (info == nullptr) {
    const std::string near = suggestion(nameToken.upper, true);
    report(nameToken.column,
           "unknown function '" + nameToken.upper + "' " + atColumn(nameToken.column),
           near.empty() ? "See docs/expressions.md for the functions available."
                        : "Did you mean " + near + "?");
    return scalarValue(std::move(node));
  }
  if (info->kind == NameKind::VectorFunction) return vectorFunction(nameToken, *info, args);
  if (!scalarArguments(nameToken, args)) return scalarValue(std::move(node));
  switch (info->kind) {
    case NameKind::Builtin:
    case NameKind::Conditional:
      if (!checkCount(nameToken, *info, args.size())) break;
      node.kind = isIf ? NodeKind::If : NodeKind::Call;
      node.builtin = info->builtin;
      for (Argument& arg : args) node.children.push_back(std::move(arg.node));
      break;
    case NameKind::HostFunction:
      return scalarValue(hostCall(nameToken, *info, args));
    case NameKind::VectorHost:
      return vectorHost(nameToken, *info, args);
    case NameKind::DataFunction:
      return scalarValue(dataCall(nameToken, *info, args));
    case NameKind::User:
      return scalarValue(userCall(nameToken, *info, args));
    case NameKind::Delay:
      return scalarValue(delayCall(nameToken, *info, args));
    case NameKind::Unsupported:
      report(nameToken.column,
             nameToken.upper + " " + atColumn(nameToken.column) + " is not supported yet",
             "This function is not available to expressions yet; see "
             "docs/expressions.md for the functions available.");
      break;
    default:
      report(nameToken.column,
             nameToken.upper + " " + atColumn(nameToken.column) + " takes no arguments",
             "Write " + nameToken.upper + " without parentheses.");
      break;
  }
  return scalarValue(std::move(node));
}

// DXYZ(i[, j][, k]) = [DX(...), DY(...), DZ(...)], and likewise VXYZ, WXYZ, ACCXYZ, WDTXYZ,
// FXYZ, TXYZ: three host calls with the same arguments.
Value Parser::vectorHost(const Token& nameToken, const NameInfo& info,
                         std::vector<Argument>& args) {
  // A refused call still yields a (placeholder) vector, so MAG(DXYZ(1.5)) reports the id
  // only, not also "MAG of a scalar".
  Value out;
  out.isVector = true;
  if (!checkCount(nameToken, info, args.size())) return out;
  bool valid = true;  // check the ids once, under the name as written
  for (std::size_t k = 0; k < args.size(); ++k) {
    long id = 0;
    if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], id)) valid = false;
  }
  if (!valid) return out;
  const std::string stem = nameToken.upper.substr(0, nameToken.upper.size() - 3);
  const char* axes[3] = {"X", "Y", "Z"};
  for (int k = 0; k < 3; ++k) {
    Token component = nameToken;
    component.upper = stem + axes[k];
    const NameInfo* scalar = findName(component.upper);
    out.parts[k] = hostCall(component, *scalar, args);
  }
  return out;
}

// ORIENT(29, n, i[, j]): element n of the direction-cosine matrix R = A_jᵀ A_i, numbered
// down the columns, so elements 3c+1..3c+3 are axis c of marker i resolved in marker j.
// `ids` holds i and, when written, j; the call keeps the column of the function name.
SyntaxNode Parser::directionCosine(const Token& nameToken, int element,
                                   const std::vector<long>& ids) {
  HostCall cosine{"ORIENT", {29, element}, nameToken.column};
  cosine.args.insert(cosine.args.end(), ids.begin(), ids.end());
  SyntaxNode node;
  node.column = nameToken.column;
  node.kind = NodeKind::Host;
  node.hostIndex = hostIndex(std::move(cosine));
  return node;
}

// The marker ids of UVX/UVY/UVZ(i[, k]) (from argument `first` on) or TRANS(v, i[, j]).
bool Parser::markerIds(const Token& nameToken, std::vector<Argument>& args, std::size_t first,
                       std::vector<long>& ids) {
  bool valid = true;
  for (std::size_t k = first; k < args.size(); ++k) {
    long id = 0;
    if (args[k].isVector) {
      report(args[k].column,
             nameToken.upper + " argument " + std::to_string(k + 1) + " " +
                 atColumn(args[k].column) + " is a vector, but it must be a marker id",
             "Write " + std::string(findName(nameToken.upper)->usage) + ".");
      valid = false;
    } else if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], id)) {
      valid = false;
    } else {
      ids.push_back(id);
    }
  }
  return valid;
}

// UVX(i[, k]) = the x axis of marker i resolved in marker k (ground when k is omitted or 0);
// UVY and UVZ likewise (ADAMS Solver C++ help, UVX). Three direction cosines.
Value Parser::markerAxis(const Token& nameToken, std::vector<Argument>& args) {
  Value out;
  out.isVector = true;
  std::vector<long> ids;
  if (!markerIds(nameToken, args, 0, ids)) return out;
  const int axis = nameToken.upper[2] - 'X';
  for (int k = 0; k < 3; ++k) out.parts[k] = directionCosine(nameToken, 3 * axis + k + 1, ids);
  return out;
}

// TRANS(v, i[, j]): v, written in the axes of marker j (ground when omitted or 0), resolved
// in the axes of marker i (ADAMS Solver C++ help, TRANS). Component c is UV{X,Y,Z}(i, j) * v.
Value Parser::transform(const Token& nameToken, std::vector<Argument>& args) {
  Value out;
  out.isVector = true;
  std::vector<long> ids;
  if (!markerIds(nameToken, args, 1, ids)) return out;
  for (int c = 0; c < 3; ++c) {
    std::array<SyntaxNode, 3> axis;
    for (int k = 0; k < 3; ++k) axis[k] = directionCosine(nameToken, 3 * c + k + 1, ids);
    out.parts[c] = dotProduct(axis, args[0].parts, nameToken.column);
  }
  return out;
}

// MAG(v) = |v|; UV(v) = v / |v|, and the zero vector where v is zero (no direction: ADAMS
// reuses the last valid one, docs/expressions.md); UVX/UVY/UVZ and TRANS above.
Value Parser::vectorFunction(const Token& nameToken, const NameInfo& info,
                             std::vector<Argument>& args) {
  // A refused call still yields a placeholder of its kind (a vector except for MAG), so
  // the error is reported once, not again as a vector/scalar mismatch around it.
  Value refused;
  refused.isVector = nameToken.upper != "MAG";
  if (!checkCount(nameToken, info, args.size())) return refused;
  if (nameToken.upper.size() == 3 && nameToken.upper.starts_with("UV")) {
    return markerAxis(nameToken, args);
  }
  if (!args[0].isVector) {
    report(args[0].column,
           nameToken.upper + " argument 1 " + atColumn(args[0].column) + " is a scalar, but " +
               nameToken.upper + " takes a vector",
           "Pass a vector such as DXYZ(i, j) or [a, b, c]; for a scalar use ABS.");
    return refused;
  }
  if (nameToken.upper == "TRANS") return transform(nameToken, args);
  SyntaxNode length = magnitude(args[0].parts, nameToken.column);
  if (nameToken.upper == "MAG") return scalarValue(std::move(length));
  // IF(v*v : -, 0, v_k/|v|): v*v is never negative; the branch taken alone gives the value
  // and the derivative, so the zero vector yields 0 with zero partials rather than 0/0.
  const SyntaxNode lengthSquared = dotProduct(args[0].parts, args[0].parts, nameToken.column);
  Value out;
  out.isVector = true;
  for (int k = 0; k < 3; ++k) {
    SyntaxNode zero = numberNode(0.0, nameToken.column);
    out.parts[k] = makeNode(NodeKind::If, nameToken.column,
                            {lengthSquared, zero, zero,
                             binary(NodeKind::Divide, nameToken.column, args[0].parts[k], length)});
  }
  return out;
}

// USER(r1, ..., r30): the constants handed to a user subroutine. It must be the whole
// expression, as in ADAMS (FUNCTION=USER(...)). Its value comes from the subroutine, so the
// node itself is a NaN placeholder; the model builder refuses an expression with a USER call
// until a subroutine is loaded for it.
SyntaxNode Parser::userCall(const Token& nameToken, const NameInfo& info,
                            std::vector<Argument>& args) {
  SyntaxNode node = numberNode(std::numeric_limits<double>::quiet_NaN(), nameToken.column);
  if (!checkCount(nameToken, info, args.size())) return node;
  if (tokens_.front().column != nameToken.column || current().kind != TokenKind::End) {
    report(nameToken.column, "USER " + atColumn(nameToken.column) + " must be the whole function",
           "Write FUNCTION=USER(r1, ..., r30) on its own; the subroutine computes the value.");
    return node;
  }
  UserCall user;
  user.column = nameToken.column;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!constantTree(args[k].node)) {
      report(args[k].column,
             "USER argument " + std::to_string(k + 1) + " " + atColumn(args[k].column) +
                 " must be a constant",
             "USER passes constants to the subroutine; the subroutine reads the state "
             "itself.");
      continue;
    }
    user.arguments.push_back(foldConstant(args[k].node));
  }
  user_ = std::move(user);
  return node;
}

// Host-call arguments are ids and flags: integer constants, optionally signed.
SyntaxNode Parser::hostCall(const Token& nameToken, const NameInfo& info,
                            std::vector<Argument>& args) {
  SyntaxNode node;
  node.column = nameToken.column;
  if (!checkCount(nameToken, info, args.size())) return node;
  HostCall hostCall{nameToken.upper, {}, nameToken.column};
  bool valid = true;
  for (std::size_t k = 0; k < args.size(); ++k) {
    long integer = 0;
    if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], integer)) {
      valid = false;
      continue;
    }
    hostCall.args.push_back(integer);
  }
  if (!valid) return node;
  node.kind = NodeKind::Host;
  node.hostIndex = hostIndex(std::move(hostCall));
  return node;
}

// AKISPL(x, z, id[, iord]), CUBSPL(x, z, id[, iord]), CURVE(alpha, iord, comp, id): x, z and
// alpha are expressions; id, iord and comp are integer constants, checked for range here.
// The id is resolved against the model's data later (Expression::bindSpline/bindCurve).
SyntaxNode Parser::dataCall(const Token& nameToken, const NameInfo& info,
                            std::vector<Argument>& args) {
  SyntaxNode node;
  node.column = nameToken.column;
  if (!checkCount(nameToken, info, args.size())) return node;
  if (nameToken.upper == "INTERP") return interpCall(nameToken, args);
  if (nameToken.upper == "INVPSD") return psdCall(nameToken, args);
  const bool isCurve = nameToken.upper == "CURVE";
  DataCall call{nameToken.upper, 0, 0, 0, nameToken.column, {}};
  const std::vector<std::size_t> integers =
      isCurve ? std::vector<std::size_t>{1, 2, 3} : std::vector<std::size_t>{2, 3};
  bool valid = true;
  long values[4] = {0, 0, 0, 0};
  for (std::size_t k : integers) {
    if (k >= args.size()) continue;
    if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], values[k])) {
      valid = false;
    }
  }
  if (!valid) return node;
  const std::size_t orderAt = isCurve ? 1 : 3;
  call.id = values[isCurve ? 3 : 2];
  call.order = static_cast<int>(values[orderAt]);
  if (call.order < 0 || call.order > 2) {
    report(args[orderAt].column,
           nameToken.upper + " argument " + std::to_string(orderAt + 1) + " " +
               atColumn(args[orderAt].column) + " (iord) is " + std::to_string(values[orderAt]) +
               ", but it must be 0, 1 or 2",
           "Write 0 for the value, 1 or 2 for the first or second derivative.");
    valid = false;
  }
  if (isCurve) {
    call.component = static_cast<int>(values[2]);
    if (call.component < 1 || call.component > 3) {
      report(args[2].column,
             "CURVE argument 3 " + atColumn(args[2].column) + " (comp) is " +
                 std::to_string(values[2]) + ", but it must be 1, 2 or 3",
             "Write 1, 2 or 3 for the x, y or z component.");
      valid = false;
    }
  }
  if (call.id <= 0) {
    const std::size_t at = isCurve ? 3 : 2;
    report(args[at].column,
           nameToken.upper + " argument " + std::to_string(at + 1) + " " +
               atColumn(args[at].column) + " must be the id of a " +
               (isCurve ? "CURVE" : "SPLINE") + " statement",
           "Write the positive id of the data element.");
    valid = false;
  }
  if (!valid) return node;
  node.kind = NodeKind::DataCall;
  node.children.push_back(std::move(args[0].node));
  if (!isCurve) node.children.push_back(std::move(args[1].node));
  node.dataIndex = dataCalls_.size();
  dataCalls_.push_back(std::move(call));
  return node;
}

SyntaxNode Parser::finishDataCall(DataCall call, SyntaxNode x) {
  SyntaxNode node = makeNode(NodeKind::DataCall, call.column, {std::move(x)});
  node.dataIndex = dataCalls_.size();
  dataCalls_.push_back(std::move(call));
  return node;
}

bool Parser::positiveId(const std::string& function, std::size_t k, const Argument& arg, long id) {
  if (id > 0) return true;
  report(arg.column,
         function + " argument " + std::to_string(k + 1) + " " + atColumn(arg.column) +
             " must be the id of a SPLINE statement",
         "Write the positive id of the data element.");
  return false;
}

// INTERP(x, degree, id[, iord]): a time-series SPLINE read linearly (degree 1) or with a
// cubic spline (degree 3).
SyntaxNode Parser::interpCall(const Token& nameToken, std::vector<Argument>& args) {
  long values[4] = {0, 0, 0, 0};
  bool valid = true;
  for (std::size_t k = 1; k < args.size(); ++k) {
    if (!integerConstant("INTERP", static_cast<int>(k) + 1, args[k], values[k])) valid = false;
  }
  if (!valid) return SyntaxNode{};
  if (values[1] != 1 && values[1] != 3) {
    report(args[1].column,
           "INTERP argument 2 " + atColumn(args[1].column) + " (degree) is " +
               std::to_string(values[1]) + ", but it must be 1 or 3",
           "Write 1 for linear or 3 for cubic interpolation.");
    valid = false;
  }
  if (values[3] < 0 || values[3] > 2) {
    report(args[3].column,
           "INTERP argument 4 " + atColumn(args[3].column) + " (iord) is " +
               std::to_string(values[3]) + ", but it must be 0, 1 or 2",
           "Write 0 for the value, 1 or 2 for the first or second derivative.");
    valid = false;
  }
  if (!positiveId("INTERP", 2, args[2], values[2]) || !valid) return SyntaxNode{};
  DataCall call{"INTERP", values[2],        static_cast<int>(values[3]),
                0,        nameToken.column, {static_cast<double>(values[1])}};
  return finishDataCall(std::move(call), std::move(args[0].node));
}

// INVPSD(x, id, f0, f1, nf, linlog, seed): id, nf and linlog are integers; f0, f1 and seed
// are constants.
SyntaxNode Parser::psdCall(const Token& nameToken, std::vector<Argument>& args) {
  bool valid = true;
  long id = 0, count = 0, logarithmic = 0;
  if (!integerConstant("INVPSD", 2, args[1], id)) valid = false;
  if (!integerConstant("INVPSD", 5, args[4], count)) valid = false;
  if (!integerConstant("INVPSD", 6, args[5], logarithmic)) valid = false;
  double reals[3] = {0.0, 0.0, 0.0};
  const std::size_t realAt[3] = {2, 3, 6};
  for (int r = 0; r < 3; ++r) {
    const Argument& arg = args[realAt[r]];
    if (!constantTree(arg.node)) {
      report(arg.column,
             "INVPSD argument " + std::to_string(realAt[r] + 1) + " " + atColumn(arg.column) +
                 " must be a constant",
             "f0, f1 and seed are numbers fixed for the run.");
      valid = false;
      continue;
    }
    reals[r] = foldConstant(arg.node);
  }
  if (!valid) return SyntaxNode{};
  if (count < 2) {
    report(args[4].column,
           "INVPSD argument 5 " + atColumn(args[4].column) + " (nf) is " + std::to_string(count) +
               ", but at least 2 frequencies are needed",
           "Give the number of frequencies between f0 and f1, 2 or more.");
    valid = false;
  }
  if (logarithmic != 0 && logarithmic != 1) {
    report(args[5].column,
           "INVPSD argument 6 " + atColumn(args[5].column) + " (linlog) is " +
               std::to_string(logarithmic) + ", but it must be 0 or 1",
           "Write 0 to read the PSD linearly or 1 to read it in the logarithmic domain.");
    valid = false;
  }
  if (!(reals[0] >= 0.0 && reals[1] > reals[0])) {
    report(args[2].column,
           "INVPSD frequencies " + atColumn(args[2].column) + " must satisfy 0 <= f0 < f1",
           "Give the lowest and the highest frequency to regenerate, in increasing order.");
    valid = false;
  }
  if (!positiveId("INVPSD", 1, args[1], id) || !valid) return SyntaxNode{};
  DataCall call{
      "INVPSD",
      id,
      0,
      0,
      nameToken.column,
      {reals[0], reals[1], static_cast<double>(count), static_cast<double>(logarithmic), reals[2]}};
  return finishDataCall(std::move(call), std::move(args[0].node));
}

// DELAY(e_delayed, e_delay, e_history[, id]): e_delayed at TIME - max(0, e_delay), read from
// the history the run records; e_history gives the values before the run's start and must
// be a function of TIME alone. The id of an interpolation-options ARRAY is not supported:
// only 0 (the default) is accepted. DELAY inside a DELAY argument is refused (its history
// would need a history of its own).
SyntaxNode Parser::delayCall(const Token& nameToken, const NameInfo& info,
                             std::vector<Argument>& args) {
  if (!checkCount(nameToken, info, args.size())) return SyntaxNode{};
  bool valid = true;
  if (args.size() == 4) {
    long id = 0;
    if (!integerConstant("DELAY", 4, args[3], id)) {
      valid = false;
    } else if (id != 0) {
      report(args[3].column,
             "DELAY argument 4 " + atColumn(args[3].column) + " names ARRAY/" + std::to_string(id) +
                 " of interpolation options, which is not supported yet",
             "Give 0 or omit the argument: OpenMSS interpolates the history with cubics "
             "(docs/expressions.md, \"DELAY\").");
      valid = false;
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    if (!containsKind(args[k].node, NodeKind::Delay)) continue;
    report(args[k].column,
           "DELAY argument " + std::to_string(k + 1) + " " + atColumn(args[k].column) +
               " contains another DELAY, which is not supported",
           "Delay a VARIABLE that holds the inner DELAY instead.");
    valid = false;
  }
  if (containsKind(args[2].node, NodeKind::Host) ||
      containsKind(args[2].node, NodeKind::DataCall)) {
    report(args[2].column,
           "DELAY argument 3 " + atColumn(args[2].column) +
               " (the history before the start) must be a function of TIME or a constant",
           "Write the history with TIME, numbers and the general functions (STEP, SIN, ...), "
           "without measures or SPLINE data.");
    valid = false;
  }
  if (!valid) return SyntaxNode{};
  SyntaxNode node =
      makeNode(NodeKind::Delay, nameToken.column,
               {std::move(args[0].node), std::move(args[1].node), std::move(args[2].node)});
  node.delayIndex = delayCount_++;
  return node;
}

}  // namespace openmss::expr::parsing
