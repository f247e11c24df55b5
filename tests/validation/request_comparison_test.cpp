// The validation metric checked on ADAMS's own output: a file compared with itself scores 0,
// known perturbations score what the definition says, and the free choices of a program (the
// sign of q, angle wrap, psi/phi at gimbal lock) score nothing.

#include "request_comparison.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "adams_reference_tables.hpp"
#include "output/request_file_reader.hpp"
#include "support/validation_data.hpp"

namespace openmss::validation {
namespace {

namespace fs = std::filesystem;

const fs::path kJoints = openmss::testing::adamsJointsDir();
constexpr long kEulerParameterRequest = 4;

std::optional<RequestRun> adamsRun(const std::string& name) {
  const fs::path path = kJoints / name / ("test_" + name + "_ADAMS.req");
  std::string error;
  const auto data = output::readRequestFile(path.string(), &error);
  if (!data) {
    ADD_FAILURE() << error;
    return std::nullopt;
  }
  return runFromRequestFile(*data, {kEulerParameterRequest});
}

RequestSeries& request(RequestRun& run, long id) {
  return *std::find_if(run.begin(), run.end(), [&](const RequestSeries& s) { return s.id == id; });
}
const RequestSeries& request(const RequestRun& run, long id) {
  return *std::find_if(run.begin(), run.end(), [&](const RequestSeries& s) { return s.id == id; });
}

double columnRange(const RequestSeries& series, std::size_t column) {
  double low = series.rows[0][column];
  double high = low;
  for (const auto& row : series.rows) {
    low = std::min(low, row[column]);
    high = std::max(high, row[column]);
  }
  return high - low;
}

class ComparisonOnAdamsOutput : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(fs::exists(kJoints)) << kJoints; }
};

