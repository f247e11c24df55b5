// The results file (.res, XRF) end to end: runs the openmss program with RESULTS on the nine
// ADAMS joint cases and the piston example, and checks the file against independent truths:
// the .req written by the same run (to its print precision), an independent parse with
// Python's xml.etree (exactly), the part quantities against the requests that measure the
// same thing, the joint reactions against the FORCE requests, and a run that fails midway.
// Layout and meaning of every quantity: docs/output-files.md, "The results file".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "output/request_file_reader.hpp"
#include "output/results_file_reader.hpp"
#include "support/cli_run.hpp"
#include "support/validation_data.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

// The data set with RESULTS/XRF added before END (the validation files stay untouched).
std::string withResults(std::string adm) {
  const std::size_t end = adm.rfind("\nEND");
  EXPECT_NE(end, std::string::npos);
  adm.insert(end + 1, "RESULTS/XRF\n");
  return adm;
}

// Half a unit in the last printed digit of a .req value: "%.5E" keeps six significant digits
// (five after the point), "%.4E" (exponents of three digits) five.
double halfLastDigit(double printed) {
  if (printed == 0.0) return 0.0;  // "0.00000E+00" is printed for zero only
  const int e = static_cast<int>(std::floor(std::log10(std::fabs(printed))));
  const int digits = (e < -99 || e >= 100) ? 4 : 5;
  // 1e-9 relative slack: log10 and pow round, the bound itself must not.
  return 0.5 * std::pow(10.0, e - digits) * (1.0 + 1e-9);
}

ResultsFileData readRes(const fs::path& path) {
  ResultsFileData d;
  std::string err;
  EXPECT_TRUE(readResultsFile(path.string(), d, &err)) << err;
  return d;
}

// Every request column the .req holds equals the .res value to the .req's print precision:
// step k of the .req is the k-th <Step> of the .res (both written by the same output step).
// Returns the number of values compared; *requests and *steps (when given) receive the .req's
// request and step counts.
long compareWithRequestFile(const fs::path& req, const fs::path& res, long* requests = nullptr,
                            long* stepCount = nullptr) {
  std::string err;
  const auto r = readRequestFile(req.string(), &err);
  EXPECT_TRUE(r.has_value()) << err;
  if (!r) return 0;
  if (requests) *requests = static_cast<long>(r->entries.size());
  if (stepCount) *stepCount = static_cast<long>(r->steps.size());
  const ResultsFileData d = readRes(res);
  EXPECT_EQ(d.runStatus, "Successful");
  std::vector<const ResultsFileStep*> steps;
  for (const auto& b : d.blocks)
    for (const auto& s : b.steps) steps.push_back(&s);
  EXPECT_EQ(steps.size(), r->steps.size());
  long compared = 0;
  for (std::size_t e = 0; e < r->entries.size(); ++e) {
    const RequestEntry& entry = r->entries[e];
    const std::string name = "REQUEST_" + std::to_string(entry.id);
    const ResultsFileEntity* ent = d.findEntity(name);
    EXPECT_NE(ent, nullptr) << name;
    if (!ent) continue;
    EXPECT_EQ(ent->components.size(), 8u) << name;
    if (ent->components.size() != 8) continue;
    const int reqColumn[6] = {1, 2, 3, 5, 6, 7};  // .req holds F2 F3 F4 F6 F7 F8
    const bool degrees = entry.type == kDisplacementRequest;
    for (std::size_t k = 0; k < steps.size() && k < r->steps.size(); ++k) {
      EXPECT_NEAR(steps[k]->time(), r->steps[k].time, halfLastDigit(r->steps[k].time));
      for (int c = 0; c < 6; ++c) {
        double v = steps[k]->values[ent->components[reqColumn[c]].id - 1];
        if (degrees && c >= 3) v *= kRadToDeg;  // the .req prints displacement angles in degrees
        const double printed = r->steps[k].rows[e][c];
        EXPECT_NEAR(v, printed, halfLastDigit(printed))
            << req << " " << name << " column " << reqColumn[c] + 1 << " step " << k;
        ++compared;
      }
    }
  }
  return compared;
}

