// GSE statements (docs/theory.md §4c; docs/language.md, "GSE"): sizes from NS/ND/NO and their
// arrays, initial values, the sample period, and the routines from a user library
// (user/loaded_gse_routines.hpp). Every independent problem is reported.

#include <string>
#include <utility>

#include "model/statement_arguments.hpp"
#include "model/user_equation_context.hpp"
#include "model/user_subroutine_arguments.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

// A count and its array go together: ADAMS reads the states and outputs through them.
int UserEquationBuilder::gseArray(const Statement& s, const char* count, long n,
                                  const char* arrayArg, DataArray::Kind kind, bool& ok) {
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
}

// IC= (continuous) or ICD= (discrete): an IC array of one value per state; zeros without one.
void UserEquationBuilder::gseInitial(const Statement& s, const char* name, long n,
                                     Eigen::VectorXd& out, bool& ok) {
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
}

// SAMPLE_PERIOD=: an expression of TIME, evaluated at each sample. False when it is invalid.
bool UserEquationBuilder::gseSamplePeriod(const Statement& s, long nd, GeneralStateElement& e) {
  const Argument* sp = s.find("SAMPLE_PERIOD");
  if (!sp) return true;
  bool ok = true;
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
  return ok;
}

// Loads the routines for the element's description (what GSE_DERIV & co. are told about it).
// False, after diagnostics, when they cannot be loaded or discrete states lack a period.
bool UserEquationBuilder::gseRoutines(const Statement& s, const std::string& baseDirectory,
                                      const std::vector<double>& par,
                                      const user::GseRoutineNames& names, GeneralStateElement& e) {
  StatementArguments args(s, diags_);
  user::GseDescription d;
  d.id = e.id;
  d.par = par;
  d.ns = e.ns;
  d.nd = e.nd;
  d.ni = e.ni;
  d.no = e.no;
  auto idOf = [&](int index) { return index >= 0 ? model_.arrays[index].id : 0L; };
  d.xArray = idOf(e.xArray);
  d.xdArray = idOf(e.xdArray);
  d.uArray = idOf(e.uArray);
  d.yArray = idOf(e.yArray);
  if (const auto ic = args.integer("IC")) d.icArray = *ic;
  if (const auto icd = args.integer("ICD")) d.icdArray = *icd;
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
  if (!e.routines) return false;
  if (e.nd > 0 && !e.samplePeriod && !e.routines->sampleStep(0.0)) {
    diags_.error(s.where, s.subject(),
                 "discrete states (ND=" + std::to_string(e.nd) +
                     ") need a sample period: neither SAMPLE_PERIOD= nor a GSE_SAMP routine "
                     "gives one",
                 "Add SAMPLE_PERIOD=<time>, or export Gse_sample from the library.");
    return false;
  }
  return true;
}

void UserEquationBuilder::gse(const Statement& s, const std::string& baseDirectory) {
  StatementArguments args(s, diags_);
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
  const long ns = args.integer("NS", true).value_or(0);
  const long nd = args.integer("ND", true).value_or(0);
  const long no = args.integer("NO", true).value_or(0);
  e.ns = static_cast<int>(ns);
  e.nd = static_cast<int>(nd);
  e.no = static_cast<int>(no);
  e.xArray = gseArray(s, "NS", ns, "X", DataArray::Kind::X, ok);
  e.xdArray = gseArray(s, "ND", nd, "XD", DataArray::Kind::X, ok);
  e.yArray = gseArray(s, "NO", no, "Y", DataArray::Kind::Y, ok);
  e.uArray = arrayRef(s, "U", DataArray::Kind::U, false, ok);
  if (e.uArray >= 0) e.ni = model_.arrays[e.uArray].size;
  if (ns + nd + no == 0) {
    diags_.error(s.where, s.subject(), "the GSE has no states and no outputs",
                 "Give NS= (continuous states), ND= (discrete states) or NO= (outputs).");
    ok = false;
  }
  gseInitial(s, "IC", ns, e.ic, ok);
  gseInitial(s, "ICD", nd, e.icd, ok);
  if (!gseSamplePeriod(s, nd, e)) ok = false;
  const auto par = userParameters(s, diags_);
  if (!par) ok = false;
  const user::GseRoutineNames names = gseRoutineNames(s, diags_, ok);
  if (!ok || !gseRoutines(s, baseDirectory, *par, names, e)) return;
  for (const auto& o : model_.generalStates)
    if (o.id == e.id) return;
  const int index = toInt(model_.generalStates.size());
  for (int a : {e.xArray, e.xdArray, e.yArray})
    if (a >= 0) model_.arrays[a].gse = index;
  if (e.xdArray >= 0) model_.arrays[e.xdArray].discrete = true;
  model_.generalStates.push_back(std::move(e));
}

}  // namespace openmss::model