TEST_F(ComparisonOnAdamsOutput, AFileComparedWithItselfScoresZero) {
  for (const char* name : {"Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                           "Spherical_Case02", "Universal_Case01", "Universal_Case02"}) {
    const auto run = adamsRun(name);
    ASSERT_TRUE(run);
    const RunComparison comparison = compareRuns(*run, *run);
    EXPECT_TRUE(comparison.problems.empty()) << name;
    EXPECT_EQ(comparison.records, 501u) << name;
    EXPECT_EQ(comparison.columns.size(), 30u) << name;
    EXPECT_EQ(comparison.worst().normalised, 0.0) << name << ": " << summary(comparison);
  }
}

TEST_F(ComparisonOnAdamsOutput, APerturbedMajorColumnScoresErrorOverItsRange) {
  const auto reference = adamsRun("Revolute_Case01");
  ASSERT_TRUE(reference);
  RequestRun candidate = *reference;
  constexpr double kShift = 0.01;
  request(candidate, 5).rows[100][2] += kShift;  // REQUEST/5 F4, the largest force column

  const RunComparison comparison = compareRuns(*reference, candidate);
  const ColumnResult worst = comparison.worst();
  EXPECT_EQ(worst.requestId, 5);
  EXPECT_EQ(worst.column, 2);
  EXPECT_NEAR(worst.timeOfMax, 1.0, 1e-12);
  EXPECT_NEAR(worst.normalised, kShift / columnRange(request(*reference, 5), 2), 1e-12);
  EXPECT_EQ(summary(comparison).substr(summary(comparison).find('(')),
            "(REQUEST/5 col F4), 501 records");
}

TEST_F(ComparisonOnAdamsOutput, AColumnThatIsZeroInTheoryIsJudgedAgainstItsRequest) {
  // REQUEST/5 F7 (reaction torque about y) is 0 in every record; F3 F6 F8 are round-off.
  const auto reference = adamsRun("Revolute_Case01");
  ASSERT_TRUE(reference);
  const RequestSeries& forces = request(*reference, 5);
  ASSERT_EQ(columnRange(forces, 4), 0.0);
  double requestRange = 0.0;
  for (std::size_t c = 0; c < 6; ++c) requestRange = std::max(requestRange, columnRange(forces, c));

  RequestRun candidate = *reference;
  constexpr double kShift = 1.0e-4;
  request(candidate, 5).rows[250][4] += kShift;
  const ColumnResult worst = compareRuns(*reference, candidate).worst();
  EXPECT_EQ(worst.column, 4);
  // scale = 0.1 * max(torque range ~3e-14, 0.01 * force range) = 0.001 * force range
  EXPECT_NEAR(worst.normalised, kShift / (1.0e-3 * requestRange), 1e-9);

  // Round-off of our own, like ADAMS's 5.8e-16, scores next to nothing.
  RequestRun roundOff = *reference;
  for (auto& row : request(roundOff, 5).rows) row[1] += 3.0e-14;
  EXPECT_LT(compareRuns(*reference, roundOff).worst().normalised, 1e-11);
}

TEST_F(ComparisonOnAdamsOutput, ASmallComponentIsJudgedAgainstItsVector) {
  // Spherical_Case02 REQUEST/3 F3: out-of-plane acceleration of ADAMS's integration noise,
  // range 5.9e-5 beside an in-plane range of 28.7. A solver that gives exactly 0 must pass.
  const auto reference = adamsRun("Spherical_Case02");
  ASSERT_TRUE(reference);
  RequestRun candidate = *reference;
  for (auto& row : request(candidate, 3).rows) {
    row[1] = 0.0;
    row[3] = 0.0;
    row[5] = 0.0;
  }
  const RunComparison comparison = compareRuns(*reference, candidate);
  EXPECT_LT(comparison.worst().normalised, 1e-3) << summary(comparison);
  EXPECT_GT(comparison.worst().normalised, 1e-4) << summary(comparison);
}

TEST_F(ComparisonOnAdamsOutput, TheSignOfEulerParametersIsFree) {
  const auto reference = adamsRun("Revolute_Case02");
  ASSERT_TRUE(reference);
  RequestRun candidate = *reference;
  auto& rows = request(candidate, kEulerParameterRequest).rows;
  for (std::size_t r = 0; r < rows.size(); r += 2) {
    for (std::size_t c = 0; c < 4; ++c) rows[r][c] = -rows[r][c];
  }
  EXPECT_EQ(compareRuns(*reference, candidate).worst().normalised, 0.0);

  // The same flip on a plain request is an error.
  RequestRun asPlain = *reference;
  request(asPlain, kEulerParameterRequest).kind = RecordKind::Plain;
  RequestRun flippedPlain = candidate;
  request(flippedPlain, kEulerParameterRequest).kind = RecordKind::Plain;
  EXPECT_GT(compareRuns(asPlain, flippedPlain).worst().normalised, 0.1);
}

TEST_F(ComparisonOnAdamsOutput, AnglesCompareModulo360) {
  const auto reference = adamsRun("Revolute_Case01");
  ASSERT_TRUE(reference);
  RequestRun candidate = *reference;
  for (auto& row : request(candidate, 1).rows) {
    row[3] += 360.0;
    row[5] -= 360.0;
  }
  EXPECT_LT(compareRuns(*reference, candidate).worst().normalised, 1e-12);

  // phi wraps through +-180 in this run; its range is that of the unwrapped swing, not 360.
  const RunComparison self = compareRuns(*reference, *reference);
  const auto phi = std::find_if(self.columns.begin(), self.columns.end(),
                                [](const auto& c) { return c.requestId == 1 && c.column == 5; });
  ASSERT_NE(phi, self.columns.end());
  EXPECT_LT(phi->scale, 359.0);
  EXPECT_GT(phi->scale, 1.0);
}

TEST_F(ComparisonOnAdamsOutput, AtGimbalLockOnlyPsiPlusPhiCounts) {
  // Spherical_Case01 starts at theta = 0, where only psi + phi is defined.
  const auto reference = adamsRun("Spherical_Case01");
  ASSERT_TRUE(reference);
  ASSERT_EQ(request(*reference, 1).rows[0][4], 0.0);
  RequestRun candidate = *reference;
  request(candidate, 1).rows[0][3] += 30.0;
  request(candidate, 1).rows[0][5] -= 30.0;
  EXPECT_LT(compareRuns(*reference, candidate).worst().normalised, 1e-12);

  request(candidate, 1).rows[0][5] += 30.0;  // now the orientation itself differs
  const ColumnResult worst = compareRuns(*reference, candidate).worst();
  EXPECT_EQ(worst.requestId, 1);
  EXPECT_NEAR(worst.maxError, 30.0, 1e-9);
}

TEST_F(ComparisonOnAdamsOutput, MissingRequestsTimesAndNotANumberAreReported) {
  const auto reference = adamsRun("Universal_Case01");
  ASSERT_TRUE(reference);
  RequestRun candidate = *reference;
  candidate.erase(candidate.begin() + 4);  // REQUEST/5
  auto& velocities = request(candidate, 2);
  velocities.times.erase(velocities.times.begin() + 300, velocities.times.end());
  velocities.rows.erase(velocities.rows.begin() + 300, velocities.rows.end());
  request(candidate, 3).rows[10][0] = std::numeric_limits<double>::quiet_NaN();

  const RunComparison comparison = compareRuns(*reference, candidate);
  ASSERT_EQ(comparison.problems.size(), 2u);
  EXPECT_EQ(comparison.problems[0], "REQUEST/2: 201 of 501 reference times missing (first t=3)");
  EXPECT_EQ(comparison.problems[1], "REQUEST/5 is missing from the run");
  EXPECT_EQ(comparison.worst().requestId, 3);
  EXPECT_FALSE(comparison.worst().normalised <= 1e-3);
}

TEST_F(ComparisonOnAdamsOutput, ReferenceTablesHoldTheSameRunAsTheRequestFile) {
  // Confirms the mapping of the .txt tables to request columns used for the cases without a
  // .req: for the six cases with both, tables and file agree to the printed digits.
  for (const char* name : {"Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                           "Spherical_Case02", "Universal_Case01", "Universal_Case02"}) {
    std::string error;
    const auto tables = runFromReferenceTables(kJoints / name, name, &error);
    ASSERT_TRUE(tables) << error;
    const auto file = adamsRun(name);
    ASSERT_TRUE(file);
    const RunComparison comparison = compareRuns(*tables, *file);
    EXPECT_TRUE(comparison.problems.empty()) << name;
    EXPECT_EQ(comparison.records, 501u) << name;
    EXPECT_EQ(comparison.columns.size(), 25u) << name;  // no angles in the tables
    EXPECT_LT(comparison.worst().normalised, 1e-5) << name << ": " << summary(comparison);
  }
}

TEST_F(ComparisonOnAdamsOutput, EveryCaseHasReadableReferenceTables) {
  for (const char* name : {"Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                           "Spherical_Case02", "Universal_Case01", "Universal_Case02",
                           "Prismatic_Case01", "Prismatic_Case02", "Cylindrical_Case01"}) {
    std::string error;
    const auto tables = runFromReferenceTables(kJoints / name, name, &error);
    ASSERT_TRUE(tables) << error;
    EXPECT_EQ(tables->size(), 5u);
    const RunComparison comparison = compareRuns(*tables, *tables);
    EXPECT_EQ(comparison.records, 501u) << name;
    EXPECT_EQ(comparison.worst().normalised, 0.0) << name;
  }
}

}  // namespace
}  // namespace openmss::validation