TEST(ResultsFile, NineJointCasesHoldTheRequestFileValues) {
  const fs::path joints = openmss::testing::adamsJointsDir();
  const char* cases[] = {"Revolute_Case01",  "Revolute_Case02",  "Spherical_Case01",
                         "Spherical_Case02", "Universal_Case01", "Universal_Case02",
                         "Prismatic_Case01", "Prismatic_Case02", "Cylindrical_Case01"};
  long total = 0;
  for (const char* name : cases) {
    const fs::path dir = scratch(std::string("res-") + name);
    const std::string model = "test_" + std::string(name);
    write(dir / (model + ".adm"), withResults(slurp(joints / name / (model + ".adm"))));
    // A tenth of a second of the case's own settings is enough to compare two files.
    write(dir / "run.acf", model +
                               ".adm\nout\noutput/noseparator\n"
                               "integrator/gstiff, error=1.0e-4\n"
                               "simulate/transient, end=0.1, dtout=0.01\nstop\n");
    const Result r = run("run run.acf --quiet", dir);
    ASSERT_EQ(r.status, 0) << name << "\n" << r.output;
    long requests = 0, steps = 0;
    const long n = compareWithRequestFile(dir / "out.req", dir / "out.res", &requests, &steps);
    // 11 steps: t = 0 (initial conditions), then 0.01 .. 0.1; 5 or 6 requests of 6 columns.
    EXPECT_EQ(steps, 11) << name;
    EXPECT_GE(requests, 5) << name;
    EXPECT_EQ(n, requests * 6 * 11) << name;
    total += n;
    fs::remove_all(dir);
  }
  EXPECT_EQ(total, (8 * 5 + 6) * 6 * 11);  // Prismatic_Case01 has six requests
  std::printf("[ values compared .res vs .req, nine joint cases: %ld ]\n", total);
}

class PistonResults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch("res-piston"));
    const fs::path example = fs::path(OPENMSS_SOURCE_DIR) / "examples" / "piston";
    fs::copy_file(example / "piston.adm", *dir_ / "piston.adm");
    fs::copy_file(example / "piston.acf", *dir_ / "piston.acf");
    status_ = run("run piston.acf --quiet", *dir_).status;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path* dir_;
  static int status_;
};
fs::path* PistonResults::dir_ = nullptr;
int PistonResults::status_ = -1;

TEST_F(PistonResults, TheExampleWritesARequestFileTheResultsFileAgreesWith) {
  ASSERT_EQ(status_, 0);
  const long n = compareWithRequestFile(*dir_ / "piston.req", *dir_ / "piston.res");
  // 8 requests x 6 columns x 201 steps (initial conditions at t = 0, then 0.01 .. 2).
  EXPECT_EQ(n, 8 * 6 * 201);
  std::printf("[ values compared .res vs .req, piston: %ld ]\n", n);
}

TEST_F(PistonResults, PythonXmlEtreeReadsTheSameValues) {
  ASSERT_EQ(status_, 0);
  const fs::path res = *dir_ / "piston.res";
  const fs::path out = *dir_ / "etree.txt";
  const std::string cmd = "/usr/bin/python3 '" OPENMSS_SOURCE_DIR "/tests/output/xrf_values.py' '" +
                          res.string() + "' > '" + out.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const ResultsFileData d = readRes(res);
  std::map<std::string, long> ids;  // "entity\tcomponent" -> id
  for (const auto& e : d.entities)
    for (const auto& c : e.components) ids[e.name + "\t" + c.name] = c.id;
  std::map<std::string, const ResultsFileBlock*> blocks;
  for (const auto& b : d.blocks) blocks[b.name] = &b;
  std::istringstream lines(slurp(out));
  std::string line;
  long compared = 0;
  while (std::getline(lines, line)) {
    std::istringstream f(line);
    std::string entity, component, block, value;
    long step = 0;
    std::getline(f, entity, '\t');
    std::getline(f, component, '\t');
    std::getline(f, block, '\t');
    f >> step;
    f.ignore(1);
    std::getline(f, value);
    ASSERT_TRUE(ids.count(entity + "\t" + component)) << line;
    ASSERT_TRUE(blocks.count(block)) << line;
    const double python = std::strtod(value.c_str(), nullptr);
    const double ours = blocks[block]->steps.at(step).values.at(ids[entity + "\t" + component] - 1);
    // Both parse the same decimal text with correctly rounded conversions: equal bit for bit.
    EXPECT_EQ(ours, python) << line;
    ++compared;
  }
  long expected = 0;
  for (const auto& b : d.blocks) expected += static_cast<long>(b.steps.size()) * d.componentCount;
  EXPECT_EQ(compared, expected);
  EXPECT_GT(compared, 201 * 100);  // 3 parts x 18 + 4 joints, 1 motion, 2 SFORCEs x 6, 8 x 8 ...
  std::printf("[ values compared with xml.etree, piston: %ld ]\n", compared);
}

