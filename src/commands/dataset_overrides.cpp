#include "commands/dataset_overrides.hpp"

#include <string>
#include <utility>

#include "commands/model_edits.hpp"
#include "language/reader.hpp"

namespace openmss::commands {
namespace {

constexpr const char* kFile = "--set";
constexpr const char* kForm =
    "Write --set STATEMENT/id.ARGUMENT=value, e.g. --set SPRINGDAMPER/3.K=12.5";

// The override as data-set text, and how its columns map back to the override as written:
// "SPRINGDAMPER/3.K=1" is read as "SPRINGDAMPER/3, K=1" (one column more after the id);
// "ACCGRAV.JGRAV=-9.8" as "ACCGRAV/JGRAV=-9.8" (same columns).
struct Translated {
  std::string text;
  int splitColumn = 0;  // 1-based column of the argument name in `text`
  int shift = 0;        // columns added from splitColumn on
};

bool translate(const std::string& written, Translated& out) {
  const size_t eq = written.find('=');
  if (eq == std::string::npos) return false;
  const std::string left = written.substr(0, eq);
  const size_t dot = left.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == left.size()) return false;
  const std::string statement = left.substr(0, dot);
  const std::string rest = written.substr(dot + 1);  // ARGUMENT=value
  if (statement.find('/') != std::string::npos) {
    out.text = statement + ", " + rest;
    out.shift = 1;
  } else {
    out.text = statement + "/" + rest;
    out.shift = 0;
  }
  out.splitColumn = static_cast<int>(dot) + 2 + out.shift;
  return true;
}

// The reader saw the override on line 2 of a two-line text (line 1 is the title): its
// locations become --set:index:column-of-the-override.
struct Relocate {
  int index;
  const Translated& t;
  void operator()(SourceLocation& where) const {
    where.file = kFile;
    where.line = index;
    if (where.column >= t.splitColumn) where.column -= t.shift;
  }
  // The arguments' and values' locations (language/dataset.hpp keeps them compact).
  void operator()(CompactLocation& where) const {
    SourceLocation full = where;
    (*this)(full);
    where = CompactLocation(full);
  }
};

void relocate(language::Statement& s, const Relocate& r) {
  r(s.where);
  s.lastLine = r.index;
  for (auto& a : s.args) {
    r(a.where);
    r(a.valueWhere);
    for (auto& v : a.values) r(v.where);
  }
}

bool applyOne(const std::string& written, int index, language::Dataset& dataset,
              Diagnostics& diags) {
  const SourceLocation at{kFile, index, 1};
  Translated t;
  if (!translate(written, t)) {
    diags.error(at, "", "the override '" + written + "' is not STATEMENT/id.ARGUMENT=value", kForm);
    return false;
  }
  language::Dataset read;
  Diagnostics local;
  language::ReadOptions options;
  options.requireArguments = false;  // the statement of the data set has them
  language::readDatasetText("--set\n" + t.text + "\nEND\n", kFile, read, local, options);
  const Relocate r{index, t};
  for (Diagnostic d : local.all()) {
    r(d.where);
    diags.add(std::move(d));
  }
  if (local.hasErrors()) return false;
  if (read.statements.size() != 1 || read.statements[0].args.size() != 1) {
    diags.error(at, "", "the override '" + written + "' must set exactly one argument",
                "Give one --set per argument");
    return false;
  }
  language::Statement s = std::move(read.statements[0]);
  relocate(s, r);
  const language::Argument& arg = s.args[0];
  if (arg.values.empty() && !arg.isExpression) {
    diags.error(arg.where, s.subject(), "the override of " + arg.name + " has no value", kForm);
    return false;
  }
  const long id = s.id.value_or(0);
  bool found = false;
  for (auto& target : dataset.statements)
    if (target.name == s.name && target.id.value_or(0) == id) {
      mergeArguments(s, target);
      found = true;
    }
  if (found) return true;
  if (!s.id && isSingletonStatement(s.name)) {  // ACCGRAV on a data set without gravity
    dataset.statements.push_back(std::move(s));
    return true;
  }
  std::string ids;
  for (long k : statementIds(dataset, s.name)) ids += (ids.empty() ? "" : ", ") + std::to_string(k);
  diags.error(s.where, s.subject(), "the data set has no " + s.subject() + " to override",
              ids.empty() ? "The data set has no " + s.name + " statement"
                          : "The " + s.name + " ids of the data set are " + ids);
  return false;
}

}  // namespace

bool applyOverrides(const std::vector<std::string>& overrides, language::Dataset& dataset,
                    Diagnostics& diags) {
  bool ok = true;
  for (size_t k = 0; k < overrides.size(); ++k)
    ok = applyOne(overrides[k], static_cast<int>(k) + 1, dataset, diags) && ok;
  return ok;
}

}  // namespace openmss::commands
