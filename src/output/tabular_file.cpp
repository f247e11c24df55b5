#include "output/tabular_file.hpp"

#include <cerrno>
#include <cstring>
#include <map>

#include "common/ascii_case.hpp"
#include "output/request_file.hpp"

namespace openmss::output {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr const char* kRule =
    "=============================================================================================="
    "======================================";  // 132 columns, a line printer's width

std::string unitsOf(model::Request::Kind kind, int column, const model::Units& u) {
  using K = model::Request::Kind;
  const std::string length = tabularUnitSymbol(u.length), time = tabularUnitSymbol(u.time);
  const std::string force = tabularUnitSymbol(u.force);
  const bool translational = column < 4;
  switch (kind) {
    case K::Displacement:
      return translational ? length : "deg";
    case K::Velocity:
      return (translational ? length : "rad") + "/" + time;
    case K::Acceleration:
      return (translational ? length : "rad") + "/" + time + "**2";
    case K::Force:
      return translational ? force : force + "*" + length;
    case K::Expressions:
      break;
  }
  return "-";
}

// Column names as ADAMS's tabular output names them (ACCM ACCX ACCY ACCZ WDTM WDTX WDTY WDTZ
// for an ACCELERATION request; the others by the same pattern).
std::array<const char*, 8> namesOf(model::Request::Kind kind) {
  using K = model::Request::Kind;
  switch (kind) {
    case K::Displacement:
      return {"DM", "DX", "DY", "DZ", "", "PSI", "THETA", "PHI"};
    case K::Velocity:
      return {"VM", "VX", "VY", "VZ", "WM", "WX", "WY", "WZ"};
    case K::Acceleration:
      return {"ACCM", "ACCX", "ACCY", "ACCZ", "WDTM", "WDTX", "WDTY", "WDTZ"};
    case K::Force:
      return {"FM", "FX", "FY", "FZ", "TM", "TX", "TY", "TZ"};
    case K::Expressions:
      break;
  }
  return {"F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8"};
}

const char* typeOf(model::Request::Kind kind) {
  using K = model::Request::Kind;
  switch (kind) {
    case K::Displacement:
      return "DISPLACEMENT";
    case K::Velocity:
      return "VELOCITY";
    case K::Acceleration:
      return "ACCELERATION";
    case K::Force:
      return "FORCE";
    case K::Expressions:
      break;
  }
  return "EXPRESSIONS";
}

}  // namespace

std::string tabularUnitSymbol(const std::string& keyword) {
  static const std::map<std::string, std::string> symbols = {
      {"METER", "m"},         {"KILOMETER", "km"},
      {"CENTIMETER", "cm"},   {"MILLIMETER", "mm"},
      {"MICROMETER", "um"},   {"NANOMETER", "nm"},
      {"INCH", "in"},         {"FOOT", "ft"},
      {"YARD", "yd"},         {"MILE", "mi"},
      {"KILOGRAM", "kg"},     {"GRAM", "g"},
      {"TONNE", "t"},         {"POUND_MASS", "lbm"},
      {"SLUG", "slug"},       {"SECOND", "s"},
      {"MILLISECONDS", "ms"}, {"MICROSECOND", "us"},
      {"MINUTE", "min"},      {"HOUR", "h"},
      {"NEWTON", "N"},        {"KNEWTON", "kN"},
      {"MEGANEWTON", "MN"},   {"MILLINEWTON", "mN"},
      {"DYNE", "dyn"},        {"KILOGRAM_FORCE", "kgf"},
      {"POUND_FORCE", "lbf"}, {"KPOUND_FORCE", "klbf"},
      {"OUNCE_FORCE", "ozf"}};
  const auto it = symbols.find(keyword);
  return it != symbols.end() ? it->second : toLowerAscii(keyword);
}

std::vector<TabularTable> tabularTables(const model::Model& m,
                                        const model::ResultsSettings& settings) {
  std::vector<TabularTable> tables;
  for (const model::Request& r : m.requests) {
    TabularTable t;
    t.id = r.id;
    t.type = typeOf(r.kind);
    t.comment = r.comment;
    const bool expressions = r.kind == model::Request::Kind::Expressions;
    if (!expressions) {
      t.iMarker = m.markers[r.iMarker].id;
      t.jMarker = r.jMarker >= 0 ? m.markers[r.jMarker].id : 0;
      t.rmMarker = r.rmMarker >= 0 ? m.markers[r.rmMarker].id : 0;
    }
    t.anglesInDegrees = r.kind == model::Request::Kind::Displacement;
    const auto names = namesOf(r.kind);
    const auto cnames = settings.requestNames.find(r.id);
    for (int c = 0; c < 8; ++c) {
      if (r.kind == model::Request::Kind::Displacement && c == 4) continue;
      std::string name = names[c];
      if (expressions && cnames != settings.requestNames.end() &&
          c < static_cast<int>(cnames->second.size()) && !cnames->second[c].empty())
        name = cnames->second[c];
      t.columns.push_back(c);
      t.names.push_back(name);
      t.units.push_back(unitsOf(r.kind, c, m.units));
    }
    tables.push_back(std::move(t));
  }
  return tables;
}

TabularFileWriter::~TabularFileWriter() { close(); }

