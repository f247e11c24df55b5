#include "analysis/save_file.hpp"

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace openmss::analysis {
namespace {

constexpr std::string_view kMagic = "OPENMSS SAVE FILE";

// FNV-1a, 64 bits: a checksum against damage, not against tampering (docs/save-format.md).
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::string hex64(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

// Exact and portable: C99 hexadecimal floats ("%a") read back by strtod bit for bit.
std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

class Writer {
 public:
  void line(const std::string& s) { out_ += s + "\n"; }
  void text(const std::string& tag, const std::string& s) {
    line("text " + tag + " " + std::to_string(s.size()));
    out_ += s + "\n";
  }
  void vector(const std::string& tag, const double* v, std::size_t n) {
    line("vector " + tag + " " + std::to_string(n));
    for (std::size_t k = 0; k < n; ++k) line(number(v[k]));
  }
  void vector(const std::string& tag, const std::vector<double>& v) {
    vector(tag, v.data(), v.size());
  }
  std::string& out() { return out_; }

 private:
  std::string out_;
};

// A parse failure at a line of the file.
struct ParseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}
  int lineNumber() const { return line_; }
  bool atEnd() const { return pos_ >= text_.size(); }

  std::string_view line() {
    if (atEnd()) fail("the file ends early (truncated)");
    ++line_;
    const std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) fail("the last line is incomplete (truncated)");
    const std::string_view l = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return l;
  }
  // "<tag> <words...>": the words after the expected tag.
  std::vector<std::string> fields(std::string_view tag) {
    const std::string_view l = line();
    std::vector<std::string> words;
    std::size_t p = 0;
    while (p < l.size()) {
      const std::size_t q = l.find(' ', p);
      words.emplace_back(l.substr(p, q == std::string_view::npos ? l.size() - p : q - p));
      if (q == std::string_view::npos) break;
      p = q + 1;
    }
    if (words.empty() || words[0] != tag)
      fail("expected \"" + std::string(tag) + "\", found \"" + std::string(l.substr(0, 40)) + "\"");
    words.erase(words.begin());
    return words;
  }
  std::vector<std::string> fields(std::string_view tag, std::size_t count) {
    auto w = fields(tag);
    if (w.size() != count)
      fail("\"" + std::string(tag) + "\" needs " + std::to_string(count) + " value(s)");
    return w;
  }
  double real(const std::string& s) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
      fail("\"" + s + "\" is not a number");
    return v;
  }
  long integer(const std::string& s) {
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
      fail("\"" + s + "\" is not an integer");
    return v;
  }
  std::size_t count(const std::string& s) {
    const long n = integer(s);
    // A count larger than the bytes left is damage, not data (no huge allocation).
    if (n < 0 || static_cast<std::size_t>(n) > text_.size() - pos_ + 1)
      fail("the count " + s + " does not fit in the file");
    return static_cast<std::size_t>(n);
  }
  std::string text(std::string_view tag) {
    const auto w = fields("text", 2);
    if (w[0] != tag) fail("expected text " + std::string(tag) + ", found text " + w[0]);
    const std::size_t n = count(w[1]);
    if (pos_ + n + 1 > text_.size()) fail("the text ends early (truncated)");
    const std::string s(text_.substr(pos_, n));
    for (const char c : s) line_ += c == '\n' ? 1 : 0;
    pos_ += n;
    if (text_[pos_] != '\n') fail("the text is not followed by a line end");
    ++pos_;
    ++line_;
    return s;
  }
  std::vector<double> vector(std::string_view tag) {
    const auto w = fields("vector", 2);
    if (w[0] != tag) fail("expected vector " + std::string(tag) + ", found vector " + w[0]);
    std::vector<double> v(count(w[1]));
    for (double& x : v) x = real(std::string(line()));
    return v;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError("line " + std::to_string(line_) + ": " + message);
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

std::string toHex(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (const unsigned char c : bytes) {
    out += digits[c >> 4];
    out += digits[c & 15];
  }
  return out;
}

std::string fromHex(Reader& r, const std::string& hex) {
  const auto value = [&](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    r.fail("user-data holds a character that is not a hexadecimal digit");
    return 0;
  };
  if (hex.size() % 2 != 0) r.fail("user-data has an odd number of hexadecimal digits");
  std::string out;
  for (std::size_t k = 0; k < hex.size(); k += 2)
    out += static_cast<char>(value(hex[k]) * 16 + value(hex[k + 1]));
  return out;
}

void readBody(Reader& r, SaveFile& f) {
  const auto kind = r.fields("kind", 1);
  if (kind[0] != "STATES" && kind[0] != "SYSTEM") r.fail("unknown kind " + kind[0]);
  f.system = kind[0] == "SYSTEM";
  f.fingerprint = r.fields("fingerprint", 1)[0];
  f.t = r.real(r.fields("time", 1)[0]);
  const auto flags = r.fields("flags", 2);
  f.initialized = r.integer(flags[0]) != 0;
  f.halted = r.integer(flags[1]) != 0;
  const auto s = r.fields("summary", 6);
  f.summary.time = r.real(s[0]);
  f.summary.steps = r.integer(s[1]);
  f.summary.outputSteps = r.integer(s[2]);
  f.summary.jacobians = r.integer(s[3]);
  f.summary.residuals = r.integer(s[4]);
  f.summary.kinematicIterations = r.integer(s[5]);
  f.summary.analysis = r.text("analysis");
  const std::vector<double> y = r.vector("y"), yp = r.vector("yp");
  if (y.size() != yp.size()) r.fail("y and yp differ in size");
  f.y = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
  f.yp = Eigen::Map<const Eigen::VectorXd>(yp.data(), static_cast<Eigen::Index>(yp.size()));
  mechanics::ExpressionRunState::Snapshot& e = f.expressions;
  const auto st = r.fields("status", 5);
  e.status.mode = static_cast<model::AnalysisMode>(r.integer(st[0]));
  e.status.stepSize = r.real(st[1]);
  e.status.order = static_cast<int>(r.integer(st[2]));
  e.status.jacobianEvaluations = r.integer(st[3]);
  e.status.residualEvaluations = r.integer(st[4]);
  e.angleReferences = r.vector("angles");
  e.delays.resize(r.count(r.fields("delays", 1)[0]));
  for (auto& d : e.delays) {
    const std::vector<double> v = r.vector("delay");
    if (v.size() % 2 != 0) r.fail("a DELAY history needs (time, value) pairs");
    for (std::size_t k = 0; k < v.size(); k += 2) d.emplace_back(v[k], v[k + 1]);
  }
  e.coupled = r.vector("coupled");
  e.sensorValues = r.vector("sensors");
  e.gseLastSample = r.vector("gse-last-sample");
  e.gseDiscrete.resize(r.count(r.fields("gse-discrete", 1)[0]));
  for (auto& xd : e.gseDiscrete) xd = r.vector("xd");
  e.frictionAnchors = r.vector("friction-anchors");
  e.curveParameters = r.vector("curve-parameters");
  if (f.system) {
    f.datasetPath = r.text("dataset-path");
    f.datasetText = r.text("dataset");
    f.commands.resize(r.count(r.fields("commands", 1)[0]));
    for (auto& c : f.commands) c = r.text("command");
  }
  f.userData = fromHex(r, r.text("user-data"));
  r.fields("end", 0);
}

}  // namespace

