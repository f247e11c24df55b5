#pragma once
// Reading and checking a data set without simulating it, for embedding (the Python package,
// docs/python.md): every diagnostic of the one pass, the degrees of freedom, and the parts
// and requests by id. The same steps as `openmss check FILE.adm` (src/app/main.cpp).

#include <string>
#include <vector>

#include "api/diagnostic_record.hpp"

namespace openmss::api {

struct PartInfo {
  long id = 0;
  std::string name;  // "PART/2" (a data set names parts only by id)
  bool ground = false;
  double mass = 0.0;
};

struct RequestInfo {
  long id = 0;
  std::string name;  // the COMMENT, or "REQUEST/7" when it has none
  std::string kind;  // "displacement", "velocity", "acceleration", "force", "expressions"
  long iMarker = 0;  // marker ids, 0 when the request names none
  long jMarker = 0;
};

struct ModelInfo {
  bool ok = false;  // read and built without errors
  std::string path;
  std::string title;
  std::vector<DiagnosticRecord> diagnostics;  // errors and warnings, in source order
  int degreesOfFreedom = 0;                   // from the rank of the constraint Jacobian
  int grueblerCount = 0;
  std::vector<PartInfo> parts;
  std::vector<RequestInfo> requests;
};

ModelInfo loadModel(const std::string& path);

}  // namespace openmss::api
