#include "model/data_element_builder.hpp"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/curve_routine.hpp"
#include "user/spline_reader.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// Index of the first value that is not above its predecessor, or -1.
int firstNotIncreasing(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (!(v[i] > v[i - 1])) return static_cast<int>(i);
  }
  return -1;
}

// SPLINE/id, FILE=, BLOCK=, ROUTINE=: the user's SPLINE_READ reads the file (docs/user-
// subroutines.md); its values are checked as X= and Y= are.
void buildUserSpline(const Statement& s, Model& model, Diagnostics& diags) {
  const Argument* file = s.find("FILE");
  const Argument* block = s.find("BLOCK");
  user::ElementData e;
  e.subject = s.subject();
  e.id = s.id ? *s.id : 0;
  e.data = userModelData(model);
  user::SplineValues v;
  std::string error;
  const std::string fileName = file->values.empty() ? "" : file->values[0].text;
  if (!user::readUserSpline(e, fileName,
                            block && !block->values.empty() ? block->values[0].text : "",
                            elementRoutineName(s), userLibraryDirectory(model), v, error)) {
    diags.error(file->where, s.subject(), error,
                "Supply the library that defines SPLINE_READ (ROUTINE=lib::name, or openmss run "
                "--user-library LIB), or list the values with X= and Y=.");
    return;
  }
  std::string problem;
  if (v.x.size() < 4)
    problem =
        "SPLINE_READ stored " + std::to_string(v.x.size()) + " x values; a SPLINE needs at least 4";
  else if (firstNotIncreasing(v.x) >= 0)
    problem = "SPLINE_READ stored x values that do not increase strictly (value " +
              std::to_string(firstNotIncreasing(v.x) + 1) + ")";
  else if (firstNotIncreasing(v.z) >= 0)
    problem = "SPLINE_READ stored z values that do not increase";
  if (!problem.empty()) {
    diags.error(file->where, s.subject(), problem, "Correct the file or the reader.");
    return;
  }
  if (!s.id || model.splineIndex.count(*s.id)) return;
  SplineData data;
  data.id = *s.id;
  data.where = s.where;
  data.spline =
      std::make_shared<const Spline>(v.x, std::move(v.z), v.curves, s.has("LINEAR_EXTRAPOLATE"));
  model.splineIndex[data.id] = static_cast<int>(model.splines.size());
  model.splines.push_back(std::move(data));
}

