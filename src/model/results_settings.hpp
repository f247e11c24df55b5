#pragma once
// What the RESULTS statement (and REQUEST's CNAMES) ask of the results file (.res): read by
// model/results_arguments.hpp, used by output/results_layout.hpp (docs/output-files.md).

#include <map>
#include <string>
#include <vector>

namespace openmss::model {

struct ResultsSettings {
  bool enabled = false;    // a RESULTS statement is present
  int decimalPlaces = 17;  // DECIMALPLACES (17: shortest text that reads back the same double)
  std::string comment;     // COMMENT
  bool noDisplacements = false, noVelocities = false, noAccelerations = false;
  bool noReactionForces = false, noAppliedForces = false, noSystemElements = false;
  bool noRequests = false;
  // FORMATTED (without XRF): the .res in the ADAMS 10 text layout (results_formatted_file.hpp).
  bool formatted = false;
  // OUTPUT/NOPRINT: no tabular output file (.out); without it a model with REQUESTs writes
  // one, as the FORTRAN ADAMS/Solver does (docs/output-files.md).
  bool noPrint = false;
  // REQUEST id -> CNAMES (case kept): the .res names of columns 1..8; an empty name leaves
  // that column out; columns past the list keep their default names.
  std::map<long, std::vector<std::string>> requestNames;
};

}  // namespace openmss::model
