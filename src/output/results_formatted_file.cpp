#include "output/results_formatted_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "common/rotation.hpp"
#include "output/request_header.hpp"

namespace openmss::output {
namespace {

// The element maps ADAMS 10's layout lists after the rigid parts map, in its order. OpenMSS
// writes parts only, so every one of them is empty (docs/output-files.md).
constexpr const char* kEmptyMaps[] = {"POINT MASS MAP",
                                      "FLEXIBLE BODY MAP",
                                      "USER DIFFERENTIAL EQUATIONS MAP",
                                      "JOINTS MAP",
                                      "JOINT PRIMITIVES MAP",
                                      "MOTION GENERATORS MAP",
                                      "GEARS MAP",
                                      "COUPLERS MAP",
                                      "USER CONSTRAINTS MAP",
                                      "SFORCES MAP",
                                      "SPRINGDAMPER FORCES MAP",
                                      "BUSHINGS MAP",
                                      "BEAMS MAP",
                                      "FIELDS MAP",
                                      "USER DEFINED RESULTS MAP",
                                      "VARIABLE MAP",
                                      "PINPUT MAP",
                                      "POUTPUT MAP",
                                      "TFSISO MAP",
                                      "LSE MAP",
                                      "GSE MAP",
                                      "PTCV MAP",
                                      "CVCV MAP",
                                      "NFORCES MAP",
                                      "VFORCES MAP",
                                      "VTORQUES MAP",
                                      "GFORCES MAP",
                                      "FRICTIONS MAP",
                                      "FLOATING MARKERS MAP"};

constexpr std::size_t kFieldWidth = 12;

// A block header: the name padded to 40 columns, the count of the lines after it in 8.
void header(std::FILE* f, const char* name, long lines) {
  std::fprintf(f, "%-40s%8ld\n", name, lines);
}

// "%12.5E", or "%12.4E" when a three-digit exponent would make a negative value 13 characters
// long: every field keeps its 12 columns, which is how the layout is read.
void value(std::FILE* f, double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.5E", v);
  if (std::strlen(text) > kFieldWidth) std::snprintf(text, sizeof text, "%.4E", v);
  std::fprintf(f, "%12s", text);
}

// FORTRAN's E23.15 style, a mantissa in [0.1, 1): 1 gives "0.100000000000000E+01".
std::string fortranE15(double v) {
  if (v == 0.0) return "0.000000000000000E+00";
  char text[40];
  std::snprintf(text, sizeof text, "%.14E", std::fabs(v));  // d.dddddddddddddd E+xx
  const int exponent = std::atoi(std::strchr(text, 'E') + 1) + 1;
  std::string digits = std::string(1, text[0]) + std::string(text + 2, 14);
  std::snprintf(text, sizeof text, "%s0.%sE%+03d", v < 0 ? "-" : "", digits.c_str(), exponent);
  return text;
}

const char* typeName(OutputKind kind) {
  switch (kind) {
    case OutputKind::InitialConditions:
      return "INITIAL_CONDITIONS";
    case OutputKind::Static:
      return "STATIC";
    case OutputKind::Kinematic:
      return "KINEMATIC";
    case OutputKind::Dynamic:
      break;
  }
  return "DYNAMIC";
}

}  // namespace

FormattedResultsWriter::~FormattedResultsWriter() { close(); }

bool FormattedResultsWriter::fail(const std::string& what) {
  if (error_.empty())
    error_ = "cannot write the results file " + path_ + " (" + what + ")" +
             (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string());
  return false;
}

bool FormattedResultsWriter::open(const std::string& path, const model::Model& m,
                                  const model::ResultsSettings& rs, const std::string& modelName,
                                  std::string* error) {
  close();
  error_.clear();
  path_ = path;
  blocks_ = 0;
  velocities_ = !rs.noVelocities;
  accelerations_ = !rs.noAccelerations;
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    if (error) *error = "cannot create the results file " + path + ": " + std::strerror(errno);
    return false;
  }
  std::FILE* f = file_;
  const RequestFileHeader h = requestFileHeader(m, nullptr);
  std::string title = m.title.substr(0, m.title.find_last_not_of(" \t\r\n") + 1);
  header(f, "FILE TYPE AND SOURCE", 6);
  std::fprintf(f, "ADAMS RESULTS FILE       %s %s\n", h.unitsToken.c_str(),
               fortranE15(h.lengthScale).c_str());
  std::fprintf(f, "ADAMS VERSION - 10.0                    A.RE7\n");
  std::fprintf(f, "OpenMSS\nUnknown\n");
  std::fprintf(f, "Sat Jan  1 00:00:00 2000\n!\n");  // fixed: bit-identical runs (docs)
  header(f, "DATA SET TITLE", 3);
  std::fprintf(f, "%s\n\n!\n", title.c_str());
  header(f, "RESULTS TITLE", 3);
  std::fprintf(f, "%s\n\n!\n", rs.comment.c_str());
  header(f, "NUMBER OF ANALYSIS BLOCKS", 2);
  countOffset_ = std::ftell(f);
  std::vector<long> ids;
  for (const model::Part& p : m.parts)
    if (p.body >= 0) ids.push_back(p.id);
  parts_ = ids.size();
  const long n = static_cast<long>(parts_);
  // The second number is the one MBDyn writes (123 + 3 x parts); its meaning is undocumented.
  std::fprintf(f, "%8ld%8ld\n!\n", 0L, 123 + 3 * n);
  header(f, "RIGID PARTS MAP", 2 + n);
  std::fprintf(f, "%8ldYES%s%s\n", n, velocities_ ? "YES" : "NO ", accelerations_ ? "YES" : "NO ");
  // Each part's lines in an analysis block (1-based, the block's own line first): positions
  // from line 5, then the velocities and the accelerations of every part.
  const long velocityLine = 5 + n, accelerationLine = 5 + (velocities_ ? 2 : 1) * n;
  for (long i = 0; i < n; ++i)
    std::fprintf(f, "%20ld%8ld%8ld%8ld\n", ids[static_cast<std::size_t>(i)], 5 + i,
                 velocityLine + i, accelerationLine + i);
  std::fprintf(f, "!\n");
  for (const char* map : kEmptyMaps) {
    header(f, map, 2);
    const bool masses =
        std::strcmp(map, "POINT MASS MAP") == 0 || std::strcmp(map, "FLEXIBLE BODY MAP") == 0;
    std::fprintf(f, "%8d%s\n!\n", 0, masses ? "YESNO NO" : "NO");
  }
  // As MBDyn writes it; the meaning of these numbers is undocumented.
  header(f, "MODE SHAPES MAP", 8);
  std::fprintf(f, "%8d%8d\n", 12, 1);
  for (int k = 0; k < 6; ++k) std::fprintf(f, "%8d%8d\n", 0, 13);
  std::fprintf(f, "!\n");
  header(f, "TIRES MAP", 2);
  std::fprintf(f, "%8dNO\n!\n", 0);
  header(f, "NAME MAP", 2 + 2 * n);
  std::fprintf(f, "%8ldYES\n", n);
  for (long id : ids)
    std::fprintf(f, "%20ldRIGID PART                 1\n.%s.PART_%ld\n", id, modelName.c_str(), id);
  std::fprintf(f, "!\n");
  errno = 0;
  if (countOffset_ < 0 || std::fflush(f) != 0 || std::ferror(f)) {
    fail("header");
    if (error) *error = error_;
    std::fclose(file_);
    file_ = nullptr;
    return false;
  }
  return true;
}