void buildSpline(const Statement& s, Model& model, Diagnostics& diags) {
  if (s.has("FILE") && (s.has("ROUTINE") || !user::defaultLibrary().empty())) {
    buildUserSpline(s, model, diags);
    return;
  }
  if (s.has("FILE")) {
    diags.error(s.find("FILE")->where, s.subject(),
                "SPLINE data from a FILE (BLOCK, CHANNEL) is not supported yet without a "
                "SPLINE_READ reader",
                "List the values in the data set with X=x1,...,xn and Y=y1,...,yn, or give "
                "ROUTINE=lib::name for a user SPLINE_READ that reads the file.");
    return;
  }
  const Argument* xArg = s.find("X");
  std::vector<const Argument*> yArgs;
  for (const Argument& a : s.args) {
    if (a.name == "Y") yArgs.push_back(&a);
  }
  if (xArg == nullptr || yArgs.empty()) {
    diags.error(s.where, s.subject(), "a SPLINE needs X= and Y= values",
                "Write SPLINE/id, X=x1,...,xn, Y=y1,...,yn (n >= 4).");
    return;
  }
  const auto x = StatementArguments(s, diags).numbers(*xArg);
  if (!x) return;
  bool ok = true;
  if (x->size() < 4) {
    diags.error(xArg->where, s.subject(),
                "X has " + std::to_string(x->size()) + " values, a SPLINE needs at least 4",
                "Add points: the interpolation methods need four or more.");
    ok = false;
  } else if (const int bad = firstNotIncreasing(*x); bad >= 0) {
    diags.error(xArg->where, s.subject(),
                "X must increase strictly, but value " + std::to_string(bad + 1) + " (" +
                    xArg->values[static_cast<std::size_t>(bad)].text +
                    ") is not above the one before it",
                "Sort the points by X and remove repeated X values.");
    ok = false;
  }
  const std::size_t n = x->size();
  std::vector<double> z;
  std::vector<std::vector<double>> curves;
  for (const Argument* yArg : yArgs) {
    auto y = StatementArguments(s, diags).numbers(*yArg);
    if (!y) {
      ok = false;
      continue;
    }
    if (yArgs.size() == 1 && y->size() == n) {
      z.push_back(0.0);
      curves.push_back(std::move(*y));
    } else if (y->size() == n + 1) {
      z.push_back(y->front());
      curves.emplace_back(y->begin() + 1, y->end());
    } else {
      diags.error(yArg->where, s.subject(),
                  "Y has " + std::to_string(y->size()) + " values, but X has " + std::to_string(n) +
                      " (a curve of a family has " + std::to_string(n + 1) + ": its z first)",
                  "Give one y per x: Y=y1,...,yn for one curve, or Y=z,y1,...,yn for each "
                  "curve of a family.");
      ok = false;
    }
  }
  if (ok && firstNotIncreasing(z) >= 0) {
    diags.error(yArgs[static_cast<std::size_t>(firstNotIncreasing(z))]->where, s.subject(),
                "the z values of a family of curves (first value of each Y) must increase",
                "Order the Y= arguments by increasing z.");
    ok = false;
  }
  if (!ok || !s.id) return;
  if (model.splineIndex.count(*s.id)) return;  // the reader already warned about duplicates
  SplineData data;
  data.id = *s.id;
  data.where = s.where;
  data.spline =
      std::make_shared<const Spline>(*x, std::move(z), curves, s.has("LINEAR_EXTRAPOLATE"));
  model.splineIndex[data.id] = static_cast<int>(model.splines.size());
  model.splines.push_back(std::move(data));
}

void buildMatrix(const Statement& s, Model& model, Diagnostics& diags) {
  if (s.has("FILE") || s.has("NAME")) {
    diags.error(s.find(s.has("FILE") ? "FILE" : "NAME")->where, s.subject(),
                "MATRIX data from a FILE is not supported yet",
                "List the entries with FULL=RORDER, ROWS=, COLUMNS=, VALUES=.");
    return;
  }
  const auto rows = StatementArguments(s, diags).integer("ROWS");
  const auto columns = StatementArguments(s, diags).integer("COLUMNS");
  const Argument* valuesArg = s.find("VALUES");
  const Argument* full = s.find("FULL");
  const bool sparse = s.has("SPARSE");
  if (!rows || !columns || valuesArg == nullptr || (full == nullptr) == !sparse) {
    diags.error(s.where, s.subject(),
                "a MATRIX needs ROWS=, COLUMNS=, VALUES= and exactly one of FULL= and SPARSE",
                "Write MATRIX/id, FULL=RORDER, ROWS=m, COLUMNS=n, VALUES=... (m*n values), or "
                "MATRIX/id, SPARSE, ROWS=m, COLUMNS=n, I=..., J=..., VALUES=....");
    return;
  }
  const auto values = StatementArguments(s, diags).numbers(*valuesArg);
  if (!values) return;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(*rows, *columns);
  if (full != nullptr) {
    const bool byRows = !full->values.empty() && full->values[0].text == "RORDER";
    if (values->size() != static_cast<std::size_t>(*rows * *columns)) {
      diags.error(valuesArg->where, s.subject(),
                  "VALUES has " + std::to_string(values->size()) +
                      " numbers, but ROWS*COLUMNS = " + std::to_string(*rows * *columns),
                  "Give every entry of the matrix.");
      return;
    }
    for (long i = 0; i < *rows; ++i) {
      for (long j = 0; j < *columns; ++j) {
        m(i, j) = (*values)[static_cast<std::size_t>(byRows ? i * *columns + j : j * *rows + i)];
      }
    }
  } else {
    const Argument* iArg = s.find("I");
    const Argument* jArg = s.find("J");
    if (iArg == nullptr || jArg == nullptr || iArg->values.size() != values->size() ||
        jArg->values.size() != values->size()) {
      diags.error(valuesArg->where, s.subject(),
                  "a SPARSE matrix needs I=, J= and VALUES= with the same number of entries",
                  "Give the row, column and value of every non-zero entry.");
      return;
    }
    for (std::size_t k = 0; k < values->size(); ++k) {
      const double i = iArg->values[k].number;
      const double j = jArg->values[k].number;
      if (i < 1 || i > static_cast<double>(*rows) || j < 1 || j > static_cast<double>(*columns) ||
          i != std::floor(i) || j != std::floor(j)) {
        diags.error(iArg->where, s.subject(),
                    "entry " + std::to_string(k + 1) + " (I=" + iArg->values[k].text +
                        ", J=" + jArg->values[k].text + ") is outside the " +
                        std::to_string(*rows) + "x" + std::to_string(*columns) + " matrix",
                    "Rows and columns count from 1.");
        return;
      }
      m(static_cast<long>(i) - 1, static_cast<long>(j) - 1) = (*values)[k];
    }
  }
  if (!s.id || model.matrixIndex.count(*s.id)) return;
  model.matrixIndex[*s.id] = static_cast<int>(model.matrices.size());
  model.matrices.push_back({*s.id, std::move(m), s.where});
}

