#pragma once
// Diagnostics are collected, never thrown: readers and checkers keep going after an error so
// that a user sees every problem of an input in one pass (Drake-style
// "file:line: severity: message").

#include <string>
#include <vector>

#include "common/source_location.hpp"

namespace openmss {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation where;
  std::string subject;  // the statement and its id, e.g. "MARKER/201" ("" when not about one)
  std::string message;  // what is wrong
  std::string hint;     // what to change ("" when there is nothing useful to add)
};

// "file:line:col: error: MARKER/201: message. hint"
std::string format(const Diagnostic& d);
const char* severityName(Severity s);

class Diagnostics {
 public:
  void add(Diagnostic d);
  void error(const SourceLocation& where, std::string subject, std::string message,
             std::string hint = {});
  void warning(const SourceLocation& where, std::string subject, std::string message,
               std::string hint = {});
  void note(const SourceLocation& where, std::string subject, std::string message,
            std::string hint = {});

  bool hasErrors() const { return errorCount_ > 0; }
  int errorCount() const { return errorCount_; }
  int warningCount() const { return warningCount_; }
  const std::vector<Diagnostic>& all() const { return items_; }
  void append(const Diagnostics& other);

 private:
  std::vector<Diagnostic> items_;
  int errorCount_ = 0;
  int warningCount_ = 0;
};

}  // namespace openmss