bool TabularFileWriter::fail(const std::string& what) {
  if (error_.empty())
    error_ = "cannot write the tabular output file " + path_ + " (" + what + ")" +
             (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string());
  return false;
}

bool TabularFileWriter::open(const std::string& path, const model::Model& m, std::string* error) {
  close();
  error_.clear();
  path_ = path;
  runFailed_ = false;
  newBlock_ = true;
  for (int& c : kindCounts_) c = 0;
  tables_.clear();
  times_.clear();
  rows_.clear();
  // Binary mode: LF line ends on every platform, so runs compare byte for byte.
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    if (error)
      *error = "cannot create the tabular output file " + path + ": " + std::strerror(errno);
    return false;
  }
  std::string title = m.title.substr(0, m.title.find_last_not_of(" \t\r\n") + 1);
  const model::Units& u = m.units;
  timeUnit_ = tabularUnitSymbol(u.time);
  std::fprintf(file_, "OpenMSS tabular output (.out): REQUEST values at every output time\n");
  std::fprintf(file_, "Title: %s\n", title.c_str());
  std::fprintf(file_,
               "Units: length %s (%s), mass %s (%s), time %s (%s), force %s (%s); angles in rad,"
               " DISPLACEMENT angles (PSI THETA PHI, body 3-1-3) in deg\n",
               tabularUnitSymbol(u.length).c_str(), u.length.c_str(),
               tabularUnitSymbol(u.mass).c_str(), u.mass.c_str(), tabularUnitSymbol(u.time).c_str(),
               u.time.c_str(), tabularUnitSymbol(u.force).c_str(), u.force.c_str());
  std::fprintf(file_, "Layout: docs/output-files.md of OpenMSS, \"The tabular output file\"\n");
  if (std::fflush(file_) != 0 || std::ferror(file_)) {
    fail("header");
    if (error) *error = error_;
    std::fclose(file_);
    file_ = nullptr;
    return false;
  }
  return true;
}

void TabularFileWriter::beginAnalysis() {
  if (file_ != nullptr) writePage();
  newBlock_ = true;
}

bool TabularFileWriter::writeStep(const OutputFrame& frame, const model::Model& m,
                                  const model::ResultsSettings& settings) {
  if (file_ == nullptr || !error_.empty()) return false;
  if (newBlock_ || frame.kind != blockKind_) {
    if (!writePage()) return false;
    char number[16];
    std::snprintf(number, sizeof number, "_%03d", ++kindCounts_[static_cast<int>(frame.kind)]);
    blockName_ = std::string(outputKindName(frame.kind)) + number;
    blockKind_ = frame.kind;
    newBlock_ = false;
    page_ = 0;
    blockRows_ = 0;
  }
  if (times_.empty()) tables_ = tabularTables(m, settings);
  if (frame.requests.size() != tables_.size()) {
    errno = 0;
    return fail("the step at time " + requestFileField(frame.time) + " has " +
                std::to_string(frame.requests.size()) + " requests, the page " +
                std::to_string(tables_.size()));
  }
  times_.push_back(frame.time);
  rows_.push_back(frame.requests);
  return times_.size() < kPageRows || writePage();
}

bool TabularFileWriter::writePage() {
  if (times_.empty()) return error_.empty();
  ++page_;
  std::fprintf(file_, "\n%s\n Analysis %s, page %d: output times %ld to %ld\n%s\n", kRule,
               blockName_.c_str(), page_, blockRows_ + 1,
               blockRows_ + static_cast<long>(times_.size()), kRule);
  for (std::size_t r = 0; r < tables_.size(); ++r) {
    const TabularTable& t = tables_[r];
    std::fprintf(file_, "\n REQUEST/%ld  %s", t.id, t.type.c_str());
    if (t.type != "EXPRESSIONS")
      std::fprintf(file_, "  I=%ld  J=%ld  RM=%ld", t.iMarker, t.jMarker, t.rmMarker);
    std::fprintf(file_, "\n Comment: %s\n", t.comment.c_str());
    std::fprintf(file_, "%14s", "TIME");
    for (const std::string& n : t.names) std::fprintf(file_, " %13s", n.c_str());
    std::fprintf(file_, "\n%14s", timeUnit_.c_str());
    for (const std::string& u : t.units) std::fprintf(file_, " %13s", u.c_str());
    std::fputc('\n', file_);
    for (std::size_t k = 0; k < times_.size(); ++k) {
      std::fprintf(file_, " %s", requestFileField(times_[k]).c_str());
      for (int c : t.columns) {
        double v = rows_[k][r][static_cast<std::size_t>(c)];
        if (t.anglesInDegrees && c >= 5) v *= kRadToDeg;
        std::fprintf(file_, " %s", requestFileField(v).c_str());
      }
      std::fputc('\n', file_);
    }
  }
  blockRows_ += static_cast<long>(times_.size());
  times_.clear();
  rows_.clear();
  errno = 0;
  if (std::fflush(file_) != 0 || std::ferror(file_)) return fail("page");
  return true;
}

void TabularFileWriter::close() {
  if (file_ == nullptr) return;
  writePage();
  std::fprintf(file_, "\n%s\n End of the run: %s\n", kRule,
               runFailed_ || !error_.empty() ? "Failed" : "Successful");
  if (std::fclose(file_) != 0) fail("close");
  file_ = nullptr;
}

}  // namespace openmss::output
