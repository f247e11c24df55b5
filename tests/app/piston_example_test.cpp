// End-to-end check of the bundled example examples/piston: runs
//   openmss run examples/piston/piston.acf --outdir <fresh temporary folder>
// once, reads the piston.req it writes, and compares the piston requests with the
// closed-form slider-crank solution derived in docs/example-piston.md.
//
// The model has zero degrees of freedom (Gruebler: 3 x 6 - (5 + 3 + 4 + 5) - 1 = 0), so
// positions, velocities and accelerations follow from the crank motion alone and can be
// written down exactly; forces do not influence them.
//
// The .req file is read by a small parser local to this test on purpose: the test must not
// trust the project's own reader to check the project's own writer.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// Closed form (docs/example-piston.md)
// ---------------------------------------------------------------------------------------

constexpr double kCrankRadius = 2.0;                // r, inch
constexpr double kRodLength = 8.0;                  // L, inch
constexpr double kOmega = 2.0 * std::numbers::pi;   // POLY(TIME,0,0,360D): one rev per second
constexpr double kPinToCm = 1.0;                    // piston CM (x=11) minus pin (x=10) at t=0
constexpr double kHeadMinusPinAtGap = 11.0;         // DM(409,109) = 11 - x_B

struct PinMotion {
  double x;  // piston-pin position along global X
  double v;  // its velocity
  double a;  // its acceleration
};

// x_B = r cos(theta) + sqrt(L^2 - r^2 sin^2(theta)) and its exact time derivatives,
// theta = omega t with omega constant.
PinMotion pistonPin(double t) {
  const double r = kCrankRadius;
  const double L = kRodLength;
  const double theta = kOmega * t;
  const double s = std::sin(theta);
  const double c = std::cos(theta);
  const double d = std::sqrt(L * L - r * r * s * s);
  PinMotion m{};
  m.x = r * c + d;
  m.v = -kOmega * (r * s + r * r * s * c / d);
  m.a = -kOmega * kOmega *
        (r * c + r * r * (c * c - s * s) / d + r * r * r * r * s * s * c * c / (d * d * d));
  return m;
}

double gasForce(double t) {
  const double dm = kHeadMinusPinAtGap - pistonPin(t).x;
  return 1422.0 * std::pow(dm, -1.4) - 185.4;
}

// ---------------------------------------------------------------------------------------
// Minimal .req reader
// Layout (as real ADAMS writes it, see
// /work/shared/validation/adams-joints/Revolute_Case01/test_Revolute_Case01_ADAMS.req):
//   3 header lines; line 3 starts with the number of requests N;
//   per request two directory lines: "id type I J words", then the comment (may be empty);
//   per output time one line holding the time, then N lines of six values
//   (columns 2,3,4,6,7,8 of the request, "%13.5E" each; displacement angles in degrees).
// ---------------------------------------------------------------------------------------

struct RequestFile {
  std::vector<long> ids;
  std::vector<int> types;
  std::vector<double> times;
  std::vector<std::vector<std::array<double, 6>>> rows;  // rows[step][request index]

  int indexOf(long id) const {
    const auto it = std::find(ids.begin(), ids.end(), id);
    return it == ids.end() ? -1 : static_cast<int>(it - ids.begin());
  }
};

std::vector<std::string> splitWhitespace(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  std::string token;
  while (in >> token) tokens.push_back(token);
  return tokens;
}

bool toDouble(const std::string& text, double* value) {
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && std::isfinite(*value);
}

