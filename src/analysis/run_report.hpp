#pragma once
// Where an analysis sends what it produces: the lines of the message file, its diagnostics,
// the request-file rows of each output step and a progress indication. The analyses
// (analysis/*_run.hpp) know nothing of files or terminals; the command layer's Session writes
// the .msg, .req and .res through this interface (commands/session.cpp), and a test can record
// everything in memory (tests/analysis/run_driver_test.cpp). Result-file writers read the
// output snapshot (output/output_frame.hpp) and nothing else.

#include <array>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "output/output_frame.hpp"

namespace openmss::analysis {

using output::OutputFrame;
using output::OutputKind;

class RunReport {
 public:
  virtual ~RunReport() = default;
  // One line of the message file (ADAMS's .msg log of the run).
  virtual void line(const std::string& text) = 0;
  // An error or warning of the run, in the order it arose.
  virtual void diagnostic(const Diagnostic& d) = 0;
  // Called before each output step's rows: opens the request file on the first call. False
  // when it cannot be written (the reason was reported through diagnostic()).
  virtual bool openRequests() = 0;
  // The six columns of each REQUEST (Model::requests order) at output time t; displacement
  // angles in degrees, as the request file holds them.
  virtual void writeRequests(double t, const std::vector<std::array<double, 6>>& rows) = 0;
  // True once a request file has been written (a failure message names it only then).
  virtual bool requestsWritten() const = 0;
  // Whether some writer wants the full output snapshot of every output step (the .res of a
  // RESULTS statement); building it reads every part and element, so only then is it built.
  virtual bool wantsFrames() const { return false; }
  // One output step's snapshot (time, analysis kind, parts, element forces, request columns,
  // user states). False when the writer failed (reported through diagnostic()).
  virtual bool writeFrame(const OutputFrame& /*frame*/) { return true; }
  // Whether the tabular output file (.out) is written: then every output step's request
  // columns (all eight, magnitudes included) are handed to writeTabular().
  virtual bool wantsTabular() const { return false; }
  // One output step's request columns (frame.requests; the other fields are not filled).
  // False when the writer failed (reported through diagnostic()).
  virtual bool writeTabular(const OutputFrame& /*frame*/) { return true; }
  // A transient starts, reaches time t of [t0, end] after `steps` integration steps, and ends
  // (a progress line on a terminal; the defaults ignore them).
  virtual void progressStart() {}
  virtual void progress(double /*t*/, double /*t0*/, double /*end*/, long /*steps*/) {}
  virtual void progressDone() {}
};

}  // namespace openmss::analysis