std::string saveBuildId() {
  // The version and the compiler that built it (its version string, blanks made '_').
  std::string id = std::string("openmss-") + OPENMSS_VERSION + "/" + __VERSION__;
  for (char& c : id)
    if (c == ' ' || c == '\n') c = '_';
  return id;
}

std::string modelFingerprint(const mechanics::MultibodySystem& system,
                             const mechanics::ExpressionRunState& run) {
  const model::Model& m = system.model();
  const mechanics::StateLayout& l = system.layout();
  std::string d = "y " + std::to_string(l.size()) + " bodies " + std::to_string(l.bodies) +
                  " constraints " + std::to_string(system.constraints().size()) + " udiff " +
                  std::to_string(l.userDifferential) + " ualg " + std::to_string(l.userAlgebraic);
  auto ids = [&d](const char* kind, const auto& elements) {
    d += std::string(" ") + kind;
    for (const auto& e : elements) d += " " + std::to_string(e.id);
  };
  ids("PART", m.parts);
  ids("MARKER", m.markers);
  ids("JOINT", m.joints);
  ids("MOTION", m.motions);
  ids("JPRIM", m.jprims);
  ids("COUPLER", m.couplers);
  ids("GEAR", m.gears);
  ids("GCON", m.gcons);
  if (!m.ucons.empty()) ids("UCON", m.ucons);  // absent otherwise: older save files still match
  ids("SFORCE", m.sforces);
  ids("VARIABLE", m.variables);
  ids("DIFF", m.diffs);
  ids("GSE", m.generalStates);
  ids("SENSOR", m.sensors);
  ids("REQUEST", m.requests);
  const auto snap = run.snapshot();
  d += " angles " + std::to_string(snap.angleReferences.size()) + " delays " +
       std::to_string(snap.delays.size()) + " coupled " + std::to_string(snap.coupled.size()) +
       " curve-parameters " + std::to_string(snap.curveParameters.size());
  for (const auto& xd : snap.gseDiscrete) d += " xd " + std::to_string(xd.size());
  return hex64(fnv1a(d));
}

SaveFile captureRunState(const RunState& state, const mechanics::MultibodySystem& system) {
  SaveFile f;
  f.build = saveBuildId();
  f.fingerprint = modelFingerprint(system, *state.expressions);
  f.t = state.t;
  f.y = state.y;
  f.yp = state.yp;
  f.initialized = state.initialized;
  f.halted = state.halted;
  f.summary = state.summary;
  f.expressions = state.expressions->snapshot();
  return f;
}

