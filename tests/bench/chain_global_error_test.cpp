// GSTIFF I3's global error on a pendulum chain (issue 20, item 5; docs/integrators.md, "GSTIFF
// I3's global error"): the tip of a 20-link planar chain (bench/model_generators.cpp, the
// benchmark chain of docs/performance.md at a CI size: 20 links and 2 s instead of 100 links
// and 10 s) after GSTIFF at ERROR = 1e-6, against the same model integrated by another
// method, MERSON (explicit Kutta-Merson on the index-1 equations) at ERROR = 1e-9. That
// reference agrees with Simbody at accuracy 1e-10 to 3.4e-11 m on the 100-link chain over
// 10 s (docs/performance.md, "References"), far below the bound asserted here.
//
// Bound: twice ERROR (2e-6 m). The chain swings 0.1 rad without damping, so a step's local
// error is not damped away and the global error after 2 s is a small multiple of the local
// ones; measured 8.5e-7 m (3.3e-7 m with the I3 velocities in the error test, an experiment
// not kept: docs/integrators.md, "GSTIFF I3's global error"). The target for the
// 100-link chain over 10 s is 2e-5 m (measured 5.2e-8 m, docs/performance.md).

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "model_generators.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::bench;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::write;

constexpr int kLinks = 20;
constexpr double kEnd = 2.0;
constexpr int kOutputSteps = 10;

// The numbers of each fixed-width line (" %13.5E" fields) of a .req file.
std::vector<std::vector<double>> numericLines(const fs::path& req) {
  std::ifstream in(req);
  std::string line;
  std::vector<std::vector<double>> out;
  while (std::getline(in, line)) {
    std::vector<double> numbers;
    bool numeric = line.size() >= 14;
    for (size_t k = 0; numeric && 1 + 13 * (k + 1) <= line.size(); ++k) {
      const std::string field = line.substr(1 + 13 * k, 13);
      char* end = nullptr;
      numbers.push_back(std::strtod(field.c_str(), &end));
      numeric = end != field.c_str() &&
                field.find_first_not_of(' ', end - field.c_str()) == std::string::npos;
    }
    if (numeric) out.push_back(numbers);
  }
  return out;
}

struct Tip {
  int status = -1;
  std::string output;
  double time = -1.0;
  std::array<double, 3> position{};
  // From the .msg's "Integrator statistics: <n> steps, ..., <j> Jacobian evaluations, <r>
  // residual evaluations" line; -1 when absent.
  long steps = -1, jacobians = -1, residuals = -1;
};

// The integer before `label` on the statistics line of the .msg, or -1.
long statistic(const std::string& msg, const std::string& label) {
  const size_t line = msg.rfind("Integrator statistics:");
  if (line == std::string::npos) return -1;
  const size_t at = msg.find(label, line);
  if (at == std::string::npos) return -1;
  size_t begin = at;
  while (begin > line && std::isdigit(static_cast<unsigned char>(msg[begin - 1]))) --begin;
  return begin < at ? std::stol(msg.substr(begin, at - begin)) : -1;
}

// The tip at the last output time: the time line, then REQUEST/1..5; REQUEST/3 carries DX and
// DY, REQUEST/4 DZ first, each as AINT(v), AINT(1e6 frac) and the rest (six printed digits are
// too few for 1e-8 m; bench/model_generators.cpp).
Tip runChain(const std::string& integrator, double error,
             const std::string& adm = planarPendulumChainAdm(kLinks), double end = kEnd,
             int outputSteps = kOutputSteps) {
  const fs::path dir = scratch("chain");
  write(dir / "chain.adm", adm);
  write(dir / "chain.acf", chainAcf("chain.adm", "chain", end, outputSteps, error, integrator));
  const Result r = run("run chain.acf", dir);
  Tip tip;
  tip.status = r.status;
  tip.output = r.output;
  const auto lines = numericLines(dir / "chain.req");
  if (lines.size() >= 6) {
    const auto& time = lines[lines.size() - 6];
    const auto& r3 = lines[lines.size() - 3];
    const auto& r4 = lines[lines.size() - 2];
    if (time.size() == 1 && r3.size() == 6 && r4.size() == 6) {
      tip.time = time[0];
      tip.position = {r3[0] + 1e-6 * (r3[1] + r3[2]), r3[3] + 1e-6 * (r3[4] + r3[5]),
                      r4[0] + 1e-6 * (r4[1] + r4[2])};
    }
  }
  std::ifstream msgFile(dir / "chain.msg");
  const std::string msg((std::istreambuf_iterator<char>(msgFile)),
                        std::istreambuf_iterator<char>());
  tip.steps = statistic(msg, " steps,");
  tip.jacobians = statistic(msg, " Jacobian evaluations");
  tip.residuals = statistic(msg, " residual evaluations");
  fs::remove_all(dir);
  return tip;
}

