#include "model/user_equation_builder.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "model/model_builder.hpp"
#include "model/user_subroutine_arguments.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// The numbers of an argument (the reader checked that they are numbers).
std::vector<double> numbersOf(const Argument& a) {
  std::vector<double> out;
  for (const auto& v : a.values) out.push_back(v.number);
  return out;
}

// A positive integer argument (id or count), or nullopt with a diagnostic.
std::optional<long> positiveInteger(const Statement& s, const char* name, Diagnostics& diags,
                                    bool allowZero = false) {
  const Argument* a = s.find(name);
  if (!a) return std::nullopt;
  if (a->values.size() != 1 || a->values[0].kind != language::Value::Kind::Number ||
      a->values[0].number != std::floor(a->values[0].number) ||
      a->values[0].number < (allowZero ? 0.0 : 1.0)) {
    diags.error(
        a->where, s.subject(),
        std::string(name) + " needs one " + (allowZero ? "non-negative" : "positive") + " integer",
        "Write " + std::string(name) + "=<integer>.");
    return std::nullopt;
  }
  return static_cast<long>(a->values[0].number);
}

int toInt(size_t n) { return static_cast<int>(n); }

std::string arrayKindName(DataArray::Kind k) {
  switch (k) {
    case DataArray::Kind::X:
      return "X";
    case DataArray::Kind::U:
      return "U";
    case DataArray::Kind::Y:
      return "Y";
    case DataArray::Kind::IC:
      return "IC";
    case DataArray::Kind::Constants:
      return "constants";
  }
  return "?";
}

class Builder {
 public:
  Builder(Model& model, Diagnostics& diags) : model_(model), diags_(diags) {}

  void variable(const Statement& s) {
    Variable v;
    v.id = *s.id;
    v.where = s.where;
    if (const Argument* ic = s.find("IC")) v.ic = ic->values.at(0).number;
    if (variableIndex_.count(v.id)) return;  // the reader warned about the duplicate
    variableIndex_[v.id] = toInt(model_.variables.size());
    model_.variables.push_back(v);
  }

  void diff(const Statement& s) {
    Diff d;
    d.id = *s.id;
    d.where = s.where;
    d.implicit = s.has("IMPLICIT");
    d.staticHold = s.has("STATIC_HOLD");
    if (const Argument* ic = s.find("IC")) {
      d.ic = ic->values.at(0).number;
      if (ic->values.size() > 1) {
        if (d.implicit)
          d.icDerivative = ic->values[1].number;
        else
          diags_.warning(ic->where, s.subject(),
                         "the second IC value (a guess of the initial derivative) is used by "
                         "IMPLICIT DIFFs only; an explicit DIFF computes its derivative",
                         "Remove the second value to silence this warning.");
      }
    }
    if (diffIndex_.count(d.id)) return;
    diffIndex_[d.id] = toInt(model_.diffs.size());
    model_.diffs.push_back(d);
  }

  // VARIABLES=id1,... as indices into Model::variables (errors for unknown ids).
  std::vector<int> variableList(const Statement& s, bool& ok) {
    std::vector<int> out;
    const Argument* a = s.find("VARIABLES");
    if (!a) {
      diags_.error(s.where, s.subject(), "missing required argument VARIABLES",
                   "Add VARIABLES=id1[,id2...] naming VARIABLE statements.");
      ok = false;
      return out;
    }
    for (const auto& v : a->values) {
      const long id = static_cast<long>(v.number);
      auto it = variableIndex_.find(id);
      if (it == variableIndex_.end()) {
        diags_.error(v.where, s.subject(), "VARIABLE/" + std::to_string(id) + " does not exist",
                     "Use the id of a VARIABLE statement of this data set.");
        ok = false;
      } else {
        out.push_back(it->second);
      }
    }
    return out;
  }

  void plant(const Statement& s, std::vector<PlantVariables>& list) {
    PlantVariables p;
    p.id = *s.id;
    p.where = s.where;
    bool ok = true;
    p.variables = variableList(s, ok);
    for (const auto& q : list)
      if (q.id == p.id) return;
    if (ok) list.push_back(p);
  }