// The part block against the requests that measure the same quantities: REQUEST/11..13 are
// the displacement, velocity and acceleration of the piston's CM marker 0401 relative to the
// ground origin, ground axes; the FORCE requests 07..10 are the joint (and motion) reactions.
TEST_F(PistonResults, PartsAndReactionsAgreeWithTheRequestsThatMeasureThem) {
  ASSERT_EQ(status_, 0);
  const ResultsFileData d = readRes(*dir_ / "piston.res");
  const auto series = [&](const char* entity, const char* component) {
    const auto id = d.componentId(entity, component);
    EXPECT_TRUE(id.has_value()) << entity << "." << component;
    return id ? d.series(*id) : std::vector<double>{};
  };
  struct Pair {
    const char* entity[2];  // entity[1] added to entity[0] when set
    const char* component;
    const char* request;
    const char* requestComponent;
  };
  const Pair pairs[] = {
      {{"PART_4_XFORM", nullptr}, "X", "REQUEST_11", "x"},
      {{"PART_4_XFORM", nullptr}, "Y", "REQUEST_11", "y"},
      {{"PART_4_XFORM", nullptr}, "PSI", "REQUEST_11", "r1"},
      {{"PART_4_XFORM", nullptr}, "THETA", "REQUEST_11", "r2"},
      {{"PART_4_XFORM", nullptr}, "VX", "REQUEST_12", "x"},
      {{"PART_4_XFORM", nullptr}, "WZ", "REQUEST_12", "r3"},
      {{"PART_4_XFORM", nullptr}, "ACCX", "REQUEST_13", "x"},
      {{"PART_4_XFORM", nullptr}, "WDZ", "REQUEST_13", "r3"},
      {{"JOINT_1", "MOTION_1"}, "FX", "REQUEST_7", "x"},
      {{"JOINT_1", "MOTION_1"}, "TZ", "REQUEST_7", "r3"},
      {{"JOINT_2", nullptr}, "FY", "REQUEST_8", "y"},
      {{"JOINT_3", nullptr}, "TX", "REQUEST_9", "r1"},
      {{"JOINT_4", nullptr}, "FZ", "REQUEST_10", "z"},
      {{"JOINT_4", nullptr}, "TY", "REQUEST_10", "r2"},
  };
  long compared = 0;
  for (const Pair& p : pairs) {
    std::vector<double> a = series(p.entity[0], p.component);
    if (p.entity[1]) {
      const std::vector<double> b = series(p.entity[1], p.component);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) a[k] += b[k];
    }
    const std::vector<double> r = series(p.request, p.requestComponent);
    ASSERT_EQ(a.size(), r.size()) << p.entity[0] << "." << p.component;
    double scale = 0.0;
    for (double v : r) scale = std::max(scale, std::fabs(v));
    for (std::size_t k = 0; k < a.size(); ++k) {
      // Two computations of one quantity from the same state: equal to rounding (1e-12 of the
      // series' largest value; the angles of a 3-1-3 set that wraps would differ by 2 pi).
      EXPECT_NEAR(a[k], r[k], 1e-12 * std::max(scale, 1.0))
          << p.entity[0] << "." << p.component << " vs " << p.request << " step " << k;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 14 * 201);
}

TEST(ResultsFile, AFailedRunLeavesAWellFormedFileWithEveryStepBeforeTheFailure) {
  // A force that grows without bound as t -> 0.55 s: the integrator gives up there; the .res
  // must hold t = 0 (initial conditions) and 0.1, ..., 0.5 and say the run failed.
  const fs::path dir = scratch("res-fail");
  write(dir / "blow.adm",
        "pendulum whose force blows up\n"
        "PART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
        "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n"
        "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(0.55-TIME)\n"
        "REQUEST/1, DISPLACEMENT, I=20, J=10\nRESULTS/XRF\nEND\n");
  const Result r = run("run blow.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  const ResultsFileData d = readRes(dir / "blow.res");  // parses: the document was closed
  EXPECT_EQ(d.runStatus, "Failed");
  ASSERT_EQ(d.blocks.size(), 2u);
  EXPECT_EQ(d.blocks[0].name, "initialConditions_001");
  EXPECT_EQ(d.blocks[1].name, "dynamic_001");
  ASSERT_EQ(d.blocks[0].steps.size(), 1u);
  ASSERT_EQ(d.blocks[1].steps.size(), 5u);
  long compared = 0;
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(d.blocks[1].steps[k].time(), 0.1 * (k + 1), 1e-12);
    ++compared;
  }
  EXPECT_EQ(compared, 5);
  // The SFORCE's own value at each step, 1/sqrt(0.55 - t) along the I-J line: its magnitude.
  const auto fx = d.componentId("SFORCE_7", "FX"), fy = d.componentId("SFORCE_7", "FY");
  ASSERT_TRUE(fx && fy);
  for (int k = 0; k < 5; ++k) {
    const auto& v = d.blocks[1].steps[k].values;
    // The element's own value, recomputed from the file's time (1e-9: a few ulps of ~1).
    EXPECT_NEAR(std::hypot(v[*fx - 1], v[*fy - 1]),
                1.0 / std::sqrt(0.55 - d.blocks[1].steps[k].time()), 1e-9);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss::output