// Returns an empty string on success, otherwise what is wrong (with the line number).
std::string readRequestFile(const fs::path& path, RequestFile* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open " + path.string();
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  auto where = [&](std::size_t i) { return path.string() + ":" + std::to_string(i + 1) + ": "; };

  if (lines.size() < 3) return path.string() + ": fewer than 3 header lines";
  const auto countTokens = splitWhitespace(lines[2]);
  double countValue = 0;
  if (countTokens.empty() || !toDouble(countTokens[0], &countValue) || countValue < 0)
    return where(2) + "expected the number of requests";
  const auto count = static_cast<std::size_t>(countValue);
  if (lines.size() < 3 + 2 * count) return path.string() + ": request directory is cut short";
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = 3 + 2 * k;
    const auto tokens = splitWhitespace(lines[i]);
    double id = 0, type = 0;
    if (tokens.size() < 2 || !toDouble(tokens[0], &id) || !toDouble(tokens[1], &type))
      return where(i) + "expected a directory entry 'id type I J words'";
    out->ids.push_back(static_cast<long>(id));
    out->types.push_back(static_cast<int>(type));
  }

  std::size_t i = 3 + 2 * count;
  while (i < lines.size()) {
    const auto timeTokens = splitWhitespace(lines[i]);
    if (timeTokens.empty()) {  // tolerate blank lines between records (e.g. at the end)
      ++i;
      continue;
    }
    double time = 0;
    if (timeTokens.size() != 1 || !toDouble(timeTokens[0], &time))
      return where(i) + "expected a time record (one value)";
    if (i + count >= lines.size()) return where(i) + "output step cut short";
    std::vector<std::array<double, 6>> step(count);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t j = i + 1 + k;
      const auto tokens = splitWhitespace(lines[j]);
      if (tokens.size() != 6) return where(j) + "expected six values";
      for (std::size_t c = 0; c < 6; ++c)
        if (!toDouble(tokens[c], &step[k][c])) return where(j) + "bad number '" + tokens[c] + "'";
    }
    out->times.push_back(time);
    out->rows.push_back(std::move(step));
    i += 1 + count;
  }
  return {};
}

// ---------------------------------------------------------------------------------------
// Running the example once for the whole suite
// ---------------------------------------------------------------------------------------

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += (ch == '\'') ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

std::string tailOf(const fs::path& path, std::size_t maxChars) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  return text.size() <= maxChars ? text : "..." + text.substr(text.size() - maxChars);
}

constexpr double kDtOut = 0.01;  // simulate/transient, end=2.0, dtout=0.01
constexpr int kSteps = 201;      // t = 0, 0.01, ..., 2.0

// Allowed error, as a fraction of each column's range over the run. The .req prints six
// significant digits ("%13.5E"), i.e. a rounding error of up to 5e-6 of the printed value:
// 5.5e-5 in on the CM position (range 4 in), 6.5e-5 in/s on the velocity (range 25.9 in/s),
// 4.9e-4 in/s^2 on the acceleration (range 157.9 in/s^2) -- 1.4e-5, 2.5e-6 and 3.1e-6 of the
// ranges. 1e-4 therefore sits a few times above what printing alone costs, leaving room for
// the solver's constraint and integration tolerances (a rod 0.01 in too long already fails);
// it is also the bound the validation data applies to real ADAMS output.
constexpr double kRelativeToRange = 1e-4;