  void array(const Statement& s) {
    DataArray a;
    a.id = *s.id;
    a.where = s.where;
    int kinds = 0;
    for (const auto& [name, kind] :
         {std::pair{"X", DataArray::Kind::X}, std::pair{"U", DataArray::Kind::U},
          std::pair{"Y", DataArray::Kind::Y}, std::pair{"IC", DataArray::Kind::IC}})
      if (s.has(name)) {
        a.kind = kind;
        ++kinds;
      }
    if (kinds > 1) {
      diags_.error(s.where, s.subject(), "X, U, Y and IC exclude each other",
                   "Keep one array type (none for a list of constants).");
      broken_.insert({a.id, true});
      return;
    }
    const auto size = positiveInteger(s, "SIZE", diags_, true);
    bool ok = true;
    if (a.kind == DataArray::Kind::U) {
      a.variables = variableList(s, ok);
      a.size = toInt(a.variables.size());
    } else if (s.has("VARIABLES")) {
      diags_.error(s.find("VARIABLES")->where, s.subject(), "VARIABLES applies to U arrays only",
                   "Add U, or remove VARIABLES.");
      ok = false;
    }
    if (a.kind == DataArray::Kind::IC || a.kind == DataArray::Kind::Constants) {
      if (const Argument* n = s.find("NUMBERS")) {
        a.numbers = numbersOf(*n);
      } else {
        diags_.error(s.where, s.subject(), "missing required argument NUMBERS",
                     "Add NUMBERS=r1[,r2...].");
        ok = false;
      }
      a.size = toInt(a.numbers.size());
    } else if (s.has("NUMBERS")) {
      diags_.error(s.find("NUMBERS")->where, s.subject(),
                   "NUMBERS applies to IC arrays and arrays of constants only",
                   "Remove NUMBERS; the " + arrayKindName(a.kind) +
                       " array's values are computed by the solver.");
      ok = false;
    }
    if (size) {
      const bool computed = a.kind == DataArray::Kind::X || a.kind == DataArray::Kind::Y;
      if (computed) {
        a.size = static_cast<int>(*size);  // checked against the element that owns it
      } else if (*size != a.size) {
        diags_.error(s.find("SIZE")->where, s.subject(),
                     "SIZE=" + std::to_string(*size) + " but " + std::to_string(a.size) +
                         (a.kind == DataArray::Kind::U ? " VARIABLES are" : " NUMBERS are") +
                         " given",
                     "Make SIZE match the list, or omit SIZE.");
        ok = false;
      }
    } else if (a.kind == DataArray::Kind::X || a.kind == DataArray::Kind::Y) {
      a.size = -1;  // set by the element that owns it
    }
    for (const auto& b : model_.arrays)
      if (b.id == a.id) return;
    // Kept even with errors (already reported), so that references to it say no more.
    (void)ok;
    arrayIndex_[a.id] = toInt(model_.arrays.size());
    model_.arrays.push_back(a);
  }

