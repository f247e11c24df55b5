#include "output/request_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace openmss::output {
namespace {

// Field widths of the layout (checked byte by byte against files real ADAMS wrote).
constexpr std::size_t kStampWidth = 19;  // "YYYY-MM-DD HH:MM:SS"
constexpr std::size_t kTitleWidth = 80;
constexpr std::size_t kCommentWordWidth = 4;  // comments are counted in 4-character words

// Cuts or blank-pads a field to its width; a trailing CR or blank of the source line is dropped
// first so that a title read from a CRLF data set does not smuggle a CR into the file.
std::string fitted(const std::string& text, std::size_t width) {
  std::string out = text.substr(0, text.find_last_not_of(" \t\r\n") + 1);
  out.resize(std::min(out.size(), width));
  out.resize(width, ' ');
  return out;
}

// One value in its 13-column field, always with a blank before it so that records split on
// whitespace as well as at fixed columns (docs/output-files.md, "Numbers that do not fit"):
// "%.5E" as ADAMS prints, but a value whose exponent needs three digits (|v| < 1e-99 or
// >= 1e100) loses one mantissa digit, "-5.3552E-101", instead of running into the previous
// field as "-5.35523E-101" would.
void writeValue(std::FILE* file, double value) {
  std::fputs(requestFileField(value).c_str(), file);
}

struct LengthUnit {
  std::string_view keyword;
  std::string_view code;
  double perMetre;
};
struct NamedCode {
  std::string_view keyword;
  std::string_view code;
};

// Only codes seen in real ADAMS output (or given by its documentation of the header) are
// listed: a guessed code would make a file that post-processors misread without complaint.
constexpr LengthUnit kLengthUnits[] = {
    {"METER", "M_", 1.0},
    {"MILLIMETER", "MM", 1.0e3},
    {"CENTIMETER", "CM", 1.0e2},
    {"INCH", "IN", 1.0 / 0.0254},
};
constexpr NamedCode kMassUnits[] = {{"KILOGRAM", "KG"}, {"POUND_MASS", "LB"}};
constexpr NamedCode kTimeUnits[] = {{"SECOND", "S"}};
constexpr NamedCode kForceUnits[] = {{"NEWTON", "N_"}, {"POUND_FORCE", "PF"}};

template <typename Table>
const auto* findKeyword(const Table& table, std::string_view keyword) {
  for (const auto& row : table) {
    if (row.keyword == keyword) return &row;
  }
  return static_cast<decltype(&table[0])>(nullptr);
}

}  // namespace

std::string requestFileField(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.5E", value);
  if (std::strlen(text) > 12) std::snprintf(text, sizeof text, "%.4E", value);
  char field[32];
  std::snprintf(field, sizeof field, "%13s", text);
  return field;
}

std::optional<RequestFileUnits> requestFileUnits(std::string_view length, std::string_view mass,
                                                 std::string_view time, std::string_view force) {
  const auto* lengthUnit = findKeyword(kLengthUnits, length);
  const auto* massUnit = findKeyword(kMassUnits, mass);
  const auto* timeUnit = findKeyword(kTimeUnits, time);
  const auto* forceUnit = findKeyword(kForceUnits, force);
  if (!lengthUnit || !massUnit || !timeUnit || !forceUnit) return std::nullopt;
  RequestFileUnits units;
  units.token = std::string(lengthUnit->code) + std::string(massUnit->code) +
                std::string(timeUnit->code) + "_" + std::string(forceUnit->code) + "RACA";
  units.lengthScale = lengthUnit->perMetre;
  return units;
}

RequestFileWriter::~RequestFileWriter() { close(); }

bool RequestFileWriter::open(const std::string& path, const RequestFileHeader& header,
                             const std::vector<RequestEntry>& entries, std::string* error) {
  close();
  error_.clear();
  path_ = path;
  requestCount_ = 0;
  // Binary mode: the file has LF line ends on every platform, so runs compare byte for byte.
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    if (error) *error = "cannot create request file " + path + ": " + std::strerror(errno);
    return false;
  }

  // The two integers and "3D" after the stamp are constant in every file ADAMS wrote; their
  // meaning is not documented, so they are reproduced as they are.
  std::fprintf(file_, " A.R3    %s               0         0  3D\n",
               fitted(header.stamp, kStampWidth).c_str());
  std::fprintf(file_, "%s\n", fitted(header.title, kTitleWidth).c_str());
  std::fprintf(file_, "%5zu     %s %.15E\n", entries.size(), header.unitsToken.c_str(),
               header.lengthScale);
  for (const RequestEntry& entry : entries) {
    std::string comment = entry.comment;
    const std::size_t words = (comment.size() + kCommentWordWidth - 1) / kCommentWordWidth;
    comment.resize(words * kCommentWordWidth, ' ');
    std::fprintf(file_, "%11ld%14d%14ld%14ld%14zu\n", entry.id, entry.type, entry.iMarker,
                 entry.jMarker, words);
    // An empty comment still gets its (empty) record, so every entry has two lines.
    std::fprintf(file_, "%s\n", comment.c_str());
  }
  requestCount_ = entries.size();
  if (std::fflush(file_) != 0 || std::ferror(file_)) {
    const std::string reason = std::strerror(errno);
    close();
    if (error) *error = "cannot write request file " + path + ": " + reason;
    return false;
  }
  return true;
}

void RequestFileWriter::writeStep(double time, const std::vector<std::array<double, 6>>& rows) {
  if (file_ == nullptr) {
    fail("request file is not open");
    return;
  }
  if (rows.size() != requestCount_) {
    fail("step at time " + std::to_string(time) + " has " + std::to_string(rows.size()) +
         " rows for " + std::to_string(requestCount_) + " requests; step not written");
    return;
  }
  std::fputc(' ', file_);
  writeValue(file_, time);
  std::fputc('\n', file_);
  for (const std::array<double, 6>& values : rows) {
    std::fputc(' ', file_);
    for (const double v : values) writeValue(file_, v);
    std::fputc('\n', file_);
  }
  if (std::fflush(file_) != 0 || std::ferror(file_)) {
    fail(std::string("cannot write request file ") + path_ + ": " + std::strerror(errno));
  }
}

void RequestFileWriter::close() {
  if (file_ == nullptr) return;
  if (std::fclose(file_) != 0) {
    fail(std::string("cannot close request file ") + path_ + ": " + std::strerror(errno));
  }
  file_ = nullptr;
}

void RequestFileWriter::fail(std::string message) {
  if (error_.empty()) error_ = std::move(message);
}

}  // namespace openmss::output
