#include "model/results_arguments.hpp"

#include <map>
#include <string>

#include "model/statement_arguments.hpp"

namespace openmss::model {

namespace {

void applyResultsArguments(const language::Statement& s, ResultsSettings& results,
                           Diagnostics& diags) {
  results.enabled = true;
  StatementArguments a(s, diags);
  const std::map<std::string, bool ResultsSettings::*> omissions = {
      {"NODISPLACEMENTS", &ResultsSettings::noDisplacements},
      {"NOVELOCITIES", &ResultsSettings::noVelocities},
      {"NOACCELERATIONS", &ResultsSettings::noAccelerations},
      {"NOREACTIONFORCES", &ResultsSettings::noReactionForces},
      {"NOAPPLIEDFORCES", &ResultsSettings::noAppliedForces},
      {"NOSYSTEMELEMENTS", &ResultsSettings::noSystemElements},
      {"NOREQUESTS", &ResultsSettings::noRequests}};
  for (const language::Argument& arg : s.args) {
    if (arg.name == "XRF") continue;  // the only layout written, and ADAMS's default
    if (const auto it = omissions.find(arg.name); it != omissions.end()) {
      results.*(it->second) = true;
    } else if (arg.name == "COMMENT") {
      results.comment = arg.values.empty() ? std::string() : arg.values[0].text;
    } else if (arg.name == "DECIMALPLACES") {
      if (const auto n = a.integer("DECIMALPLACES", /*allowZero=*/true)) {
        if (*n > 17) {
          a.error(arg, "DECIMALPLACES must be from 0 to 17",
                  "17 (the default) already writes every double exactly.");
        } else {
          results.decimalPlaces = static_cast<int>(*n);
        }
      }
    } else if (arg.name == "NOCONTACTS" || arg.name == "NODATASTRUCTURES" ||
               arg.name == "NOFLOATINGMARKERS" || arg.name == "NOLINEAR" || arg.name == "NOTIRES") {
      // These leave out quantities the .res of this solver never holds (docs/output-files.md):
      // the file is what they ask for, so they are accepted without a warning.
      continue;
    } else if (arg.name == "FORMATTED") {
      diags.warning(arg.where, s.subject(),
                    "FORMATTED (the ADAMS 10 text layout) is not written; the XML (XRF) .res "
                    "is written instead",
                    "Remove FORMATTED, or convert the XRF file with a post-processor.");
    } else {
      diags.warning(arg.where, s.subject(),
                    arg.name + " is not supported yet and has no effect on the .res",
                    "Remove it to silence this warning (docs/output-files.md lists the "
                    "RESULTS arguments the .res honours).");
    }
  }
}

// CNAMES of one REQUEST; CUNITS, CLABELS and RESULTS_NAME are read but not written, and say so.
void readRequestNames(const language::Statement& s, ResultsSettings& results, Diagnostics& diags) {
  if (const language::Argument* c = s.find("CNAMES")) {
    if (c->values.size() > 8) {
      diags.error(c->where, s.subject(),
                  "CNAMES gives " + std::to_string(c->values.size()) +
                      " names for the 8 columns of a request",
                  "Give at most eight names, \"\" for a column to leave out of the .res.");
    } else if (s.id) {
      std::vector<std::string>& names = results.requestNames[*s.id];
      for (const language::Value& v : c->values)
        names.push_back(v.written.empty() && !v.quoted ? v.text : v.written);
    }
  }
  for (const char* name : {"CUNITS", "CLABELS", "RESULTS_NAME"})
    if (const language::Argument* arg = s.find(name))
      diags.warning(arg->where, s.subject(),
                    std::string(name) + " is not supported yet and has no effect on the .res",
                    "Remove it to silence this warning.");
}

}  // namespace

ResultsSettings readResultsSettings(const language::Dataset& dataset, Diagnostics& diags) {
  ResultsSettings results;
  for (const language::Statement& s : dataset.statements) {
    if (s.name == "RESULTS")
      applyResultsArguments(s, results, diags);
    else if (s.name == "REQUEST")
      readRequestNames(s, results, diags);
  }
  return results;
}

}  // namespace openmss::model