// CURVE/id, FUNCTION=USER(...): CURSUB gives the curve over MINPAR..MAXPAR (default -1..1).
void buildUserCurve(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  bool ok = true;
  for (const char* name : {"MATRIX", "CURVE_POINTS"})
    if (const Argument* arg = s.find(name)) {
      diags.error(arg->where, s.subject(),
                  std::string(name) + " with FUNCTION=USER(...): CURSUB gives the whole curve",
                  std::string("Remove ") + name + ", or FUNCTION to use the matrix.");
      ok = false;
    }
  user::CurveShape shape;
  shape.closed = s.has("CLOSED");
  if (s.has("ORDER"))
    if (auto o = a.integer("ORDER")) shape.order = static_cast<int>(*o);
  if (s.has("MINPAR"))
    if (auto v = a.real("MINPAR")) shape.minPar = *v;
  if (s.has("MAXPAR"))
    if (auto v = a.real("MAXPAR")) shape.maxPar = *v;
  if (!(shape.maxPar > shape.minPar)) {
    diags.error(s.where, s.subject(), "MAXPAR must be greater than MINPAR",
                "Give the parameter range of the curve CURSUB computes, MINPAR < MAXPAR.");
    ok = false;
  }
  const auto par = userParameters(s, diags);
  if (!par || !ok || !s.id || model.curveIndex.count(*s.id)) return;
  user::ElementData e;
  e.subject = s.subject();
  e.id = *s.id;
  e.par = *par;
  e.data = userModelData(model);
  std::string error;
  CurveData data;
  data.id = *s.id;
  data.where = s.where;
  data.curve =
      user::loadCurveRoutine(e, shape, elementRoutineName(s), userLibraryDirectory(model), error);
  if (!data.curve) {
    diags.error(s.find("FUNCTION")->where, s.subject(), error,
                "Supply the library that defines CURSUB (ROUTINE=lib::name on the statement, or "
                "openmss run --user-library LIB); docs/user-subroutines.md says how to build one.");
    return;
  }
  model.curveIndex[data.id] = static_cast<int>(model.curves.size());
  model.curves.push_back(std::move(data));
}

