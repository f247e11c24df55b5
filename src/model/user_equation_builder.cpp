#include "model/user_equation_builder.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "model/model_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_equation_context.hpp"
#include "model/user_routine_binding.hpp"
#include "model/user_subroutine_arguments.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

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

void UserEquationBuilder::variable(const Statement& s) {
  Variable v;
  v.id = *s.id;
  v.where = s.where;
  if (const Argument* ic = s.find("IC")) v.ic = ic->values.at(0).number;
  if (variableIndex_.count(v.id)) return;  // the reader warned about the duplicate
  variableIndex_[v.id] = toInt(model_.variables.size());
  model_.variables.push_back(v);
}

void UserEquationBuilder::diff(const Statement& s) {
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

void UserEquationBuilder::plant(const Statement& s, std::vector<PlantVariables>& list) {
  PlantVariables p;
  p.id = *s.id;
  p.where = s.where;
  bool ok = true;
  p.variables = variableList(s, ok);
  for (const auto& q : list)
    if (q.id == p.id) return;
  if (ok) list.push_back(p);
}

void UserEquationBuilder::array(const Statement& s) {
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
  const auto size = StatementArguments(s, diags_).integer("SIZE", true);
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

// After every element: state offsets, and X/Y arrays nobody owns.
void UserEquationBuilder::finish() {
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
      diags_.error(
          a.where, "ARRAY/" + std::to_string(a.id),
          "this " + arrayKindName(a.kind) +
              " array belongs to no LSE, TFSISO or GSE, so it has no values",
          "Name it in an LSE, TFSISO or GSE (" + arrayKindName(a.kind) + "=), or remove it.");
  }
}

bool isUserEquationStatement(const std::string& name) {
  return name == "VARIABLE" || name == "DIFF" || name == "ARRAY" || name == "LSE" ||
         name == "TFSISO" || name == "PINPUT" || name == "POUTPUT" || name == "GSE";
}

void buildUserEquations(const std::vector<const Statement*>& statements,
                        const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  // MATRIX statements come through Model::matrices; user libraries are found next to the file.
  const std::string baseDirectory =
      std::filesystem::path(dataset.file).parent_path().string();
  UserEquationBuilder b(model, diags);
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
      user::ElementData e;
      user::RoutineKind kind = user::RoutineKind::Varsub;
      if (s->name == "VARIABLE") {
        e.ic = model.variables[nextVariable - 1].ic.value_or(0.0);
      } else {
        const Diff& d = model.diffs[nextDiff - 1];
        kind = user::RoutineKind::Difsub;
        e.ic = d.ic;
        e.icDerivative = d.icDerivative.value_or(0.0);
        e.staticHold = d.staticHold;
        e.implicit = d.implicit;
      }
      bindUserRoutine(model, *s, *fn, kind, e, {target}, true, diags);
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