  // An ARRAY= reference of an LSE/TFSISO of the given kind; -1 (with a diagnostic) otherwise.
  int arrayRef(const Statement& s, const char* name, DataArray::Kind kind, bool required,
               bool& ok) {
    const Argument* arg = s.find(name);
    if (!arg) {
      if (required) {
        diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                     std::string("Add ") + name + "=<id of an ARRAY/" + arrayKindName(kind) + ">.");
        ok = false;
      }
      return -1;
    }
    const auto id = positiveInteger(s, name, diags_);
    if (!id) {
      ok = false;
      return -1;
    }
    auto it = arrayIndex_.find(*id);
    if (it == arrayIndex_.end()) {
      if (!broken_.count(*id))
        diags_.error(arg->where, s.subject(), "ARRAY/" + std::to_string(*id) + " does not exist",
                     "Use the id of an ARRAY statement of this data set.");
      ok = false;
      return -1;
    }
    DataArray& a = model_.arrays[it->second];
    referenced_.insert(it->second);
    const bool icLike = kind == DataArray::Kind::IC && a.kind == DataArray::Kind::Constants;
    if (a.kind != kind && !icLike) {
      diags_.error(arg->where, s.subject(),
                   std::string(name) + "=" + std::to_string(*id) + " must name an " +
                       arrayKindName(kind) + " array; ARRAY/" + std::to_string(*id) + " is " +
                       arrayKindName(a.kind),
                   "Give ARRAY/" + std::to_string(*id) + " the type " + arrayKindName(kind) +
                       ", or name another array.");
      ok = false;
      return -1;
    }
    if ((kind == DataArray::Kind::X || kind == DataArray::Kind::Y) &&
        (a.owner >= 0 || a.gse >= 0)) {
      diags_.error(arg->where, s.subject(),
                   "ARRAY/" + std::to_string(*id) + " already holds the " +
                       (kind == DataArray::Kind::X ? "states" : "outputs") + " of " +
                       (a.owner >= 0 ? elementName(model_.linearStates[a.owner])
                                     : "GSE/" + std::to_string(model_.generalStates[a.gse].id)),
                   "Give each LSE/TFSISO/GSE its own " + arrayKindName(kind) + " array.");
      ok = false;
      return -1;
    }
    return it->second;
  }

  const Eigen::MatrixXd* matrixRef(const Statement& s, const char* name, bool required, bool& ok) {
    const Argument* arg = s.find(name);
    if (!arg) {
      if (required) {
        diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                     std::string("Add ") + name + "=<id of a MATRIX statement>.");
        ok = false;
      }
      return nullptr;
    }
    const auto id = positiveInteger(s, name, diags_);
    if (!id) {
      ok = false;
      return nullptr;
    }
    // MATRIX statements are read by model/data_element_builder.cpp before this runs.
    auto it = model_.matrixIndex.find(*id);
    if (it == model_.matrixIndex.end()) {
      diags_.error(arg->where, s.subject(), "MATRIX/" + std::to_string(*id) + " does not exist",
                   "Use the id of a MATRIX statement of this data set.");
      ok = false;
      return nullptr;
    }
    return &model_.matrices[static_cast<size_t>(it->second)].values;
  }

  static std::string elementName(const LinearStateElement& e) {
    return (e.kind == LinearStateElement::Kind::Lse ? "LSE/" : "TFSISO/") + std::to_string(e.id);
  }

  // Checks that a matrix has the expected shape.
  bool shape(const Statement& s, const char* name, const Eigen::MatrixXd& m, Eigen::Index rows,
             Eigen::Index cols, const std::string& why) {
    if (m.rows() == rows && m.cols() == cols) return true;
    diags_.error(s.find(name)->where, s.subject(),
                 std::string(name) + " is " + std::to_string(m.rows()) + "x" +
                     std::to_string(m.cols()) + " but must be " + std::to_string(rows) + "x" +
                     std::to_string(cols) + " (" + why + ")",
                 "Correct the MATRIX's ROWS/COLUMNS or the arrays it is used with.");
    return false;
  }

  // The X (and Y) array sizes: given by SIZE or taken from the element.
  bool claimSize(const Statement& s, const char* name, int array, Eigen::Index n) {
    DataArray& a = model_.arrays[array];
    if (a.size >= 0 && a.size != n) {
      diags_.error(s.find(name)->where, s.subject(),
                   "ARRAY/" + std::to_string(a.id) + " has SIZE=" + std::to_string(a.size) +
                       " but the element needs " + std::to_string(n),
                   "Correct SIZE on ARRAY/" + std::to_string(a.id) + " or omit it.");
      return false;
    }
    a.size = static_cast<int>(n);
    return true;
  }

  void lse(const Statement& s) {
    LinearStateElement e;
    e.id = *s.id;
    e.where = s.where;
    e.kind = LinearStateElement::Kind::Lse;
    e.staticHold = s.has("STATIC_HOLD");
    bool ok = true;
    e.xArray = arrayRef(s, "X", DataArray::Kind::X, true, ok);
    const Eigen::MatrixXd* a = matrixRef(s, "A", true, ok);
    const bool hasB = s.has("B"), hasU = s.has("U"), hasC = s.has("C"), hasY = s.has("Y");
    if (hasB != hasU) {
      diags_.error(s.where, s.subject(), "B and U go together",
                   hasB ? "Add U=<id of an ARRAY/U> (the inputs B multiplies)."
                        : "Add B=<id of a MATRIX> (the input matrix).");
      ok = false;
    }
    if (hasC != hasY || (s.has("D") && !hasY)) {
      diags_.error(s.where, s.subject(), "C (or D) and Y go together",
                   hasY ? "Add C=<id of a MATRIX> (the output matrix)."
                        : "Add Y=<id of an ARRAY/Y> (the outputs).");
      ok = false;
    }
    if (s.has("D") && !hasU) {
      diags_.error(s.find("D")->where, s.subject(), "D needs inputs",
                   "Add U=<id of an ARRAY/U> and B=, or remove D.");
      ok = false;
    }
    e.uArray = arrayRef(s, "U", DataArray::Kind::U, false, ok);
    e.yArray = arrayRef(s, "Y", DataArray::Kind::Y, false, ok);
    const int icArray = arrayRef(s, "IC", DataArray::Kind::IC, false, ok);
    const Eigen::MatrixXd* b = matrixRef(s, "B", false, ok);
    const Eigen::MatrixXd* c = matrixRef(s, "C", false, ok);
    const Eigen::MatrixXd* d = matrixRef(s, "D", false, ok);
    if (!ok || !a) return;
    const Eigen::Index n = a->rows();
    if (!shape(s, "A", *a, n, n, "A is square")) return;
    if (!claimSize(s, "X", e.xArray, n)) return;
    e.a = *a;
    const Eigen::Index nu = e.uArray >= 0 ? model_.arrays[e.uArray].size : 0;
    e.b = Eigen::MatrixXd::Zero(n, nu);
    if (b) {
      if (!shape(s, "B", *b, n, nu, "states x inputs")) return;
      e.b = *b;
    }
    Eigen::Index ny = c ? c->rows() : (d ? d->rows() : 0);
    if (e.yArray >= 0 && model_.arrays[e.yArray].size >= 0) ny = model_.arrays[e.yArray].size;
    e.c = Eigen::MatrixXd::Zero(ny, n);
    e.d = Eigen::MatrixXd::Zero(ny, nu);
    if (c) {
      if (!shape(s, "C", *c, ny, n, "outputs x states")) return;
      e.c = *c;
    }
    if (d) {
      if (!shape(s, "D", *d, ny, nu, "outputs x inputs")) return;
      e.d = *d;
    }
    if (e.yArray >= 0 && !claimSize(s, "Y", e.yArray, ny)) return;
    e.ic = Eigen::VectorXd::Zero(n);
    if (icArray >= 0) {
      const DataArray& ic = model_.arrays[icArray];
      if (ic.size != n) {
        diags_.error(s.find("IC")->where, s.subject(),
                     "ARRAY/" + std::to_string(ic.id) + " has " + std::to_string(ic.size) +
                         " numbers; the LSE has " + std::to_string(n) + " states",
                     "Give one initial value per state.");
        return;
      }
      for (Eigen::Index i = 0; i < n; ++i) e.ic(i) = ic.numbers[static_cast<size_t>(i)];
    }
    add(e);
  }

  void tfsiso(const Statement& s) {
    LinearStateElement e;
    e.id = *s.id;
    e.where = s.where;
    e.kind = LinearStateElement::Kind::Tfsiso;
    e.staticHold = s.has("STATIC_HOLD");
    bool ok = true;
    e.xArray = arrayRef(s, "X", DataArray::Kind::X, true, ok);
    e.uArray = arrayRef(s, "U", DataArray::Kind::U, true, ok);
    e.yArray = arrayRef(s, "Y", DataArray::Kind::Y, true, ok);
    const Argument* num = s.find("NUMERATOR");
    const Argument* den = s.find("DENOMINATOR");
    for (const char* name : {"NUMERATOR", "DENOMINATOR"})
      if (!s.has(name)) {
        diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                     std::string("Add ") + name + "=c0,c1,... (ascending powers of s).");
        ok = false;
      }
    if (!num || !den) return;
    std::vector<double> bn = numbersOf(*num), an = numbersOf(*den);
    if (an.size() < 2) {
      diags_.error(den->where, s.subject(),
                   "the DENOMINATOR must be at least of degree 1 (two coefficients)",
                   "A pure gain needs no TFSISO: multiply the input VARIABLE instead.");
      ok = false;
    } else if (an.back() == 0.0) {
      diags_.error(den->where, s.subject(),
                   "the last DENOMINATOR coefficient (highest power of s) is zero",
                   "Drop trailing zero coefficients: the degree is that of the last nonzero one.");
      ok = false;
    }
    if (bn.size() > an.size()) {
      diags_.error(num->where, s.subject(),
                   "the NUMERATOR has more coefficients than the DENOMINATOR (improper transfer "
                   "function)",
                   "Give at most " + std::to_string(an.size()) + " numerator coefficients.");
      ok = false;
    }
    if (e.uArray >= 0 && model_.arrays[e.uArray].size != 1) {
      diags_.error(s.find("U")->where, s.subject(),
                   "the U array of a TFSISO must hold one VARIABLE",
                   "Name an ARRAY/U with VARIABLES=<one id>.");
      ok = false;
    }
    if (!ok) return;
    // Controllable canonical form of H(s) = (b0 + ... + bn s^n) / (a0 + ... + an s^n):
    // x_i' = x_{i+1}, x_n' = u - sum a_i/a_n x_{i+1}; y = sum (b_i - b_n a_i) / a_n x_{i+1}
    // + b_n/a_n u.
    const Eigen::Index n = static_cast<Eigen::Index>(an.size()) - 1;
    const double lead = an.back();
    bn.resize(an.size(), 0.0);
    e.a = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i + 1 < n; ++i) e.a(i, i + 1) = 1.0;
    for (Eigen::Index i = 0; i < n; ++i) e.a(n - 1, i) = -an[static_cast<size_t>(i)] / lead;
    e.b = Eigen::MatrixXd::Zero(n, 1);
    e.b(n - 1, 0) = 1.0;
    const double bLead = bn[static_cast<size_t>(n)] / lead;
    e.c = Eigen::MatrixXd::Zero(1, n);
    for (Eigen::Index i = 0; i < n; ++i)
      e.c(0, i) = bn[static_cast<size_t>(i)] / lead - bLead * an[static_cast<size_t>(i)] / lead;
    e.d = Eigen::MatrixXd::Constant(1, 1, bLead);
    e.ic = Eigen::VectorXd::Zero(n);
    if (!claimSize(s, "X", e.xArray, n) || !claimSize(s, "Y", e.yArray, 1)) return;
    add(e);
  }

  void add(LinearStateElement& e) {
    for (const auto& o : model_.linearStates)
      if (o.id == e.id && o.kind == e.kind) return;
    const int index = toInt(model_.linearStates.size());
    model_.arrays[e.xArray].owner = index;
    if (e.yArray >= 0) model_.arrays[e.yArray].owner = index;
    model_.linearStates.push_back(e);
  }

  // GSE (docs/theory.md, "GSE"): sizes from NS/ND/NO and the arrays, the routines from a
  // user library (user/loaded_gse_routines.hpp). Every independent problem is reported.
  void gse(const Statement& s, const std::string& baseDirectory) {
    GeneralStateElement e;
    e.id = *s.id;
    e.where = s.where;
    e.staticHold = s.has("STATIC_HOLD");
    bool ok = true;
    if (const Argument* a = s.find("IMPLICIT")) {
      diags_.error(a->where, s.subject(),
                   "IMPLICIT GSEs (GSE_DERIV returning residuals) are not supported",
                   "Write the routine in explicit form (it returns x'), and drop IMPLICIT.");
      ok = false;
    }
    const long ns = positiveInteger(s, "NS", diags_, true).value_or(0);
    const long nd = positiveInteger(s, "ND", diags_, true).value_or(0);
    const long no = positiveInteger(s, "NO", diags_, true).value_or(0);
    e.ns = static_cast<int>(ns);
    e.nd = static_cast<int>(nd);
    e.no = static_cast<int>(no);
    // A count and its array go together: ADAMS reads the states and outputs through them.
    auto counted = [&](const char* count, long n, const char* arrayArg, DataArray::Kind kind) {
      const bool has = s.has(arrayArg);
      if (n > 0 && !has) {
        diags_.error(s.where, s.subject(),
                     std::string(count) + "=" + std::to_string(n) + " needs " + arrayArg + "=",
                     std::string("Add ") + arrayArg + "=<id of an ARRAY/" + arrayKindName(kind) +
                         " of SIZE " + std::to_string(n) + ">.");
        ok = false;
        return -1;
      }
      const int index = arrayRef(s, arrayArg, kind, false, ok);
      if (index >= 0 && n == 0) {
        diags_.error(s.find(arrayArg)->where, s.subject(),
                     std::string(arrayArg) + "= needs " + count + "= (the number of entries)",
                     std::string("Add ") + count + "=<count>.");
        ok = false;
        return -1;
      }
      if (index >= 0 && !claimSize(s, arrayArg, index, n)) ok = false;
      return index;
    };
    e.xArray = counted("NS", ns, "X", DataArray::Kind::X);
    e.xdArray = counted("ND", nd, "XD", DataArray::Kind::X);
    e.yArray = counted("NO", no, "Y", DataArray::Kind::Y);
    e.uArray = arrayRef(s, "U", DataArray::Kind::U, false, ok);
    if (e.uArray >= 0) e.ni = model_.arrays[e.uArray].size;
    if (ns + nd + no == 0) {
      diags_.error(s.where, s.subject(), "the GSE has no states and no outputs",
                   "Give NS= (continuous states), ND= (discrete states) or NO= (outputs).");
      ok = false;
    }
    auto initial = [&](const char* name, long n, Eigen::VectorXd& out) {
      out = Eigen::VectorXd::Zero(n);
      const int index = arrayRef(s, name, DataArray::Kind::IC, false, ok);
      if (index < 0) return;
      const DataArray& ic = model_.arrays[index];
      if (ic.size != n) {
        diags_.error(s.find(name)->where, s.subject(),
                     "ARRAY/" + std::to_string(ic.id) + " has " + std::to_string(ic.size) +
                         " numbers; the GSE has " + std::to_string(n) +
                         (std::string(name) == "IC" ? " continuous" : " discrete") + " states",
                     "Give one initial value per state.");
        ok = false;
        return;
      }
      for (long i = 0; i < n; ++i) out(i) = ic.numbers[static_cast<size_t>(i)];
    };
    initial("IC", ns, e.ic);
    initial("ICD", nd, e.icd);
    if (const Argument* sp = s.find("SAMPLE_PERIOD")) {
      expr::Expression period;
      if (!expr::Expression::parse(sp->expression, sp->valueWhere, s.subject(), diags_, period)) {
        ok = false;
      } else if (!period.hostCalls().empty()) {
        diags_.error(sp->valueWhere, s.subject(),
                     "SAMPLE_PERIOD may depend on TIME only (it is evaluated at each sample)",
                     "Write the period as a constant or a function of TIME.");
        ok = false;
      } else {
        e.samplePeriod = std::move(period);
      }
      if (nd == 0)
        diags_.warning(sp->where, s.subject(),
                       "SAMPLE_PERIOD has no effect without discrete states (ND=0)",
                       "Remove SAMPLE_PERIOD, or add ND= and XD=.");
    }
    const auto par = userParameters(s, diags_);
    if (!par) ok = false;
    const user::GseRoutineNames names = gseRoutineNames(s, diags_, ok);
    if (!ok) return;
    user::GseDescription d;
    d.id = e.id;
    d.par = *par;
    d.ns = e.ns;
    d.nd = e.nd;
    d.ni = e.ni;
    d.no = e.no;
    auto idOf = [&](int index) { return index >= 0 ? model_.arrays[index].id : 0L; };
    d.xArray = idOf(e.xArray);
    d.xdArray = idOf(e.xdArray);
    d.uArray = idOf(e.uArray);
    d.yArray = idOf(e.yArray);
    if (const auto ic = positiveInteger(s, "IC", diags_)) d.icArray = *ic;
    if (const auto icd = positiveInteger(s, "ICD", diags_)) d.icdArray = *icd;
    d.staticHold = e.staticHold;
    for (const DataArray& a : model_.arrays)
      if (a.kind == DataArray::Kind::IC || a.kind == DataArray::Kind::Constants)
        d.constantArrays.push_back({a.id, a.numbers});
    std::vector<std::string> problems;
    e.routines = user::loadGseRoutines(d, names, baseDirectory, problems);
    for (const std::string& p : problems) {
      const Argument* at = s.find("INTERFACE") ? s.find("INTERFACE") : s.find("ROUTINE");
      diags_.error(at ? at->where : s.where, s.subject(), p,
                   "Build the library with the routines (extern \"C\", signatures of "
                   "src/user/openmss_usersub.h) and name it with INTERFACE=lib::name, "
                   "ROUTINE=lib:: or `openmss run --user-library PATH`; docs/language.md, "
                   "\"GSE\".");
    }
    if (!e.routines) return;
    if (nd > 0 && !e.samplePeriod && !e.routines->sampleStep(0.0)) {
      diags_.error(s.where, s.subject(),
                   "discrete states (ND=" + std::to_string(nd) +
                       ") need a sample period: neither SAMPLE_PERIOD= nor a GSE_SAMP routine "
                       "gives one",
                   "Add SAMPLE_PERIOD=<time>, or export Gse_sample from the library.");
      return;
    }
    for (const auto& o : model_.generalStates)
      if (o.id == e.id) return;
    const int index = toInt(model_.generalStates.size());
    for (int a : {e.xArray, e.xdArray, e.yArray})
      if (a >= 0) model_.arrays[a].gse = index;
    if (e.xdArray >= 0) model_.arrays[e.xdArray].discrete = true;
    e.discrete.assign(e.icd.data(), e.icd.data() + e.icd.size());
    model_.generalStates.push_back(std::move(e));
  }

  // After every element: state offsets, and X/Y arrays nobody owns.
  void finish() {
    int next = toInt(model_.diffs.size());
    for (auto& e : model_.linearStates) {
      e.firstState = next;
      next += static_cast<int>(e.a.rows());
    }
    int nextOutput = toInt(model_.variables.size() + model_.diffs.size());
    for (auto& e : model_.generalStates) {  // after the LSE/TFSISO states, DIFF derivatives
      e.firstState = next;
      next += e.ns;
      e.firstOutput = nextOutput;
      nextOutput += e.no;
    }
    for (int k = 0; k < toInt(model_.arrays.size()); ++k) {
      const DataArray& a = model_.arrays[static_cast<size_t>(k)];
      if ((a.kind == DataArray::Kind::X || a.kind == DataArray::Kind::Y) && a.owner < 0 &&
          a.gse < 0 && !referenced_.count(k))
        diags_.error(a.where, "ARRAY/" + std::to_string(a.id),
                     "this " + arrayKindName(a.kind) +
                         " array belongs to no LSE, TFSISO or GSE, so it has no values",
                     "Name it in an LSE, TFSISO or GSE (" + arrayKindName(a.kind) +
                         "=), or remove it.");
    }
  }

 private:
  Model& model_;
  Diagnostics& diags_;
  std::map<long, int> variableIndex_, diffIndex_, arrayIndex_;
  std::map<long, bool> broken_;  // arrays with errors (no second diagnostic for them)
  std::set<int> referenced_;     // arrays an LSE/TFSISO names (even one with errors)
};

}  // namespace

