// LINEAR end to end through the openmss program: state matrices of a spring-mass with a plant
// input and two plant outputs read back from the MATLAB flat files (and the MATRIXx file)
// against the closed forms, the double pendulum's eigenvalues after SIMULATE/STATICS from a
// displaced configuration, and the refusal of a zero-DOF model.
//
// Tolerances: the flat files hold 17 significant digits, so every entry reads back to the
// double computed; the entries are exact up to round-off (1e-14 relative). The .msg prints
// eigenvalues with 10 significant digits (5e-10 relative), under the 1e-8 required.

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include <sys/wait.h>

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

int run(const std::string& args, const fs::path& dir) {
  return openmss::testing::run(args, dir).status;
}

// A MATLAB ASCII flat file: every line a row of whitespace-separated numbers, all rows of one
// length. Fails the test on anything else.
Eigen::MatrixXd readFlat(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in.good()) << p;
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<double> row;
    std::string token;
    while (ls >> token) {
      size_t used = 0;
      row.push_back(std::stod(token, &used));
      EXPECT_EQ(used, token.size()) << "not a plain number: " << token << " in " << p;
    }
    rows.push_back(row);
  }
  Eigen::MatrixXd m(rows.size(), rows.empty() ? 0 : rows[0].size());
  for (size_t r = 0; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r].size(), rows[0].size()) << "ragged row in " << p;
    for (size_t c = 0; c < rows[r].size() && c < rows[0].size(); ++c)
      m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r][c];
  }
  return m;
}

void expectMatrix(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want, const char* what) {
  ASSERT_EQ(got.rows(), want.rows()) << what;
  ASSERT_EQ(got.cols(), want.cols()) << what;
  const double scale = std::max(1.0, want.cwiseAbs().maxCoeff());
  EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-14 * scale) << what << "\n" << got;
}

// m x'' + c x' + k x = u (an action-only SFORCE along +z carrying VARIABLE/1, the plant input);
// outputs VARIABLE/2 = DZ (the displacement) and VARIABLE/3 = VZ + 2 u. In the part
// coordinates (Z, VZ) of PART/2: A = [[0, 1], [-k/m, -c/m]], B = [0; 1/m], C = I, D = [0; 2].
const char* kSpringMass =
    "spring mass with plant input\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,-1\nMARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=100, C=3, LENGTH=1\n"
    "VARIABLE/1, FUNCTION=0\n"
    "SFORCE/1, TRANSLATION, ACTIONONLY, I=20, J=10, FUNCTION=VARVAL(1)\n"
    "VARIABLE/2, FUNCTION=DZ(20,10)\nVARIABLE/3, FUNCTION=VZ(20,10) + 2*VARVAL(1)\n"
    "PINPUT/1, VARIABLES=1\nPOUTPUT/1, VARIABLES=2,3\nEND\n";

TEST(LinearCli, StateMatricesInMatlabFilesMatchTheClosedForm) {
  const fs::path dir = scratch("statemat");
  write(dir / "sm.adm", kSpringMass);
  write(dir / "sm.acf",
        "sm.adm\nsm\nLINEAR/STATEMAT, PINPUT=1, POUTPUT=1, FILE=plant\n"
        "LINEAR/STATEMAT, PINPUT=1, POUTPUT=1, FORMAT=MATRIXX, FILE=plant\n"
        "LINEAR/STATEMAT\nSTOP\n");
  ASSERT_EQ(run("run sm.acf", dir), 0) << slurp(dir / "cli.log");
  const double m = 2, k = 100, c = 3;
  Eigen::MatrixXd a(2, 2), b(2, 1), cc(2, 2), d(2, 1);
  a << 0, 1, -k / m, -c / m;
  b << 0, 1 / m;
  cc << 1, 0, 0, 1;
  d << 0, 2;
  expectMatrix(readFlat(dir / "plant.a"), a, "A");
  expectMatrix(readFlat(dir / "plant.b"), b, "B");
  expectMatrix(readFlat(dir / "plant.c"), cc, "C");
  expectMatrix(readFlat(dir / "plant.d"), d, "D");
  // States: PART/2 Z (code 3) and VZ (code 9); input VARIABLE/1; outputs VARIABLE/2 and 3.
  Eigen::MatrixXd st(2, 3), pi(1, 1), po(2, 1);
  st << 2, 3, 1, 2, 9, 1;
  pi << 1;
  po << 2, 3;
  expectMatrix(readFlat(dir / "plant.st"), st, "states");
  expectMatrix(readFlat(dir / "plant.pi"), pi, "inputs");
  expectMatrix(readFlat(dir / "plant.po"), po, "outputs");
  // Without PINPUT/POUTPUT only A and the states are written (as ADAMS, fewer files), named
  // after the output prefix.
  EXPECT_TRUE(fs::exists(dir / "sm.a"));
  EXPECT_TRUE(fs::exists(dir / "sm.st"));
  EXPECT_FALSE(fs::exists(dir / "sm.b"));
  EXPECT_FALSE(fs::exists(dir / "sm.c"));
  // MATRIXx: header line, then per matrix "NAME rows cols 0(1P3E25.17)" and the entries by
  // columns, three per line.
  std::ifstream mx(dir / "plant.mat");
  std::string line;
  ASSERT_TRUE(std::getline(mx, line));
  EXPECT_EQ(line.rfind("MATRIXx MATSAVE", 0), 0u) << line;
  ASSERT_TRUE(std::getline(mx, line));
  EXPECT_EQ(line, "A             2    2    0(1P3E25.17)");
  std::vector<double> entries;
  for (int i = 0; i < 4; ++i) {
    double v = 0;
    mx >> v;
    entries.push_back(v);
  }
  EXPECT_EQ(entries, (std::vector<double>{0, -k / m, 1, -c / m}));
  const std::string msg = slurp(dir / "sm.msg");
  EXPECT_NE(msg.find("1  PART/2 Z"), std::string::npos);
  EXPECT_NE(msg.find("Input 1: VARIABLE/1"), std::string::npos);
}

