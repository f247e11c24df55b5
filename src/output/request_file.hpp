#pragma once
// The ADAMS request file (.req, OUTPUT/REQSAVE), in the fixed ASCII layout real ADAMS writes:
// a header, one directory entry per REQUEST, then per output time a time record and one record
// of six values per request (columns 2,3,4,6,7,8 of the request). See docs/output-files.md.

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace openmss::output {

struct RequestFileHeader {
  std::string title;                      // data set title (line 1 of the .adm)
  std::string unitsToken = "M_KGS_N_RACA";  // length/mass/time/force/angle units tag
  double lengthScale = 1.0;               // model length units per metre
  std::string stamp = "2000-01-01 00:00:00";  // fixed for bit-identical output (see docs)
};

struct RequestEntry {
  long id = 0;
  int type = 5;  // 1 displacement, 2 velocity, 3 acceleration, 4 force, 5 expressions/user
  long iMarker = 0;
  long jMarker = 0;
  std::string comment;
};

class RequestFileWriter {
 public:
  RequestFileWriter() = default;
  ~RequestFileWriter();
  RequestFileWriter(const RequestFileWriter&) = delete;
  RequestFileWriter& operator=(const RequestFileWriter&) = delete;

  // Creates the file and writes header and directory. Returns false with *error set on failure.
  bool open(const std::string& path, const RequestFileHeader& header,
            const std::vector<RequestEntry>& entries, std::string* error);
  // One output time: rows[k] holds the six values of entries[k]. Flushed to disk at once so a
  // failed run keeps every completed output step.
  void writeStep(double time, const std::vector<std::array<double, 6>>& rows);
  void close();
  bool isOpen() const { return file_ != nullptr; }

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace openmss::output