bool FormattedResultsWriter::writeStep(const OutputFrame& frame) {
  if (file_ == nullptr || !error_.empty()) return false;
  if (frame.parts.size() != parts_) {
    errno = 0;
    return fail("a step has " + std::to_string(frame.parts.size()) + " parts, the map " +
                std::to_string(parts_));
  }
  std::FILE* f = file_;
  const long n = static_cast<long>(parts_);
  header(f, "ANALYSIS OUTPUT BLOCK",
         5 + n * (1 + (velocities_ ? 1 : 0) + (accelerations_ ? 1 : 0)));
  std::fprintf(f, "%8ld%-20sOpenMSS\n", ++blocks_, typeName(frame.kind));
  value(f, frame.time);
  std::fprintf(f, "\n\n\n");
  for (const PartOutput& p : frame.parts) {
    // Euler parameters of the body frame in ground, e0 >= 0 (common/rotation.hpp).
    const Eigen::Vector4d e =
        quaternionFromMatrix(matrixFromEuler313(p.angles(0), p.angles(1), p.angles(2)));
    for (int k = 0; k < 3; ++k) value(f, p.position(k));
    for (int k = 0; k < 4; ++k) value(f, e(k));
    std::fputc('\n', f);
  }
  if (velocities_)
    for (const PartOutput& p : frame.parts) {
      for (int k = 0; k < 3; ++k) value(f, p.velocity(k));
      for (int k = 0; k < 3; ++k) value(f, p.angularVelocity(k));
      std::fputc('\n', f);
    }
  if (accelerations_)
    for (const PartOutput& p : frame.parts) {
      for (int k = 0; k < 3; ++k) value(f, p.acceleration(k));
      for (int k = 0; k < 3; ++k) value(f, p.angularAcceleration(k));
      std::fputc('\n', f);
    }
  std::fprintf(f, "!\n");
  errno = 0;
  if (std::fflush(f) != 0 || std::ferror(f)) return fail("step");
  return true;
}

