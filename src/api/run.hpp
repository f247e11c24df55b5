#pragma once
// Running analyses for embedding (the Python package, docs/python.md): an ADAMS command file,
// or a transient simulation of a data set, into an output directory. The outputs are the ones
// `openmss run` writes (<prefix>.msg, .req, and .res where the run writes one); the caller
// reads them back. A failed run keeps every output step up to the failure.

#include <string>
#include <vector>

#include "api/diagnostic_record.hpp"

namespace openmss::api {

struct SimulateOptions {
  double end = 1.0;        // SIMULATE/TRANSIENT END=
  double dtout = 0.0;      // DTOUT= when > 0, else STEPS=
  long steps = 100;        // STEPS= when dtout is 0
  std::string integrator;  // INTEGRATOR/<name> (GSTIFF, WSTIFF, DSTIFF, ABAM, ...); "" = default
  double error = 0.0;      // INTEGRATOR ERROR= when > 0
  std::string prefix;      // output prefix; "" = the data set's base name
};

struct RunResult {
  enum class Status { Completed, InputError, Failed };
  Status status = Status::InputError;
  double time = 0.0;  // simulated time reached
  long steps = 0, outputSteps = 0;
  std::string analysis;  // "dynamic", "kinematic", ... of the last analysis
  std::string outputDirectory, prefix;
  // Paths of the files on disk after the run ("" for one not written).
  std::string messageFile, requestFile, resultsFile;
  std::vector<DiagnosticRecord> diagnostics;  // every error and warning of the run
};

// As `openmss run FILE.acf --outdir DIR`.
RunResult runCommandFile(const std::string& path, const std::string& outputDirectory);
// As `openmss run FILE.adm --end ... --outdir DIR` with OUTPUT/REQSAVE: the request file is
// always written, since the caller wants the requests back.
RunResult simulateModel(const std::string& path, const SimulateOptions& options,
                        const std::string& outputDirectory);

// The shortest decimal text that reads back as the same double (1e-07, 0.1, 2.5).
std::string exactNumber(double v);

}  // namespace openmss::api
