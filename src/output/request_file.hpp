#pragma once
// The ADAMS request file (.req, OUTPUT/REQSAVE), in the fixed ASCII layout real ADAMS writes:
// a header, one directory entry per REQUEST, then per output time a time record and one record
// of six values per request (columns 2,3,4,6,7,8 of the request). See docs/output-files.md.

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace openmss::output {

struct RequestFileHeader {
  std::string title;                          // data set title (line 1 of the .adm)
  std::string unitsToken = "M_KGS_N_RACA";    // length/mass/time/force/angle units tag
  double lengthScale = 1.0;                   // model length units per metre
  std::string stamp = "2000-01-01 00:00:00";  // fixed for bit-identical output (see docs)
};

// Request types as the directory records number them.
enum RequestType : int {
  kDisplacementRequest = 1,
  kVelocityRequest = 2,
  kAccelerationRequest = 3,
  kForceRequest = 4,
  kExpressionRequest = 5,  // F2=..F8= expressions and user-written requests
};

struct RequestEntry {
  long id = 0;
  int type = 5;  // 1 displacement, 2 velocity, 3 acceleration, 4 force, 5 expressions/user
  long iMarker = 0;
  long jMarker = 0;
  std::string comment;
};

// The units token and length scale of the header for a UNITS statement. The arguments are the
// ADAMS keywords as written in UNITS/ (upper case: "MILLIMETER", "KILOGRAM", "SECOND",
// "NEWTON"). Returns nullopt for a combination whose token has not been seen in a file real
// ADAMS wrote (see docs/output-files.md); callers then keep the SI default and say so.
struct RequestFileUnits {
  std::string token;
  double lengthScale = 1.0;  // model length units per metre
};
std::optional<RequestFileUnits> requestFileUnits(std::string_view length, std::string_view mass,
                                                 std::string_view time, std::string_view force);

// One value as a step record prints it: "%.5E" right-aligned in 13 columns, or "%.4E" when the
// exponent needs three digits, so that the field always starts with a blank (docs).
std::string requestFileField(double value);

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
  //
  // Values are written as given. The format holds the three angles of a displacement request
  // (psi, theta, phi) in degrees and everything else in model units, so the caller converts
  // those angles from radians (src/analysis does); the writer converts nothing.
  //
  // A step whose row count differs from the directory is not written (a partial block would
  // make the rest of the file unreadable); it and any I/O failure set failed() and error().
  void writeStep(double time, const std::vector<std::array<double, 6>>& rows);
  void close();
  bool isOpen() const { return file_ != nullptr; }
  bool failed() const { return !error_.empty(); }
  // The first failure since open(), "" when none.
  const std::string& error() const { return error_; }

 private:
  void fail(std::string message);

  std::FILE* file_ = nullptr;
  std::string path_;
  std::size_t requestCount_ = 0;  // directory entries, i.e. rows expected per step
  std::string error_;
};

}  // namespace openmss::output