void FormattedResultsWriter::close() {
  if (file_ == nullptr) return;
  // The block count of the header, written in its 8 columns now that it is known.
  if (std::fseek(file_, countOffset_, SEEK_SET) == 0) std::fprintf(file_, "%8ld", blocks_);
  if (std::fclose(file_) != 0) fail("close");
  file_ = nullptr;
}

namespace {

std::vector<double> fields(const std::string& line) {
  std::vector<double> out;
  for (std::size_t at = 0; at + kFieldWidth <= line.size(); at += kFieldWidth)
    out.push_back(std::strtod(line.substr(at, kFieldWidth).c_str(), nullptr));
  return out;
}

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(" \r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

bool readFormattedResultsFile(const std::string& path, FormattedResultsData& d,
                              std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = "cannot open " + path;
    return false;
  }
  d = FormattedResultsData{};
  bool velocities = false, accelerations = false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 48) {
      if (error) *error = "not a block header: \"" + line + "\"";
      return false;
    }
    const std::string name = trimmed(line.substr(0, 40));
    const long count = std::atol(line.substr(40).c_str());
    std::vector<std::string> lines;
    for (long k = 0; k < count && std::getline(in, line); ++k) lines.push_back(line);
    if (count <= 0 || static_cast<long>(lines.size()) != count || lines.back().rfind('!', 0) != 0) {
      if (error) *error = "block " + name + " is incomplete";
      return false;
    }
    if (name == "FILE TYPE AND SOURCE") {
      if (lines[0].size() > 25) d.unitsToken = trimmed(lines[0].substr(25, 12));
    } else if (name == "DATA SET TITLE") {
      d.title = lines[0];
    } else if (name == "NUMBER OF ANALYSIS BLOCKS") {
      d.declaredBlocks = std::atol(lines[0].c_str());
    } else if (name == "RIGID PARTS MAP") {
      lines[0].resize(17, ' ');
      velocities = lines[0].substr(11, 3) == "YES";
      accelerations = lines[0].substr(14, 3) == "YES";
      for (std::size_t k = 1; k + 1 < lines.size(); ++k)
        d.partIds.push_back(std::atol(lines[k].substr(0, 20).c_str()));
    } else if (name == "ANALYSIS OUTPUT BLOCK") {
      FormattedResultsBlock b;
      if (lines.size() < 5) {
        if (error) *error = "an analysis output block is too short";
        return false;
      }
      lines[0].resize(28, ' ');
      b.type = trimmed(lines[0].substr(8, 20));
      b.time = std::strtod(lines[1].c_str(), nullptr);
      std::size_t k = 4;
      const std::size_t n = d.partIds.size();
      for (std::size_t p = 0; p < n && k < lines.size(); ++p)
        b.positions.push_back(fields(lines[k++]));
      if (velocities)
        for (std::size_t p = 0; p < n && k < lines.size(); ++p)
          b.velocities.push_back(fields(lines[k++]));
      if (accelerations)
        for (std::size_t p = 0; p < n && k < lines.size(); ++p)
          b.accelerations.push_back(fields(lines[k++]));
      d.blocks.push_back(std::move(b));
    }
  }
  return true;
}

}  // namespace openmss::output
