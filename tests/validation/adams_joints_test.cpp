// End-to-end validation against real ADAMS: runs the openmss program on each of the nine joint
// models exactly as ADAMS ran them (the .acf beside the model) and compares every column of
// every request with what ADAMS wrote. The metric is in request_comparison.hpp and
// docs/output-files.md.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "adams_reference_tables.hpp"
#include "output/request_file_reader.hpp"
#include "request_comparison.hpp"
#include "support/validation_data.hpp"

namespace openmss::validation {
namespace {

namespace fs = std::filesystem;

const fs::path kJoints = openmss::testing::adamsJointsDir();
constexpr long kEulerParameterRequest = 4;
// The worst column may be off by this share of its scale (see docs/output-files.md).
constexpr double kWorstAllowed = 1.0e-3;
// hmax=1e-5 over 5 s is half a million steps; a Debug build may be slow, a hung run may not.
constexpr int kRunTimeoutSeconds = 1800;

std::string quoted(const fs::path& path) {
  std::string text = "'";
  for (char c : path.string()) {
    if (c == '\'') {
      text += "'\\''";
    } else {
      text += c;
    }
  }
  return text + "'";
}

std::string tailOf(const fs::path& path, std::size_t characters) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  return all.size() <= characters ? all : "..." + all.substr(all.size() - characters);
}

// A fresh, empty folder of its own for each run.
fs::path freshFolder(const std::string& name) {
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  const fs::path folder =
      fs::temp_directory_path() / ("openmss-validation-" + name + "-" + std::to_string(ticks));
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

// Records where ADAMS's own output departs from the analytic solution by more than our
// tolerance: there the analytic value is the truth we compare with, and the test says so.
// Prismatic_Case02 is a block sliding without friction down a 45-degree guide: its
// acceleration is exactly (0, -g/2, -g/2) and the guide's reaction on ground exactly
// (0, +g/2, -g/2) for m = 1, at every time. ADAMS printed -4.90255 / -4.90410 at t = 4.72
// (its corrector noise 80 m from the origin); the .txt tables carry the same values.
struct AnalyticOverride {
  const char* caseName;
  long requestId;
  int column;  // 0..5 = F2 F3 F4 F6 F7 F8
  double value;
};
constexpr double kHalfG = 9.80665 / 2.0;
constexpr AnalyticOverride kAnalytic[] = {
    {"Prismatic_Case02", 3, 1, -kHalfG}, {"Prismatic_Case02", 3, 2, -kHalfG},
    {"Prismatic_Case02", 5, 1, kHalfG},  {"Prismatic_Case02", 5, 2, -kHalfG},
};
// ADAMS prints 6 significant digits: 4.90332 vs 4.903325 is a print difference, not a
// departure. Larger differences are ADAMS's own error.
constexpr double kPrintTolerance = 3.0e-6;  // 1.5 units of the sixth digit of 4.90332

void applyAnalyticOverrides(const std::string& name, RequestRun& reference) {
  for (const AnalyticOverride& o : kAnalytic) {
    if (name != o.caseName) continue;
    for (RequestSeries& series : reference) {
      if (series.id != o.requestId) continue;
      double worst = 0.0, at = 0.0;
      int replaced = 0;
      for (std::size_t r = 0; r < series.rows.size(); ++r) {
        const double departure = std::abs(series.rows[r][o.column] - o.value);
        if (departure > kPrintTolerance * std::abs(o.value)) {
          if (departure > worst) { worst = departure; at = series.times[r]; }
          series.rows[r][o.column] = o.value;
          ++replaced;
        }
      }
      if (replaced > 0)
        std::cout << name << ": note: ADAMS's REQUEST/" << o.requestId << " "
                  << columnName(o.column) << " departs from the analytic " << o.value
                  << " in " << replaced << " records (worst " << worst << " at t=" << at
                  << "); those records are compared with the analytic value" << std::endl;
    }
  }
}

class AdamsJoint : public ::testing::TestWithParam<std::string> {};

TEST_P(AdamsJoint, MatchesAdams) {
  const std::string name = GetParam();
  const fs::path caseFolder = kJoints / name;
  ASSERT_TRUE(fs::exists(caseFolder)) << caseFolder;

  // The reference: ADAMS's own request file where it exists, else its tables.
  RequestRun reference;
  std::string error;
  const fs::path adamsFile = caseFolder / ("test_" + name + "_ADAMS.req");
  if (fs::exists(adamsFile)) {
    const auto adams = output::readRequestFile(adamsFile.string(), &error);
    ASSERT_TRUE(adams) << error;
    reference = runFromRequestFile(*adams, {kEulerParameterRequest});
  } else {
    const auto tables = runFromReferenceTables(caseFolder, name, &error);
    ASSERT_TRUE(tables) << error;
    reference = *tables;
  }

  applyAnalyticOverrides(name, reference);

  const fs::path binary = OPENMSS_BINARY;
  ASSERT_TRUE(fs::exists(binary)) << "the openmss program was not built: " << binary;
  const fs::path outdir = freshFolder(name);
  const fs::path log = outdir / "run.log";
  // Started in the empty output folder, so nothing can depend on being started in the case folder.
  const std::string command = "cd " + quoted(outdir) + " && timeout " +
                              std::to_string(kRunTimeoutSeconds) + " " + quoted(binary) + " run " +
                              quoted(caseFolder / ("test_" + name + ".acf")) + " --outdir " +
                              quoted(outdir) + " > " + quoted(log) + " 2>&1";
  const int status = std::system(command.c_str());
  const int exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  ASSERT_EQ(exitCode, 0) << command << "\nfailed (exit code " << exitCode
                         << (exitCode == 124 ? ", timed out" : "") << "); its output:\n"
                         << tailOf(log, 4000);

  const fs::path oursFile = outdir / ("test_" + name + "_ADAMS.req");
  ASSERT_TRUE(fs::exists(oursFile))
      << "the run wrote no " << oursFile.filename() << " in " << outdir << "; output:\n"
      << tailOf(log, 4000);
  const auto ours = output::readRequestFile(oursFile.string(), &error);
  ASSERT_TRUE(ours) << error;

  const RunComparison comparison =
      compareRuns(reference, runFromRequestFile(*ours, {kEulerParameterRequest}));
  std::cout << name << ": " << summary(comparison) << std::endl;
  for (const std::string& problem : comparison.problems) ADD_FAILURE() << name << ": " << problem;
  for (const ColumnResult& column : comparison.columns) {
    EXPECT_LE(column.normalised, kWorstAllowed)
        << name << " REQUEST/" << column.requestId << " " << columnName(column.column)
        << ": max error " << column.maxError << " at t=" << column.timeOfMax << " over scale "
        << column.scale;
  }
  if (!HasFailure()) fs::remove_all(outdir);  // kept for a look when anything failed
}

INSTANTIATE_TEST_SUITE_P(SharedData, AdamsJoint,
                         ::testing::Values("Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                                           "Spherical_Case02", "Universal_Case01",
                                           "Universal_Case02", "Prismatic_Case01",
                                           "Prismatic_Case02", "Cylindrical_Case01"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param;
                         });

// Every integrator on every case (docs/integrators.md): the .acf's ERROR and HMAX with the
// method replaced, over the first kShortEnd seconds to keep the suite's time small (the full
// 5 s table is made by scripts/integrator_table.sh, which sets OPENMSS_INTEGRATOR_END). The
// reference is cut at the same time. Prints one TABLE line per run for that script.
constexpr double kShortEnd = 0.2;

struct IntegratorCase {
  std::string caseName;
  std::string integrator;  // the INTEGRATOR arguments naming method and formulation
};

class AdamsJointByIntegrator : public ::testing::TestWithParam<IntegratorCase> {};

long countAfter(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return -1;
  std::size_t start = text.rfind(' ', at - 2);
  return std::atol(text.substr(start + 1, at - start - 1).c_str());
}

TEST_P(AdamsJointByIntegrator, MatchesAdams) {
  const IntegratorCase param = GetParam();
  const std::string& name = param.caseName;
  const fs::path caseFolder = kJoints / name;
  ASSERT_TRUE(fs::exists(caseFolder)) << caseFolder;
  double end = kShortEnd;
  if (const char* e = std::getenv("OPENMSS_INTEGRATOR_END")) end = std::atof(e);

  RequestRun reference;
  std::string error;
  const fs::path adamsFile = caseFolder / ("test_" + name + "_ADAMS.req");
  if (fs::exists(adamsFile)) {
    const auto adams = output::readRequestFile(adamsFile.string(), &error);
    ASSERT_TRUE(adams) << error;
    reference = runFromRequestFile(*adams, {kEulerParameterRequest});
  } else {
    const auto tables = runFromReferenceTables(caseFolder, name, &error);
    ASSERT_TRUE(tables) << error;
    reference = *tables;
  }
  applyAnalyticOverrides(name, reference);
  // Each column is measured against its scale over the whole 5 s run (as MatchesAdams does),
  // not over the shortened window, where a column may hardly move.
  const RunComparison fullScales = compareRuns(reference, reference);
  for (RequestSeries& series : reference) {
    std::size_t keep = 0;
    while (keep < series.times.size() && series.times[keep] <= end + 1e-9) ++keep;
    series.times.resize(keep);
    series.rows.resize(keep);
  }

  std::string tag = param.integrator;
  for (char& c : tag)
    if (c == ',' || c == ' ') c = '_';
  const fs::path outdir = freshFolder(name + "-" + tag);
  const fs::path acf = outdir / "run.acf";
  {
    std::ofstream out(acf);
    out << (caseFolder / ("test_" + name + ".adm")).string() << "\n"
        << "test_" << name << "_ADAMS\n"
        << "output/noseparator\n"
        << "integrator/" << param.integrator << ", error = 1.0e-4, hmax=1e-5\n"
        << "simulate/transient, end=" << end << ", dtout=1.0E-002\n"
        << "stop\n";
  }
  const fs::path log = outdir / "run.log";
  const std::string command = "cd " + quoted(outdir) + " && timeout " +
                              std::to_string(kRunTimeoutSeconds) + " " + quoted(OPENMSS_BINARY) +
                              " run " + quoted(acf) + " --outdir " + quoted(outdir) + " > " +
                              quoted(log) + " 2>&1";
  const auto started = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const int exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  ASSERT_EQ(exitCode, 0) << command << "\nfailed; its output:\n" << tailOf(log, 4000);
  const auto ours =
      output::readRequestFile((outdir / ("test_" + name + "_ADAMS.req")).string(), &error);
  ASSERT_TRUE(ours) << error;
  const RunComparison comparison =
      compareRuns(reference, runFromRequestFile(*ours, {kEulerParameterRequest}));
  for (const std::string& problem : comparison.problems) ADD_FAILURE() << name << ": " << problem;
  double worst = 0.0;
  for (const ColumnResult& column : comparison.columns) {
    double scale = column.scale;
    for (const ColumnResult& full : fullScales.columns)
      if (full.requestId == column.requestId && full.column == column.column)
        scale = std::max(scale, full.scale);
    worst = std::max(worst, scale > 0 ? column.maxError / scale : column.normalised);
  }
  const std::string msg = tailOf(outdir / ("test_" + name + "_ADAMS.msg"), 100000);
  // Run time is reported, never tested.
  std::printf("TABLE | %s | %s | %.2e | %ld | %ld | %.1f\n", name.c_str(),
              param.integrator.c_str(), worst, countAfter(msg, "steps,"),
              countAfter(msg, "Jacobian evaluations"), seconds);
  EXPECT_LE(worst, kWorstAllowed) << name << " with " << param.integrator;
  if (!HasFailure()) fs::remove_all(outdir);
}

std::vector<IntegratorCase> everyIntegratorOnEveryCase() {
  std::vector<IntegratorCase> all;
  for (const char* c : {"Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                        "Spherical_Case02", "Universal_Case01", "Universal_Case02",
                        "Prismatic_Case01", "Prismatic_Case02", "Cylindrical_Case01"})
    // DSTIFF runs on SI2 whatever the formulation asked (docs/integrators.md, "DSTIFF and
    // ABAM"); ABAM is coordinate partitioning with CVODE's Adams method; MERSON explicit
    // Kutta-Merson on the index-1 equations (an OpenMSS extension).
    for (const char* i : {"GSTIFF", "WSTIFF", "GSTIFF, SI2", "WSTIFF, SI2", "HHT", "NEWMARK",
                          "DSTIFF", "ABAM", "MERSON"})
      all.push_back({c, i});
  return all;
}

INSTANTIATE_TEST_SUITE_P(SharedData, AdamsJointByIntegrator,
                         ::testing::ValuesIn(everyIntegratorOnEveryCase()),
                         [](const ::testing::TestParamInfo<IntegratorCase>& p) {
                           std::string n = p.param.caseName + "_" + p.param.integrator;
                           for (char& c : n)
                             if (c == ',' || c == ' ') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace openmss::validation