class PistonExample : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    runError_ = new std::string;
    req_ = new RequestFile;
    outDir_ = new fs::path;

    std::string pattern = (fs::temp_directory_path() / "openmss_piston_XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (mkdtemp(buffer.data()) == nullptr) {
      *runError_ = "cannot create a temporary output folder from " + pattern;
      return;
    }
    *outDir_ = buffer.data();

    const fs::path acf = fs::path(OPENMSS_SOURCE_DIR) / "examples" / "piston" / "piston.acf";
    const fs::path console = *outDir_ / "console.txt";
    const std::string command = shellQuote(OPENMSS_BINARY) + " run " + shellQuote(acf.string()) +
                                " --outdir " + shellQuote(outDir_->string()) + " > " +
                                shellQuote(console.string()) + " 2>&1";
    const int status = std::system(command.c_str());
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      const int code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
      *runError_ = "command failed (exit status " + std::to_string(code) + "): " + command +
                   "\n--- output ---\n" + tailOf(console, 4000);
      return;
    }
    const std::string parseError = readRequestFile(*outDir_ / "piston.req", req_);
    if (!parseError.empty()) *runError_ = parseError;
  }

  static void TearDownTestSuite() {
    // Keep the output for inspection when something failed; clean up otherwise.
    const auto* suite = ::testing::UnitTest::GetInstance()->current_test_suite();
    if (suite != nullptr && suite->Passed() && !outDir_->empty()) {
      std::error_code ignored;
      fs::remove_all(*outDir_, ignored);
    }
    delete runError_;
    delete req_;
    delete outDir_;
  }

  void SetUp() override {
    ASSERT_TRUE(runError_->empty()) << *runError_;
    ASSERT_EQ(req_->times.size(), static_cast<std::size_t>(kSteps))
        << "expected output at t = 0, 0.01, ..., 2.0 s in " << outDir_->string();
    for (int k = 0; k < kSteps; ++k)
      ASSERT_NEAR(req_->times[k], k * kDtOut, 1e-6) << "output time record " << k;
  }

  static std::string* runError_;
  static RequestFile* req_;
  static fs::path* outDir_;
};

std::string* PistonExample::runError_ = nullptr;
RequestFile* PistonExample::req_ = nullptr;
fs::path* PistonExample::outDir_ = nullptr;

struct Column {
  const char* name;
  std::function<double(double)> exact;  // exact value at time t
  // Scale of the error bound. 0: the range of `exact` over the run. Columns whose exact value
  // is constant (0, or the fixed piston angles) have no range and get an explicit scale.
  double scale = 0.0;
  bool angleDegrees = false;  // compare modulo 360
};

// Compares six columns of one request at every output time; reports the worst column.
void compareRequest(const RequestFile& req, long id, const std::array<Column, 6>& columns) {
  const int index = req.indexOf(id);
  ASSERT_GE(index, 0) << "REQUEST/" << id << " missing from piston.req";

  for (std::size_t c = 0; c < 6; ++c) {
    const Column& col = columns[c];
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < kSteps; ++k) {
      const double e = col.exact(k * kDtOut);
      lo = std::min(lo, e);
      hi = std::max(hi, e);
    }
    const double scale = col.scale > 0.0 ? col.scale : hi - lo;
    ASSERT_GT(scale, 0.0) << col.name;
    const double tolerance = kRelativeToRange * scale;

    double worst = 0.0;
    int worstStep = 0;
    for (int k = 0; k < kSteps; ++k) {
      const double got = req.rows[k][index][c];
      double err = got - col.exact(k * kDtOut);
      if (col.angleDegrees) err = std::remainder(err, 360.0);
      if (std::fabs(err) > worst) {
        worst = std::fabs(err);
        worstStep = k;
      }
    }
    const double t = worstStep * kDtOut;
    EXPECT_LE(worst, tolerance) << "REQUEST/" << id << " column " << (c + 1) << " (" << col.name
                                << "): worst error " << worst << " at t=" << t << " (solver "
                                << req.rows[worstStep][index][c] << ", exact " << col.exact(t)
                                << "), allowed " << tolerance << " = " << kRelativeToRange
                                << " x " << scale;
  }
}

double zero(double) { return 0.0; }

TEST_F(PistonExample, WritesEveryRequestOfTheDataSet) {
  for (long id : {7L, 8L, 9L, 10L, 11L, 12L, 13L, 14L})
    EXPECT_GE(req_->indexOf(id), 0) << "REQUEST/" << id << " missing from piston.req";
  EXPECT_EQ(req_->ids.size(), 8u);
  // Directory type codes as real ADAMS writes them: 1 displacement, 2 velocity, 3 acceleration.
  for (auto [id, type] : {std::pair{11L, 1}, std::pair{12L, 2}, std::pair{13L, 3}}) {
    const int index = req_->indexOf(id);
    if (index >= 0) {
      EXPECT_EQ(req_->types[index], type) << "REQUEST/" << id;
    }
  }
}

