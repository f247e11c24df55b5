#pragma once
// The results file (.res) in the legacy FORMATTED text layout of ADAMS 10 (RESULTS/FORMATTED):
// block-structured ASCII, each block a header line (name padded to column 40, then the count
// of the lines that follow it, "!" included, in 8 columns) and its lines, ended by "!". The
// header blocks, the element maps and the name map come first; then one ANALYSIS OUTPUT BLOCK
// per output time with every moving part's position and Euler parameters, velocities and
// accelerations. ADAMS's own documentation of the layout is not public; the block grammar
// follows MBDyn's writer of it (read by Adams/View), and docs/output-files.md ("The FORMATTED
// results file") lists what OpenMSS writes in each field and what it leaves out.

#include <cstdio>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/results_settings.hpp"
#include "output/output_frame.hpp"

namespace openmss::output {

class FormattedResultsWriter {
 public:
  FormattedResultsWriter() = default;
  ~FormattedResultsWriter();
  FormattedResultsWriter(const FormattedResultsWriter&) = delete;
  FormattedResultsWriter& operator=(const FormattedResultsWriter&) = delete;

  // Creates the file and writes the header blocks and maps. `modelName` names the parts in the
  // name map (.<modelName>.PART_<id>). False with *error on failure.
  bool open(const std::string& path, const model::Model& model,
            const model::ResultsSettings& settings, const std::string& modelName,
            std::string* error);
  // One ANALYSIS OUTPUT BLOCK; false (and error()) when it could not be written.
  bool writeStep(const OutputFrame& frame);
  // Writes the number of analysis blocks into the header and closes the file.
  void close();
  bool isOpen() const { return file_ != nullptr; }
  const std::string& error() const { return error_; }

 private:
  bool fail(const std::string& what);

  std::FILE* file_ = nullptr;
  std::string path_, error_;
  long countOffset_ = 0;  // where the number of analysis blocks is written at close
  long blocks_ = 0;
  std::size_t parts_ = 0;
  bool velocities_ = true, accelerations_ = true;
};

// A FORMATTED file read back: the part ids of the rigid parts map and, per analysis block, its
// type, time and the lines of numbers of each part (7 position values, 6 velocities, 6
// accelerations; empty when not written).
struct FormattedResultsBlock {
  std::string type;
  double time = 0.0;
  std::vector<std::vector<double>> positions, velocities, accelerations;
};
struct FormattedResultsData {
  std::string unitsToken, title;
  std::vector<long> partIds;
  long declaredBlocks = 0;  // NUMBER OF ANALYSIS BLOCKS
  std::vector<FormattedResultsBlock> blocks;
};
bool readFormattedResultsFile(const std::string& path, FormattedResultsData& data,
                              std::string* error);

}  // namespace openmss::output
