// The references of the user equations to each other and to MATRIX statements: VARIABLES=
// lists, ARRAY= ids of the right kind and owner, MATRIX ids and their shapes, and the sizes of
// X and Y arrays claimed by the element that owns them.

#include <string>

#include "model/statement_arguments.hpp"
#include "model/user_equation_context.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

// VARIABLES=id1,... as indices into Model::variables (errors for unknown ids).
std::vector<int> UserEquationBuilder::variableList(const Statement& s, bool& ok) {
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

// An ARRAY= reference of an LSE/TFSISO of the given kind; -1 (with a diagnostic) otherwise.
int UserEquationBuilder::arrayRef(const Statement& s, const char* name, DataArray::Kind kind,
                                  bool required, bool& ok) {
  const Argument* arg = s.find(name);
  if (!arg) {
    if (required) {
      diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                   std::string("Add ") + name + "=<id of an ARRAY/" + arrayKindName(kind) + ">.");
      ok = false;
    }
    return -1;
  }
  const auto id = StatementArguments(s, diags_).integer(name);
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
  if ((kind == DataArray::Kind::X || kind == DataArray::Kind::Y) && (a.owner >= 0 || a.gse >= 0)) {
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

const Eigen::MatrixXd* UserEquationBuilder::matrixRef(const Statement& s, const char* name,
                                                      bool required, bool& ok) {
  const Argument* arg = s.find(name);
  if (!arg) {
    if (required) {
      diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                   std::string("Add ") + name + "=<id of a MATRIX statement>.");
      ok = false;
    }
    return nullptr;
  }
  const auto id = StatementArguments(s, diags_).integer(name);
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

std::string UserEquationBuilder::elementName(const LinearStateElement& e) {
  return (e.kind == LinearStateElement::Kind::Lse ? "LSE/" : "TFSISO/") + std::to_string(e.id);
}

// Checks that a matrix has the expected shape.
bool UserEquationBuilder::shape(const Statement& s, const char* name, const Eigen::MatrixXd& m,
                                Eigen::Index rows, Eigen::Index cols, const std::string& why) {
  if (m.rows() == rows && m.cols() == cols) return true;
  diags_.error(s.find(name)->where, s.subject(),
               std::string(name) + " is " + std::to_string(m.rows()) + "x" +
                   std::to_string(m.cols()) + " but must be " + std::to_string(rows) + "x" +
                   std::to_string(cols) + " (" + why + ")",
               "Correct the MATRIX's ROWS/COLUMNS or the arrays it is used with.");
  return false;
}

// The X (and Y) array sizes: given by SIZE or taken from the element.
bool UserEquationBuilder::claimSize(const Statement& s, const char* name, int array,
                                    Eigen::Index n) {
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

}  // namespace openmss::model