bool isUserEquationStatement(const std::string& name) {
  return name == "VARIABLE" || name == "DIFF" || name == "ARRAY" || name == "LSE" ||
         name == "TFSISO" || name == "PINPUT" || name == "POUTPUT" || name == "GSE";
}

void buildUserEquations(const std::vector<const Statement*>& statements,
                        const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  // MATRIX statements come through Model::matrices; user libraries are found next to the file.
  const std::string baseDirectory =
      std::filesystem::path(dataset.file).parent_path().string();
  Builder b(model, diags);
  // Referenced elements first: VARIABLEs (U arrays, PINPUT/POUTPUT), then arrays, then the
  // elements that own arrays.
  for (const Statement* s : statements) {
    if (!s->id) continue;
    if (s->name == "VARIABLE") b.variable(*s);
    if (s->name == "DIFF") b.diff(*s);
  }
  for (const Statement* s : statements) {
    if (!s->id) continue;
    if (s->name == "ARRAY") b.array(*s);
    if (s->name == "PINPUT") b.plant(*s, model.pinputs);
    if (s->name == "POUTPUT") b.plant(*s, model.poutputs);
  }
  for (const Statement* s : statements) {
    if (!s->id) continue;
    if (s->name == "LSE") b.lse(*s);
    if (s->name == "TFSISO") b.tfsiso(*s);
    if (s->name == "GSE") b.gse(*s, baseDirectory.empty() ? "." : baseDirectory);
  }
  b.finish();
}