TEST(ChainGlobalError, GstiffI3AtOneMillionthAgainstMerson) {
  const Tip reference = runChain("MERSON", 1e-9);
  const Tip gstiff = runChain("GSTIFF", 1e-6);
  for (const Tip* t : {&reference, &gstiff}) {
    ASSERT_EQ(t->status, 0) << t->output;
    ASSERT_DOUBLE_EQ(t->time, kEnd) << t->output;  // the last record is the end time
  }
  // The tip hangs about kLinks m below the pivot: the comparison is not of zeros.
  EXPECT_GT(std::hypot(reference.position[0], reference.position[1]), 0.9 * kLinks);
  const double distance = std::hypot(gstiff.position[0] - reference.position[0],
                                     gstiff.position[1] - reference.position[1],
                                     gstiff.position[2] - reference.position[2]);
  std::printf("chain-planar %d links, %g s: GSTIFF ERROR=1e-6 tip %.2e m from MERSON 1e-9\n",
              kLinks, kEnd, distance);
  EXPECT_LT(distance, 2e-6);
}

// The corrector's cost per step (docs/integrators.md, "Order and cost per step on the undamped
// chains"): a step that converged slowly on an older Newton matrix re-forms it at the next
// attempt (kRefreshRate in src/solvers/bdf_integrator.cpp). Measured on this chain: 724 residual
// evaluations and 48 Jacobians in 208 steps (3.48 per step); without the rule 891 and 35 (4.28
// per step), with the same steps and tip to the printed digits. Bound: 3.9 per step, between
// the two; a matrix kept until cj drifts exceeds it. The tip bound of the test above holds too.
TEST(ChainGlobalError, SlowConvergenceReformsTheNewtonMatrix) {
  const Tip gstiff = runChain("GSTIFF", 1e-6);
  ASSERT_EQ(gstiff.status, 0) << gstiff.output;
  ASSERT_GT(gstiff.steps, 100);  // the statistics line was read (208 steps measured)
  ASSERT_GT(gstiff.jacobians, 0);
  const double perStep = static_cast<double>(gstiff.residuals) / static_cast<double>(gstiff.steps);
  std::printf(
      "chain-planar %d links, %g s, GSTIFF ERROR=1e-6: %ld steps, %ld Jacobians, %ld "
      "residuals (%.2f per step)\n",
      kLinks, kEnd, gstiff.steps, gstiff.jacobians, gstiff.residuals, perStep);
  EXPECT_LT(perStep, 3.9);
}

// The round-off floor of an I3 velocity (kRoundOffUlps in src/solvers/bdf_integrator.cpp,
// docs/integrators.md "Singular configurations"): a velocity recovered from positions through cj
// carries their round-off, cj ulp(|q|), not its own. The 3000-link spatial chain's far links
// hang 3 km from the pivot (ulp 4.5e-13 m); at ERROR = 1e-7 their velocity changes stalled just
// above the corrector's stall test, and with the floor sized on the velocity's own magnitude the
// run failed at t = 1.08e-4 s with "the corrector did not converge" (every retry at a shorter
// step worse, the noise growing as cj; docs/performance.md, "Large models"). With the floor on
// the largest position it reaches END. Truth: the same chain by MERSON at ERROR = 1e-9, tip
// within 1e-6 m (10 ERROR; the tip moves about g t^2 / 2 = 2e-5 m in 2e-3 s). At END = 2e-4 s
// the old floor passed too (shorter steps): this END reproduces the failure.
TEST(ChainGlobalError, FarLinksRoundOffDoesNotStopTheCorrector) {
  constexpr int kFarLinks = 3000;
  constexpr double kShortEnd = 2e-3;
  const std::string adm = spatialPendulumChainAdm(kFarLinks);
  const Tip gstiff = runChain("GSTIFF", 1e-7, adm, kShortEnd, 2);
  ASSERT_EQ(gstiff.status, 0) << gstiff.output;
  ASSERT_DOUBLE_EQ(gstiff.time, kShortEnd) << gstiff.output;
  const Tip reference = runChain("MERSON", 1e-9, adm, kShortEnd, 2);
  ASSERT_EQ(reference.status, 0) << reference.output;
  ASSERT_DOUBLE_EQ(reference.time, kShortEnd) << reference.output;
  EXPECT_GT(std::hypot(reference.position[0], reference.position[1]), 0.9 * kFarLinks);
  const double distance = std::hypot(gstiff.position[0] - reference.position[0],
                                     gstiff.position[1] - reference.position[1],
                                     gstiff.position[2] - reference.position[2]);
  std::printf("chain-spatial %d links, %g s: GSTIFF ERROR=1e-7 (%ld steps) tip %.2e m from "
              "MERSON 1e-9\n",
              kFarLinks, kShortEnd, gstiff.steps, distance);
  EXPECT_LT(distance, 1e-6);
}

}  // namespace