bool restoreRunState(const SaveFile& file, const mechanics::MultibodySystem& system,
                     RunState& state, std::string* error) {
  const std::string here = modelFingerprint(system, *state.expressions);
  if (file.fingerprint != here) {
    *error = "the states belong to another model (model fingerprint " + file.fingerprint +
             ", this model's is " + here + ")";
    return false;
  }
  if (file.y.size() != state.y.size()) {
    *error = "the file holds " + std::to_string(file.y.size()) + " state values, this model " +
             std::to_string(state.y.size());
    return false;
  }
  // The expression history first: it is the only part that can still refuse.
  if (!state.expressions->restore(file.expressions)) {
    *error = "the file's run history (angles, DELAY, sensors, GSE) does not fit this model";
    return false;
  }
  state.t = file.t;
  state.y = file.y;
  state.yp = file.yp;
  state.initialized = file.initialized;
  state.halted = file.halted;
  state.summary = file.summary;
  return true;
}

std::string encodeSaveFile(const SaveFile& f) {
  Writer w;
  w.line(std::string(kMagic));
  w.line("format " + std::to_string(kSaveFormatVersion));
  w.line("build " + f.build);
  w.line(std::string("kind ") + (f.system ? "SYSTEM" : "STATES"));
  w.line("fingerprint " + f.fingerprint);
  w.line("time " + number(f.t));
  w.line("flags " + std::to_string(f.initialized ? 1 : 0) + " " + std::to_string(f.halted ? 1 : 0));
  const RunSummary& s = f.summary;
  w.line("summary " + number(s.time) + " " + std::to_string(s.steps) + " " +
         std::to_string(s.outputSteps) + " " + std::to_string(s.jacobians) + " " +
         std::to_string(s.residuals) + " " + std::to_string(s.kinematicIterations));
  w.text("analysis", s.analysis);
  w.vector("y", f.y.data(), static_cast<std::size_t>(f.y.size()));
  w.vector("yp", f.yp.data(), static_cast<std::size_t>(f.yp.size()));
  const mechanics::ExpressionRunState::Snapshot& e = f.expressions;
  w.line("status " + std::to_string(static_cast<int>(e.status.mode)) + " " +
         number(e.status.stepSize) + " " + std::to_string(e.status.order) + " " +
         std::to_string(e.status.jacobianEvaluations) + " " +
         std::to_string(e.status.residualEvaluations));
  w.vector("angles", e.angleReferences);
  w.line("delays " + std::to_string(e.delays.size()));
  for (const auto& d : e.delays) {
    std::vector<double> flat;
    for (const auto& [t, v] : d) {
      flat.push_back(t);
      flat.push_back(v);
    }
    w.vector("delay", flat);
  }
  w.vector("coupled", e.coupled);
  w.vector("sensors", e.sensorValues);
  w.vector("gse-last-sample", e.gseLastSample);
  w.line("gse-discrete " + std::to_string(e.gseDiscrete.size()));
  for (const auto& xd : e.gseDiscrete) w.vector("xd", xd);
  w.vector("friction-anchors", e.frictionAnchors);
  w.vector("curve-parameters", e.curveParameters);
  if (f.system) {
    w.text("dataset-path", f.datasetPath);
    w.text("dataset", f.datasetText);
    w.line("commands " + std::to_string(f.commands.size()));
    for (const auto& c : f.commands) w.text("command", c);
  }
  w.text("user-data", toHex(f.userData));  // SAVSUB's bytes, two hexadecimal digits each
  w.line("end");
  w.line("checksum " + hex64(fnv1a(w.out())));
  return w.out();
}

std::optional<SaveFile> decodeSaveFile(std::string_view text, std::string* error) {
  Reader r(text);
  try {
    if (r.line() != kMagic) r.fail("not an OpenMSS save file (no \"" + std::string(kMagic) + "\")");
    const auto format = r.fields("format", 1);
    if (r.integer(format[0]) != kSaveFormatVersion)
      r.fail("save-file format " + format[0] + "; this build reads format " +
             std::to_string(kSaveFormatVersion));
    // The checksum covers every byte before its own line; a file cut short has none.
    const std::size_t at = text.rfind("\nchecksum ");
    if (at == std::string_view::npos) {
      int last = 1;  // the line the file ends in
      for (const char c : text) last += c == '\n' ? 1 : 0;
      throw ParseError("line " + std::to_string(last) +
                       ": no checksum line: the file is truncated");
    }
    const std::string_view body = text.substr(0, at + 1);
    std::string_view sum = text.substr(at + 10);
    if (!sum.empty() && sum.back() == '\n') sum.remove_suffix(1);
    int checksumLine = 1;
    for (const char c : body) checksumLine += c == '\n' ? 1 : 0;
    if (sum != hex64(fnv1a(body)))
      throw ParseError("line " + std::to_string(checksumLine) +
                       ": checksum mismatch: the file is damaged (checksum " + std::string(sum) +
                       ", contents give " + hex64(fnv1a(body)) + ")");
    SaveFile f;
    f.build = r.fields("build", 1)[0];
    if (f.build != saveBuildId())
      r.fail("written by " + f.build + ", this is " + saveBuildId() +
             ": another build may continue differently");
    readBody(r, f);
    if (r.lineNumber() + 1 != checksumLine) r.fail("unexpected text after \"end\"");
    return f;
  } catch (const ParseError& e) {
    *error = e.what();
    return std::nullopt;
  }
}

}  // namespace openmss::analysis