// After the matrices: a CURVE refers to one.
void buildCurve(const Statement& s, Model& model, Diagnostics& diags) {
  if (s.has("FUNCTION")) {
    buildUserCurve(s, model, diags);
    return;
  }
  const auto matrixId = StatementArguments(s, diags).integer("MATRIX");
  if (!matrixId) {
    if (!s.has("MATRIX")) {
      diags.error(s.where, s.subject(), "a CURVE needs MATRIX=id",
                  "Give the id of a MATRIX with one row (x, y, z) per point.");
    }
    return;
  }
  for (const char* name : {"MINPAR", "MAXPAR"}) {
    if (s.has(name)) {
      diags.warning(
          s.find(name)->where, s.subject(),
          std::string(name) + " has no effect on a MATRIX curve: its parameter runs from -1 to 1",
          std::string("Remove ") + name + ".");
    }
  }
  const auto found = model.matrixIndex.find(*matrixId);
  if (found == model.matrixIndex.end()) {
    diags.error(s.find("MATRIX")->where, s.subject(),
                "MATRIX/" + std::to_string(*matrixId) + " does not exist",
                "Use the id of a MATRIX statement of this data set.");
    return;
  }
  const Eigen::MatrixXd& m = model.matrices[static_cast<std::size_t>(found->second)].values;
  if (m.cols() != 3) {
    diags.error(s.find("MATRIX")->where, s.subject(),
                "MATRIX/" + std::to_string(*matrixId) + " has " + std::to_string(m.cols()) +
                    " columns; a CURVE needs 3 (x, y, z of each point)",
                "Give the points as rows x, y, z (z = 0 for a planar curve).");
    return;
  }
  long order = 4;
  if (s.has("ORDER")) {
    const auto o = StatementArguments(s, diags).integer("ORDER");
    if (!o) return;
    order = *o;
  }
  const bool closed = s.has("CLOSED");
  std::vector<std::array<double, 3>> points;
  for (Eigen::Index i = 0; i < m.rows(); ++i) points.push_back({m(i, 0), m(i, 1), m(i, 2)});
  const std::string problem = BSplineCurve::check(points, static_cast<int>(order), closed);
  if (!problem.empty()) {
    diags.error(s.where, s.subject(), problem,
                "Change ORDER, the MATRIX rows or CLOSED so that they agree.");
    return;
  }
  if (!s.id || model.curveIndex.count(*s.id)) return;
  CurveData data;
  data.id = *s.id;
  data.matrixId = *matrixId;
  data.where = s.where;
  data.curve = std::make_shared<const BSplineCurve>(points, static_cast<int>(order), closed,
                                                    s.has("CURVE_POINTS"));
  model.curveIndex[data.id] = static_cast<int>(model.curves.size());
  model.curves.push_back(std::move(data));
}

void buildString(const Statement& s, Model& model) {
  const Argument* a = s.find("STRING");
  if (!s.id || model.stringIndex.count(*s.id)) return;
  StringData data;
  data.id = *s.id;
  data.where = s.where;
  if (a != nullptr && !a->values.empty()) data.text = a->values[0].text;
  model.stringIndex[data.id] = static_cast<int>(model.strings.size());
  model.strings.push_back(std::move(data));
}

}  // namespace

bool isDataElementStatement(const std::string& name) {
  return name == "SPLINE" || name == "CURVE" || name == "MATRIX" || name == "STRING";
}

void buildDataElements(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  for (const Statement& s : dataset.statements) {
    if (s.name == "SPLINE") buildSpline(s, model, diags);
    if (s.name == "MATRIX") buildMatrix(s, model, diags);
    if (s.name == "STRING") buildString(s, model);
  }
  for (const Statement& s : dataset.statements) {
    if (s.name == "CURVE") buildCurve(s, model, diags);
  }
}

bool bindDataCalls(const Model& model, expr::Expression& expression, const SourceLocation& where,
                   const std::string& subject, Diagnostics& diags) {
  bool ok = true;
  const std::vector<expr::DataCall>& calls = expression.dataCalls();
  for (std::size_t k = 0; k < calls.size(); ++k) {
    const expr::DataCall& call = calls[k];
    const bool isCurve = call.name == "CURVE";
    const std::map<long, int>& index = isCurve ? model.curveIndex : model.splineIndex;
    const auto found = index.find(call.id);
    if (found == index.end()) {
      SourceLocation at = where;
      if (call.column > 0 && where.column > 0) at.column = where.column + call.column - 1;
      const std::string kind = isCurve ? "CURVE" : "SPLINE";
      diags.error(at, subject,
                  call.name + ": " + kind + "/" + std::to_string(call.id) + " does not exist",
                  "Use the id of a " + kind + " statement of this data set.");
      ok = false;
      continue;
    }
    const auto i = static_cast<std::size_t>(found->second);
    if (isCurve) {
      expression.bindCurve(k, model.curves[i].curve);
    } else {
      expression.bindSpline(k, model.splines[i].spline);
    }
  }
  return ok;
}

}  // namespace openmss::model
