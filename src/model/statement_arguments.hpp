#pragma once
// Typed reading of one statement's (or command's) arguments, with located diagnostics: the one
// argument reader of the model builders, the analysis settings (EQUILIBRIUM, IC, INTEGRATOR) and
// the command readers of src/commands (SIMULATE reads END=, STEPS=, ... through firstNumber).
//
// The language reader has already checked every argument against the schema (value kinds and
// counts, required arguments of data-set statements; docs/language.md). These reads guard the
// model's own requirements: a sign, a whole number, an identifier. Every problem is reported
// at the argument (file:line:column), with the statement's subject ("PART/2") and what to
// write instead; a read that fails returns std::nullopt (or false) after reporting.
//
// Two families:
// - by name, for statements read argument by argument (`real("MASS")`): an absent argument
//   gives std::nullopt and no diagnostic; the caller decides whether it is required
//   (`require`) and what its default is (`.value_or(...)`).
// - per argument, for settings read in a loop over Statement::args (`positive(a, out)`): the
//   output is written only when the value is acceptable, so it keeps its default otherwise.
// ok() tells whether any read of this reader reported an error.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::model {

class StatementArguments {
 public:
  StatementArguments(const language::Statement& s, Diagnostics& diags) : s_(s), diags_(diags) {}

  const language::Statement& statement() const { return s_; }
  bool has(const char* name) const { return s_.has(name); }
  const language::Argument* find(const char* name) const { return s_.find(name); }

  // --- By name ---------------------------------------------------------------------------
  // Exactly one number ("NAME needs one number").
  std::optional<double> real(const char* name);
  // Exactly `count` numbers ("NAME needs <count> numbers").
  std::optional<std::vector<double>> numbers(const char* name, size_t count);
  // Three numbers, e.g. QP=x,y,z ("NAME needs three numbers").
  std::optional<Eigen::Vector3d> vec3(const char* name);
  // One positive whole number naming another statement (I=, J=, PART=, CM=, JOINT=, ...).
  std::optional<long> id(const char* name);
  // One whole number >= 1, or >= 0 with `allowZero` (sizes and counts: NS=, SIZE=, ...).
  std::optional<long> integer(const char* name, bool allowZero = false);
  // One word (a keyword value such as TYPE=...).
  std::optional<std::string> word(const char* name);
  // The first value when it is a number, without any diagnostic: for arguments whose form the
  // schema fixes and whose meaning the caller checks itself (END=, STEPS=, VALUE=, ...).
  std::optional<double> firstNumber(const char* name) const;
  // Reports a missing required argument ("Add NAME=<what>."), unless the schema marks it as
  // required: the language reader then reported it already.
  void require(const char* name, const char* what);

  // --- Per argument (settings) -------------------------------------------------------------
  // A number > 0 ("NAME must be a positive number").
  bool positive(const language::Argument& a, double& out);
  // A whole number from 1 to 10^6 ("NAME must be a positive whole number").
  bool count(const language::Argument& a, int& out);
  // A number in [low, high]; `what` says the range in words for the message.
  bool within(const language::Argument& a, double low, double high, const std::string& what,
              double& out);
  // Every value a number, any count (SPLINE X=, MATRIX VALUES=, ...); the first word found is
  // reported at its own location ("NAME needs numbers, found 'W'").
  std::optional<std::vector<double>> numbers(const language::Argument& a);
  // "NAME is not supported yet", with what to do instead.
  void unsupported(const language::Argument& a, const std::string& hint);

  // --- Reporting ---------------------------------------------------------------------------
  void error(const language::Argument& a, const std::string& message, const std::string& hint);
  void error(const SourceLocation& at, const std::string& message, const std::string& hint);
  bool ok() const { return ok_; }

 private:
  const language::Statement& s_;
  Diagnostics& diags_;
  bool ok_ = true;
};

}  // namespace openmss::model