void bindUserEquationFunctions(const std::vector<const Statement*>& statements, Model& model,
                               Diagnostics& diags) {
  // Elements were built in statement order, the first statement of each id.
  size_t nextVariable = 0, nextDiff = 0;
  std::set<long> seenVariables, seenDiffs;
  for (const Statement* s : statements) {
    if (!s->id || (s->name != "VARIABLE" && s->name != "DIFF")) continue;
    BoundExpression* target = nullptr;
    if (s->name == "VARIABLE" && seenVariables.insert(*s->id).second &&
        nextVariable < model.variables.size())
      target = &model.variables[nextVariable++].function;
    if (s->name == "DIFF" && seenDiffs.insert(*s->id).second && nextDiff < model.diffs.size())
      target = &model.diffs[nextDiff++].function;
    if (!target) continue;  // a duplicate id
    const Argument* fn = s->find("FUNCTION");
    if (!fn) continue;  // the reader reported the missing FUNCTION
    if (fn->expression.rfind("USER", 0) == 0) {
      diags.error(fn->where, s->subject(),
                  std::string("FUNCTION=USER(...) (") +
                      (s->name == "VARIABLE" ? "VARSUB" : "DIFSUB") + ") is not supported yet",
                  "Write the function as an expression.");
      continue;
    }
    bindExpression(model, fn->expression, fn->valueWhere, s->subject(), true, diags, *target);
  }
}