// The run's summary names every output file on disk: the data set has OUTPUT/REQSAVE,
// RESULTS and requests, so the .msg, .req, .res and .out (docs/output-files.md).
TEST_F(PistonExample, SummaryNamesTheMessageRequestAndResultsFiles) {
  const std::string console = tailOf(*outDir_ / "console.txt", 4000);
  const std::string dir = outDir_->string();
  EXPECT_NE(console.find("  outputs:  " + dir + "/piston.msg, " + dir + "/piston.req, " + dir +
                         "/piston.res, " + dir + "/piston.out\n"),
            std::string::npos)
      << console;
  EXPECT_TRUE(fs::exists(*outDir_ / "piston.res"));
}

// REQUEST/11: DISPLACEMENT of the piston CM marker 0401 relative to ground marker 0101.
TEST_F(PistonExample, PistonDisplacementMatchesClosedForm) {
  const double xRange = 2.0 * kCrankRadius;  // the CM moves between 7 and 11
  compareRequest(*req_, 11,
                 {Column{"X", [](double t) { return pistonPin(t).x + kPinToCm; }},
                  Column{"Y", zero, xRange},
                  Column{"Z", zero, xRange},
                  // Marker 0401 has REULER=90D,90D,0 and the piston never turns. The angles
                  // are held to 1e-4 of 90 degrees.
                  Column{"PSI", [](double) { return 90.0; }, 90.0, true},
                  Column{"THETA", [](double) { return 90.0; }, 90.0, true},
                  Column{"PHI", zero, 90.0, true}});
}

// REQUEST/12: VELOCITY; the piston translates along X only.
TEST_F(PistonExample, PistonVelocityMatchesClosedForm) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < kSteps; ++k) {
    lo = std::min(lo, pistonPin(k * kDtOut).v);
    hi = std::max(hi, pistonPin(k * kDtOut).v);
  }
  const double vRange = hi - lo;
  compareRequest(*req_, 12,
                 {Column{"VX", [](double t) { return pistonPin(t).v; }},
                  Column{"VY", zero, vRange},
                  Column{"VZ", zero, vRange},
                  // Angular velocity of the piston is zero; scale: the crank speed.
                  Column{"WX", zero, kOmega},
                  Column{"WY", zero, kOmega},
                  Column{"WZ", zero, kOmega}});
}

// REQUEST/13: ACCELERATION.
TEST_F(PistonExample, PistonAccelerationMatchesClosedForm) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < kSteps; ++k) {
    lo = std::min(lo, pistonPin(k * kDtOut).a);
    hi = std::max(hi, pistonPin(k * kDtOut).a);
  }
  const double aRange = hi - lo;
  compareRequest(*req_, 13,
                 {Column{"AX", [](double t) { return pistonPin(t).a; }},
                  Column{"AY", zero, aRange},
                  Column{"AZ", zero, aRange},
                  // Angular acceleration is zero; scale: the crank's centripetal omega^2.
                  Column{"WDX", zero, kOmega * kOmega},
                  Column{"WDY", zero, kOmega * kOmega},
                  Column{"WDZ", zero, kOmega * kOmega}});
}

// REQUEST/14: F2 = DM(409,109), F3 = VR(408,109), F4 = gas force, F6 = damping force
// (-0.2*VR); F7 and F8 are not given and are written as 0 (held to an absolute 1e-4).
TEST_F(PistonExample, ForceExpressionsMatchClosedForm) {
  compareRequest(*req_, 14,
                 {Column{"F2 DM(409,109)",
                         [](double t) { return kHeadMinusPinAtGap - pistonPin(t).x; }},
                  Column{"F3 VR(408,109)", [](double t) { return -pistonPin(t).v; }},
                  Column{"F4 gas force", gasForce},
                  Column{"F6 damping force", [](double t) { return 0.2 * pistonPin(t).v; }},
                  Column{"F7 (unset)", zero, 1.0},
                  Column{"F8 (unset)", zero, 1.0}});
}

}  // namespace
