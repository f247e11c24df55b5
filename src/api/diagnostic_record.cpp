#include "api/diagnostic_record.hpp"

namespace openmss::api {

DiagnosticRecord toRecord(const Diagnostic& d) {
  DiagnosticRecord r;
  r.severity = severityName(d.severity);
  r.file = d.where.file;
  r.line = d.where.line;
  r.column = d.where.column;
  r.statement = d.subject;
  r.message = d.message;
  r.hint = d.hint;
  r.text = format(d);
  return r;
}

std::vector<DiagnosticRecord> toRecords(const Diagnostics& d) {
  std::vector<DiagnosticRecord> out;
  out.reserve(d.all().size());
  for (const auto& x : d.all()) out.push_back(toRecord(x));
  return out;
}

}  // namespace openmss::api
