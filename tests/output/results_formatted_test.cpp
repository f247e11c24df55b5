// The FORMATTED results file (RESULTS/FORMATTED, the ADAMS 10 text layout) end to end: the
// piston example written with FORMATTED instead of XRF, read back with our reader, against the
// .req of the same run: the piston's position, Euler parameters, velocity and acceleration
// against REQUEST/11..13 (its CM marker 0401 relative to the ground origin, ground axes), to
// the print precision of both files. A failed run leaves a complete file whose header counts
// its blocks. Layout: docs/output-files.md, "The FORMATTED results file".

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/rotation.hpp"
#include "output/request_file_reader.hpp"
#include "output/results_formatted_file.hpp"
#include "support/cli_run.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// Half a unit in the sixth significant digit of a printed value ("%.5E" in both files), with
// 1e-9 relative slack for the bound's own rounding.
double half(double printed) {
  if (printed == 0.0) return 0.0;
  const int e = static_cast<int>(std::floor(std::log10(std::fabs(printed))));
  return 0.5 * std::pow(10.0, e - 5) * (1.0 + 1e-9);
}

TEST(FormattedResults, PistonPartMotionEqualsTheRequestsThatMeasureIt) {
  const fs::path dir = scratch("res-formatted");
  const fs::path example = fs::path(OPENMSS_SOURCE_DIR) / "examples" / "piston";
  std::string adm = slurp(example / "piston.adm");
  const std::size_t at = adm.find("RESULTS/\n, XRF\n");
  ASSERT_NE(at, std::string::npos);
  adm.replace(at, 15, "RESULTS/\n, FORMATTED\n");
  write(dir / "piston.adm", adm);
  fs::copy_file(example / "piston.acf", dir / "piston.acf");
  const Result r = run("run piston.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("FORMATTED"), std::string::npos) << r.output;  // no warning

  FormattedResultsData d;
  std::string err;
  ASSERT_TRUE(readFormattedResultsFile((dir / "piston.res").string(), d, &err)) << err;
  const auto req = readRequestFile((dir / "piston.req").string(), &err);
  ASSERT_TRUE(req.has_value()) << err;
  EXPECT_EQ(d.unitsToken, "INLBS_PFRACA");
  EXPECT_EQ(d.declaredBlocks, static_cast<long>(d.blocks.size()));
  ASSERT_EQ(d.blocks.size(), req->steps.size());
  std::size_t piston = d.partIds.size();
  for (std::size_t p = 0; p < d.partIds.size(); ++p)
    if (d.partIds[p] == 4) piston = p;
  ASSERT_LT(piston, d.partIds.size());
  std::size_t e11 = 99, e12 = 99, e13 = 99;  // the directory entries of REQUEST/11, 12, 13
  for (std::size_t e = 0; e < req->entries.size(); ++e) {
    if (req->entries[e].id == 11) e11 = e;
    if (req->entries[e].id == 12) e12 = e;
    if (req->entries[e].id == 13) e13 = e;
  }
  ASSERT_LT(std::max({e11, e12, e13}), req->entries.size());
  long compared = 0;
  const auto near = [&](double res, double reqValue, const char* what, std::size_t k) {
    // Two roundings of one double to six significant digits.
    EXPECT_NEAR(res, reqValue, half(res) + half(reqValue)) << what << " step " << k;
    ++compared;
  };
  for (std::size_t k = 0; k < d.blocks.size(); ++k) {
    const FormattedResultsBlock& b = d.blocks[k];
    const auto& s = req->steps[k];
    near(b.time, s.time, "time", k);
    // The piston is driven by a motion (zero degrees of freedom): initial conditions, then a
    // kinematic analysis.
    EXPECT_EQ(b.type, k == 0 ? "INITIAL_CONDITIONS" : "KINEMATIC");
    const auto& pos = b.positions[piston];
    const auto& vel = b.velocities[piston];
    const auto& acc = b.accelerations[piston];
    ASSERT_EQ(pos.size(), 7u);
    ASSERT_EQ(vel.size(), 6u);
    ASSERT_EQ(acc.size(), 6u);
    for (int c = 0; c < 3; ++c) near(pos[c], s.rows[e11][c], "position", k);
    // The Euler parameters against the rotation the request's PSI THETA PHI (degrees) give:
    // matrix entries agree to 1e-5 (six printed digits of each side, entries of size <= 1).
    const Eigen::Vector4d q(pos[3], pos[4], pos[5], pos[6]);
    const Eigen::Matrix3d fromRequest = matrixFromEuler313(
        s.rows[e11][3] * kDegToRad, s.rows[e11][4] * kDegToRad, s.rows[e11][5] * kDegToRad);
    const Eigen::Quaterniond qq(q(0), q(1), q(2), q(3));
    EXPECT_LT((qq.normalized().toRotationMatrix() - fromRequest).cwiseAbs().maxCoeff(), 1e-5)
        << "step " << k;
    ++compared;
    for (int c = 0; c < 6; ++c) near(vel[c], s.rows[e12][c], "velocity", k);
    for (int c = 0; c < 6; ++c) near(acc[c], s.rows[e13][c], "acceleration", k);
  }
  EXPECT_EQ(compared, static_cast<long>(d.blocks.size()) * (1 + 3 + 1 + 6 + 6));
  std::printf("[ FORMATTED .res vs .req, piston: %ld values over %zu blocks ]\n", compared,
              d.blocks.size());
  fs::remove_all(dir);
}

TEST(FormattedResults, AFailedRunLeavesACompleteFile) {
  // The force blows up at t = 0.55 s: blocks at t = 0 (initial conditions) and 0.1 .. 0.5.
  const fs::path dir = scratch("res-formatted-fail");
  write(dir / "blow.adm",
        "pendulum whose force blows up\n"
        "PART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
        "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n"
        "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(0.55-TIME)\n"
        "RESULTS/FORMATTED, NOACCELERATIONS\nEND\n");
  const Result r = run("run blow.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  FormattedResultsData d;
  std::string err;
  ASSERT_TRUE(readFormattedResultsFile((dir / "blow.res").string(), d, &err)) << err;
  ASSERT_EQ(d.blocks.size(), 6u);
  EXPECT_EQ(d.declaredBlocks, 6);
  EXPECT_EQ(d.partIds, std::vector<long>{2});
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(d.blocks[k].time, 0.1 * static_cast<double>(k), 1e-12);
    EXPECT_EQ(d.blocks[k].velocities.size(), 1u);
    EXPECT_TRUE(d.blocks[k].accelerations.empty());  // NOACCELERATIONS
    // The CM stays on the unit circle about the revolute joint at the origin (5e-6: printed
    // digits).
    const auto& p = d.blocks[k].positions[0];
    EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 5e-6) << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss::output
