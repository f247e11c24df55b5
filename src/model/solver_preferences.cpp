#include "model/solver_preferences.hpp"

namespace openmss::model {

void applySolverPreferences(const language::Statement& s, Diagnostics& diags) {
  for (const language::Argument& a : s.args) {
    std::string why;
    if (a.name == "LIST") continue;  // the command form's listing
    if (s.name == "LSOLVER")
      why =
          "OpenMSS factors its Newton matrices with its own dense or sparse LU "
          "(docs/theory.md); the choice of linear solver has no effect";
    else if (s.name == "ENVIRONMENT" && a.name != "NAME")
      continue;  // VALUE is named with its variable
    else if (s.name == "ENVIRONMENT")
      why = "the environment variable " +
            (a.values.empty() ? std::string() : a.values[0].text.str()) +
            " is not read by OpenMSS and has no effect";
    else if (a.name == "NTHREADS")
      why = "OpenMSS solves on one thread; its results do not depend on NTHREADS";
    else if (a.name == "CONTACT_FACETING_TOLERANCE" || a.name == "CONTACT_GEOMETRY_LIBRARY")
      why = a.name + " chooses ADAMS's faceted contact geometry, which OpenMSS does not use";
    else if (a.name == "SIMFAIL" && !a.values.empty() && a.values[0].text == "STOPCF")
      continue;  // what OpenMSS always does: a failed analysis ends the command file
    else
      why = a.name + " does not apply to OpenMSS and has no effect";
    diags.warning(a.where, s.subject(), s.name + "/" + a.name + ": " + why,
                  "Remove it to silence this warning.");
  }
}

}  // namespace openmss::model
