#include "common/diagnostics.hpp"

#include <utility>

namespace openmss {

const char* severityName(Severity s) {
  switch (s) {
    case Severity::Note:
      return "note";
    case Severity::Warning:
      return "warning";
    case Severity::Error:
      return "error";
  }
  return "error";
}

std::string format(const Diagnostic& d) {
  std::string out;
  if (!d.where.file.empty()) {
    out += d.where.file;
    if (d.where.line > 0) {
      out += ':' + std::to_string(d.where.line);
      if (d.where.column > 0) out += ':' + std::to_string(d.where.column);
    }
    out += ": ";
  }
  out += severityName(d.severity);
  out += ": ";
  if (!d.subject.empty()) out += d.subject + ": ";
  out += d.message;
  if (!d.hint.empty()) {
    if (!out.empty() && out.back() != '.') out += '.';
    out += ' ' + d.hint;
  }
  return out;
}

void Diagnostics::add(Diagnostic d) {
  if (d.severity == Severity::Error) ++errorCount_;
  if (d.severity == Severity::Warning) ++warningCount_;
  items_.push_back(std::move(d));
}

void Diagnostics::error(const SourceLocation& where, std::string subject, std::string message,
                        std::string hint) {
  add({Severity::Error, where, std::move(subject), std::move(message), std::move(hint)});
}

void Diagnostics::warning(const SourceLocation& where, std::string subject, std::string message,
                          std::string hint) {
  add({Severity::Warning, where, std::move(subject), std::move(message), std::move(hint)});
}

void Diagnostics::note(const SourceLocation& where, std::string subject, std::string message,
                       std::string hint) {
  add({Severity::Note, where, std::move(subject), std::move(message), std::move(hint)});
}

void Diagnostics::append(const Diagnostics& other) {
  for (const auto& d : other.items_) add(d);
}

}  // namespace openmss
