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
    if (arg.name == "XRF") continue;  // ADAMS's default layout
    if (const auto it = omissions.find(arg.name); it != omissions.end()) {
      results.*(it->second) = true;
    } else if (arg.name == "COMMENT") {
      results.comment = arg.values.empty() ? std::string() : arg.values[0].text.str();
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
      // The ADAMS 10 text layout (output/results_formatted_file.hpp); with XRF as well the
      // XML file is written, as one .res cannot be both.
      if (s.find("XRF"))
        diags.warning(arg.where, s.subject(),
                      "XRF and FORMATTED both given: the .res is written in the XML (XRF) layout",
                      "Keep only the layout you want.");
      else
        results.formatted = true;
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
    std::vector<std::string> names;
    for (const language::Value& v : c->values)
      names.push_back(v.written.empty() && !v.quoted ? v.text : v.written);
    // ADAMS/View pads the list with empty names past the eighth (seen in its exports): those
    // are dropped; a ninth name that is not empty names no column and is said so.
    for (std::size_t k = 8; k < names.size(); ++k)
      if (!names[k].empty()) {
        diags.warning(c->values[k].where, s.subject(),
                      "CNAMES: a request has 8 columns; the name '" + names[k] + "' (number " +
                          std::to_string(k + 1) + ") names none and is ignored",
                      "Give at most eight names.");
        break;
      }
    if (names.size() > 8) names.resize(8);
    if (s.id) results.requestNames[*s.id] = std::move(names);
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
    else if (s.name == "OUTPUT" && s.find("NOPRINT"))
      results.noPrint = true;  // no tabular output file (docs/output-files.md)
  }
  return results;
}

}  // namespace openmss::model
