#pragma once
// Reads a request file (.req) written by real ADAMS or by RequestFileWriter: header, directory
// and every output step, with CRLF or LF line ends. Values are returned as printed in the file
// (so displacement angles in degrees). See docs/output-files.md for the layout.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/request_file.hpp"

namespace openmss::output {

// One output time: rows[k] belongs to the k-th directory entry.
struct RequestFileStep {
  double time = 0.0;
  std::vector<std::array<double, 6>> rows;
};

struct RequestFileData {
  RequestFileHeader header;            // title and stamp without their padding blanks
  std::vector<RequestEntry> entries;   // comments without their padding blanks
  std::vector<RequestFileStep> steps;  // every step in file order, repeated times included

  // Index of the directory entry of REQUEST/id, or -1.
  int entryIndex(long id) const;
};

// Parses the text of a request file. On a malformed file returns nullopt and sets *error to
// "<name>:<line>: <what is wrong>".
std::optional<RequestFileData> parseRequestFile(std::string_view text, const std::string& name,
                                                std::string* error);
// Reads and parses the file at path (errors as above, or that the file cannot be read).
std::optional<RequestFileData> readRequestFile(const std::string& path, std::string* error);

// The steps with one record per output time: of consecutive steps with the same printed time
// the last is kept. A run with an initial-conditions analysis writes t=0 twice (the IC result,
// then the first output of the transient); the later record is the one the transient used.
std::vector<RequestFileStep> lastStepPerTime(const std::vector<RequestFileStep>& steps);

}  // namespace openmss::output
