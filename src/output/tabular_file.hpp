#pragma once
// The tabular output file (<prefix>.out) of the FORTRAN ADAMS/Solver: the REQUEST output laid
// out for reading, with the magnitude columns F1 and F5 the request file leaves out. ADAMS's
// own page layout is not public; OpenMSS's (docs/output-files.md, "The tabular output file"):
// a header (no date, host or path), then pages of at most kPageRows output times, each page
// one table per REQUEST (type, I/J/RM markers, comment, column names and units) with one row
// per output time, every value a 13-column "%.5E" field after a blank, printed exactly as the
// .req prints it. A page is written when full, when an analysis ends, and at close, so a run
// that fails leaves every step before the failure; close() ends the file with the run status.

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/results_settings.hpp"
#include "output/output_frame.hpp"

namespace openmss::output {

// One REQUEST's table.
struct TabularTable {
  long id = 0;
  std::string type;  // DISPLACEMENT, VELOCITY, ACCELERATION, FORCE or EXPRESSIONS
  long iMarker = 0, jMarker = 0, rmMarker = 0;  // ids; 0 when absent (or an expression request)
  std::string comment;
  // The request columns printed (0-based indices of F1..F8), with their names and units. A
  // DISPLACEMENT request has no rotational magnitude: its column 5 is left out.
  std::vector<int> columns;
  std::vector<std::string> names, units;
  bool anglesInDegrees = false;  // DISPLACEMENT: PSI THETA PHI printed in degrees, as the .req
};

// The tables of the model's REQUESTs, in Model::requests order. Expression requests take their
// column names from CNAMES when given (else F1..F8) and have no units ("-").
std::vector<TabularTable> tabularTables(const model::Model& model,
                                        const model::ResultsSettings& settings);
// Short unit symbols of a UNITS keyword ("in", "lbf", "s"); the lower-case keyword when none.
std::string tabularUnitSymbol(const std::string& keyword);

class TabularFileWriter {
 public:
  static constexpr std::size_t kPageRows = 50;  // output times per page

  TabularFileWriter() = default;
  ~TabularFileWriter();
  TabularFileWriter(const TabularFileWriter&) = delete;
  TabularFileWriter& operator=(const TabularFileWriter&) = delete;

  // Creates the file and writes its header. False with *error on failure.
  bool open(const std::string& path, const model::Model& model, std::string* error);
  // The next step starts a new analysis block (each SIMULATE command is one); the pending page
  // is written first.
  void beginAnalysis();
  // One output step of `model` (its tables are taken at the first step of each page). False
  // (and error()) when it cannot be held or written.
  bool writeStep(const OutputFrame& frame, const model::Model& model,
                 const model::ResultsSettings& settings);
  void markFailed() { runFailed_ = true; }
  // Writes the pending page and the closing line with the run status.
  void close();
  bool isOpen() const { return file_ != nullptr; }
  const std::string& error() const { return error_; }

 private:
  bool writePage();
  bool fail(const std::string& what);

  std::FILE* file_ = nullptr;
  std::string path_, error_;
  std::string timeUnit_;  // of the TIME column
  bool runFailed_ = false, newBlock_ = true;
  OutputKind blockKind_ = OutputKind::Dynamic;
  std::string blockName_;
  int kindCounts_[4] = {0, 0, 0, 0};
  int page_ = 0;                      // pages of the current block
  long blockRows_ = 0;                // output times of the current block written in earlier pages
  std::vector<TabularTable> tables_;  // of the pending page
  // The pending page: times and the eight request columns of every request at each.
  std::vector<double> times_;
  std::vector<std::vector<std::array<double, 8>>> rows_;
};

}  // namespace openmss::output
