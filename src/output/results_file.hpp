#pragma once
// The ADAMS results file (.res) in its XML layout (XRF, namespace
// http://www.mscsoftware.com/:xrf10), written with libxml2's xmlTextWriter: a header
// (Bibliography, Analysis, ModelInfo, Units), the StepMap naming every component and its id,
// then one <Data> block per analysis with one <Step> per output time, and a TerminationStatus.
// Streamed: each step is written and flushed as it comes, nothing is held, and close() ends
// the document validly whether the run succeeded or failed (docs/output-files.md).

#include <string>

#include "model/model.hpp"
#include "output/output_frame.hpp"
#include "output/results_layout.hpp"

// libxml2's writer, kept out of the header's users.
struct _xmlTextWriter;

namespace openmss::output {

struct ResultsFileHeader {
  std::string analysisName = "Last_Run";      // <Analysis name=...> (the output prefix)
  std::string solver = "OpenMSS";             // <Analysis Solver=...>
  std::string version;                        // <Application version=...>
  std::string stamp = "2000-01-01 00:00:00";  // fixed, for bit-identical output (docs)
};

// Text of one value with `decimalPlaces` digits after the point (ADAMS's DECIMALPLACES);
// 17 (the default) gives the shortest text that reads back as the same double.
std::string formatResultValue(double value, int decimalPlaces);

class ResultsFileWriter {
 public:
  ResultsFileWriter() = default;
  ~ResultsFileWriter();
  ResultsFileWriter(const ResultsFileWriter&) = delete;
  ResultsFileWriter& operator=(const ResultsFileWriter&) = delete;

  // Creates the file and writes everything up to the StepMap. False with *error on failure.
  bool open(const std::string& path, const model::Model& model,
            const model::ResultsSettings& settings, const ResultsFileHeader& header,
            std::string* error);
  // The next step starts a new <Data> block even when its analysis kind is the current one's
  // (each SIMULATE command is one analysis).
  void beginAnalysis() { newBlock_ = true; }
  // One output step; false (and error()) when it could not be written.
  bool writeStep(const OutputFrame& frame);
  // The run ended in failure: TerminationStatus says runStatus="Failed".
  void markFailed() { runFailed_ = true; }
  // Ends the open <Data> block, writes TerminationStatus and closes the document.
  void close();
  bool isOpen() const { return writer_ != nullptr; }
  const std::string& error() const { return error_; }
  const ResultsLayout& layout() const { return layout_; }

 private:
  bool check(int rc, const char* what);
  bool startBlock(OutputKind kind);

  _xmlTextWriter* writer_ = nullptr;
  std::string path_;
  ResultsLayout layout_;
  int decimalPlaces_ = 17;
  bool dataOpen_ = false, newBlock_ = true, runFailed_ = false;
  OutputKind blockKind_ = OutputKind::Dynamic;
  int blocks_ = 0;                    // <Data id=...>
  int kindCounts_[4] = {0, 0, 0, 0};  // per OutputKind: the _001, _002 of the block names
  std::string error_;
};

}  // namespace openmss::output