bool bindUserMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                     const BindFailure& fail) {
  using K = MeasureKind;
  static const std::map<std::string, K> kinds = {{"VARVAL", K::VarVal}, {"DIF", K::Dif},
                                                 {"DIF1", K::Dif1},     {"ARYVAL", K::AryVal},
                                                 {"PINVAL", K::PinVal}, {"POUVAL", K::PouVal}};
  auto it = kinds.find(call.name);
  if (it == kinds.end()) return false;
  m.kind = it->second;
  const long id = call.args.empty() ? 0 : call.args[0];
  const std::string what = call.name == "VARVAL"                       ? "VARIABLE"
                           : call.name == "DIF" || call.name == "DIF1" ? "DIFF"
                           : call.name == "ARYVAL"                     ? "ARRAY"
                           : call.name == "PINVAL"                     ? "PINPUT"
                                                                       : "POUTPUT";
  auto find = [&](const auto& list) {
    for (size_t k = 0; k < list.size(); ++k)
      if (list[k].id == id) return static_cast<int>(k);
    return -1;
  };
  int size = 0;
  switch (m.kind) {
    case K::VarVal:
      m.element = find(model.variables);
      break;
    case K::Dif:
    case K::Dif1:
      m.element = find(model.diffs);
      break;
    case K::AryVal:
      m.element = find(model.arrays);
      if (m.element >= 0) size = model.arrays[m.element].size;
      break;
    case K::PinVal:
      m.element = find(model.pinputs);
      if (m.element >= 0) size = toInt(model.pinputs[m.element].variables.size());
      break;
    default:
      m.element = find(model.poutputs);
      if (m.element >= 0) size = toInt(model.poutputs[m.element].variables.size());
      break;
  }
  if (m.element < 0) {
    fail(what + "/" + std::to_string(id) + " does not exist",
         std::string("Use the id of ") + (what == "ARRAY" ? "an " : "a ") + what +
             " statement of this data set.");
    return true;
  }
  if (m.kind == K::AryVal || m.kind == K::PinVal || m.kind == K::PouVal) {
    const long n = call.args.size() > 1 ? call.args[1] : 0;
    // A negative size: an X or Y array whose element has errors (reported already).
    if (n < 1 || (size >= 0 && n > size)) {
      fail("position " + std::to_string(n) + " is outside " + what + "/" + std::to_string(id) +
               " (it has " + std::to_string(size) + " entries)",
           "Give a position from 1 to " + std::to_string(size) + ".");
      return true;
    }
    m.component = static_cast<int>(n);
  }
  return true;
}

}  // namespace openmss::model