// The double pendulum of linear_analysis_test.cpp released 20 degrees from the vertical:
// SIMULATE/STATICS brings it down, then LINEAR/EIGENSOL linearises about that equilibrium.
TEST(LinearCli, DoublePendulumEigenvaluesAfterStatics) {
  const double m1 = 2.0, l1 = 1.2, i1 = 0.3, m2 = 1.5, l2 = 0.8, i2 = 0.1, g = 9.81;
  const fs::path dir = scratch("eigensol");
  write(dir / "dp.adm",
        "double pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=0.3,0.3,0.3, REULER=20D,0,0\n"
        "MARKER/20, PART=2, QP=0,-0.6,0\nMARKER/21, PART=2\nMARKER/22, PART=2, QP=0,-1.2,0\n"
        "PART/3, MASS=1.5, CM=30, IP=0.1,0.1,0.1, REULER=20D,0,0\n"
        "MARKER/30, PART=3, QP=0,-1.6,0\nMARKER/31, PART=3, QP=0,-1.2,0\n"
        "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=31, J=22\n"
        "ACCGRAV/ JGRAV=-9.81\nEQUILIBRIUM/ ERROR=1e-12, IMBALANCE=1e-10\nEND\n");
  write(dir / "dp.acf", "dp.adm\ndp\nSIMULATE/STATICS\nLINEAR/EIGENSOL\nSTOP\n");
  ASSERT_EQ(run("run dp.acf", dir), 0) << slurp(dir / "cli.log");
  const std::string msg = slurp(dir / "dp.msg");
  std::istringstream in(msg.substr(msg.find("Mode          Real")));
  std::string header;
  std::getline(in, header);
  std::vector<std::complex<double>> got;
  for (int i = 0; i < 4; ++i) {
    int mode = 0;
    double re = 0, im = 0, zeta = 0, fn = 0, fd = 0;
    in >> mode >> re >> im >> zeta >> fn >> fd;
    got.push_back({re, im});
    EXPECT_NEAR(fn, std::abs(got.back()) / (2 * M_PI), 1e-9 * fn);
  }
  const double a1 = l1 / 2, a2 = l2 / 2;
  Eigen::Matrix2d mm, kk;
  mm << i1 + m1 * a1 * a1 + m2 * l1 * l1, m2 * l1 * a2, m2 * l1 * a2, i2 + m2 * a2 * a2;
  kk << (m1 * a1 + m2 * l1) * g, 0, 0, m2 * a2 * g;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> s(kk, mm);
  for (int i = 0; i < 2; ++i)
    for (double sign : {-1.0, 1.0}) {
      const std::complex<double> want(0.0, sign * std::sqrt(s.eigenvalues()(i)));
      double best = 1e300;
      for (const auto& z : got) best = std::min(best, std::abs(z - want) / std::abs(want));
      std::printf("  expected %+.12fi: nearest printed eigenvalue differs by %.2e\n", want.imag(),
                  best);
      EXPECT_LT(best, 1e-8);
    }
  EXPECT_NE(msg.find("Mode shape"), std::string::npos);
}

TEST(LinearCli, ZeroDegreeOfFreedomModelIsRefused) {
  const fs::path dir = scratch("zerodof");
  write(dir / "z.adm",
        "fixed part\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nJOINT/1, FIXED, I=20, J=10\nEND\n");
  write(dir / "z.acf", "z.adm\nz\nLINEAR/EIGENSOL\nSTOP\n");
  EXPECT_NE(run("run z.acf", dir), 0);
  const std::string log = slurp(dir / "cli.log");
  EXPECT_NE(log.find("LINEAR"), std::string::npos) << log;
  EXPECT_NE(log.find("no degree of freedom"), std::string::npos) << log;
  EXPECT_NE(slurp(dir / "z.msg").find("no degree of freedom"), std::string::npos);
}

}  // namespace
