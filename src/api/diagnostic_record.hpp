#pragma once
// One diagnostic as the embeddable API hands it out: plain strings and numbers, so that a
// binding (python/bindings) needs no project header beyond src/api (docs/python.md).

#include <string>
#include <vector>

#include "common/diagnostics.hpp"

namespace openmss::api {

struct DiagnosticRecord {
  std::string severity;   // "error", "warning" or "note"
  std::string file;       // as the user gave it; "" when unknown
  int line = 0;           // 1-based; 0 when unknown
  int column = 0;         // 1-based; 0 when unknown
  std::string statement;  // "MARKER/201", "" when not about one
  std::string message;    // what is wrong
  std::string hint;       // what to change ("" when nothing useful to add)
  std::string text;       // the whole line, "file:line:col: error: MARKER/201: message. hint"
};

DiagnosticRecord toRecord(const Diagnostic& d);
std::vector<DiagnosticRecord> toRecords(const Diagnostics& d);

}  // namespace openmss::api
