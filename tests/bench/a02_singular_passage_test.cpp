// IFToMM benchmark A02, the row of N four-bar windows (bench/model_generators.cpp,
// docs/validation.md "IFToMM A02"), through its flat singular configurations with every
// integrator, against the exact one-degree-of-freedom solution.
//
// Truth: the windows stay parallelograms, so every rocker turns by the same angle phi and the
// couplers translate with the rocker tops. With thin rods (mass m, length L, m L^2/12 about the
// centre) the kinetic energy is A phi'^2 / 2 with A = (N+1) m L^2/3 + N m L^2 and the potential
// energy g B sin phi with B = (N+1) m L/2 + N m L, so A phi'' = -g B cos phi with phi(0) = pi/2
// and phi'(0) = -1 rad/s (B0, the top of the first rocker, at +1 m/s along x). B0 is
// (L cos phi, L sin phi). The equation is integrated here by classical RK4 at h = 1e-4 s: its
// global error, of order h^4 times the solution's fourth derivative (k^2 ~ 130 s^-4) over 10 s,
// is below 1e-12 m, far under the 1e-3 m asserted.
//
// N = 4 and 10 s stand in for the benchmark's N = 40 and 20 s (CI time): the mechanism turns
// over and over and is flat (all rods on the ground line) every half turn, 10 times in 10 s (B0's y
// changes sign at each); the count is asserted. The N = 40 table is in docs/validation.md
// (bench/a02_table.py).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
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

constexpr int kWindows = 4;
constexpr double kEnd = 10.0;
constexpr int kOutputSteps = 200;  // every 0.05 s
// The benchmark's "high precision" bound on B0 (docs/validation.md, "IFToMM A02").
constexpr double kBenchmarkTolerance = 1e-3;

struct Sample {
  double t, x, y;
};

// B0 of the exact solution at the given times (RK4, h = 1e-4 s, landing on each time).
std::vector<Sample> exactB0(const std::vector<double>& times, int windows = kWindows) {
  const double n = windows, m = 1.0, l = 1.0, g = 9.81;
  const double a = (n + 1) * m * l * l / 3.0 + n * m * l * l;
  const double b = (n + 1) * m * l / 2.0 + n * m * l;
  const double k = g * b / a;
  auto acc = [k](double p) { return -k * std::cos(p); };
  double p = M_PI / 2, w = -1.0, t = 0.0;
  std::vector<Sample> out;
  for (double target : times) {
    while (t < target - 1e-12) {
      const double h = std::min(1e-4, target - t);
      const double k1p = w, k1w = acc(p);
      const double k2p = w + h / 2 * k1w, k2w = acc(p + h / 2 * k1p);
      const double k3p = w + h / 2 * k2w, k3w = acc(p + h / 2 * k2p);
      const double k4p = w + h * k3w, k4w = acc(p + h * k3p);
      p += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
      w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
      t += h;
    }
    out.push_back({target, l * std::cos(p), l * std::sin(p)});
  }
  return out;
}

// B0 per output time from REQUEST/3 of the generated data set: each coordinate printed as
// AINT(v), AINT(1e6 frac) and the rest (bench/model_generators.cpp), six fields of 13 columns.
std::vector<Sample> simulatedB0(const fs::path& req) {
  std::ifstream in(req);
  std::string line;
  std::vector<std::vector<double>> record;  // the numbers of the current output time
  std::vector<Sample> out;
  auto flush = [&]() {
    // Time line, then REQUEST/1..5: REQUEST/3 is the fourth line of the record.
    if (record.size() == 6 && record[3].size() == 6) {
      const std::vector<double>& r = record[3];
      out.push_back({record[0][0], r[0] + 1e-6 * (r[1] + r[2]), r[3] + 1e-6 * (r[4] + r[5])});
    }
    record.clear();
  };
  while (std::getline(in, line)) {
    std::vector<double> numbers;
    bool numeric = line.size() >= 14;
    for (size_t k = 0; numeric && 1 + 13 * (k + 1) <= line.size(); ++k) {
      const std::string field = line.substr(1 + 13 * k, 13);
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      numeric = end != field.c_str() &&
                field.find_first_not_of(' ', end - field.c_str()) == std::string::npos;
      numbers.push_back(v);
    }
    if (!numeric) continue;
    if (numbers.size() == 1) {
      flush();
      record.push_back(numbers);
    } else if (!record.empty()) {
      record.push_back(numbers);
    }
  }
  flush();
  return out;
}

struct Outcome {
  int status = -1;
  std::string output;
  int samples = 0;
  int flatPassages = 0;  // sign changes of B0's y along the run
  double largestError = INFINITY;
  double endError = INFINITY;  // at t = END, one of the benchmark's times (10 and 20 s)
  std::string request;         // the request file's text
};

// `options` are further arguments of `openmss run` (--pivot-order).
Outcome runA02(const std::string& integrator, double error, int windows = kWindows,
               double end = kEnd, int outputSteps = kOutputSteps, const std::string& options = "") {
  const fs::path dir = scratch("a02");
  write(dir / "a02.adm", fourBarChainAdm(windows));
  write(dir / "a02.acf", chainAcf("a02.adm", "a02", end, outputSteps, error, integrator));
  const Result r = run("run a02.acf" + options, dir);
  Outcome o;
  o.status = r.status;
  o.output = r.output;
  const std::vector<Sample> sim = simulatedB0(dir / "a02.req");
  std::vector<double> times;
  for (const Sample& s : sim) times.push_back(s.t);
  const std::vector<Sample> exact = exactB0(times, windows);
  o.samples = static_cast<int>(sim.size());
  o.largestError = 0.0;
  for (size_t i = 0; i < sim.size(); ++i) {
    o.largestError =
        std::max(o.largestError, std::hypot(sim[i].x - exact[i].x, sim[i].y - exact[i].y));
    if (i > 0 && (exact[i].y > 0) != (exact[i - 1].y > 0)) ++o.flatPassages;
  }
  if (!sim.empty() && std::abs(sim.back().t - end) < 1e-9)
    o.endError = std::hypot(sim.back().x - exact.back().x, sim.back().y - exact.back().y);
  o.request = openmss::testing::slurp(dir / "a02.req");
  fs::remove_all(dir);
  return o;
}

// Largest over all outputs (default) or, with atEndOnly, at t = END only (the benchmark's own
// comparison times are 10 and 20 s).
void expectWithinBenchmark(const std::string& integrator, double error,
                           double tolerance = kBenchmarkTolerance, bool atEndOnly = false) {
  const Outcome o = runA02(integrator, error);
  char label[64];
  std::snprintf(label, sizeof label, "%s ERROR=%g", integrator.c_str(), error);
  SCOPED_TRACE(label);
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.samples, kOutputSteps + 1) << o.output;  // every output time, t = 0 to END
  EXPECT_EQ(o.flatPassages, 10);
  EXPECT_LT(atEndOnly ? o.endError : o.largestError, tolerance);
  std::printf(
      "A02 N=%d %s ERROR=%g: largest B0 error %.2e m over %d outputs, %.2e m at %g s, "
      "%d flat passages\n",
      kWindows, integrator.c_str(), error, o.largestError, o.samples, o.endError, kEnd,
      o.flatPassages);
}

// The subset run in CI (a few seconds each), chosen from the measured table of
// docs/validation.md: every integrator once, at an ERROR where it meets the benchmark's 1e-3.
TEST(A02SingularPassage, Gstiff) { expectWithinBenchmark("GSTIFF", 1e-8); }
TEST(A02SingularPassage, GstiffSi2) { expectWithinBenchmark("SI2_GSTIFF", 1e-6); }
TEST(A02SingularPassage, Wstiff) { expectWithinBenchmark("WSTIFF", 1e-8); }
// DSTIFF (IDA) with its own convergence test (docs/integrators.md, "DSTIFF"): at ERROR = 1e-8 it
// stopped at the first flat passage (t = 0.717 s) before; measured now, with the noise rules
// of 2026-11-29, 5.3e-4 m at 1e-6 and 8.2e-7 m at 1e-8 over all outputs (2.1e-4 and 1.6e-6 m
// before them).
TEST(A02SingularPassage, Dstiff) {
  expectWithinBenchmark("DSTIFF", 1e-6);
  expectWithinBenchmark("DSTIFF", 1e-8);
}
// A run at a tight ERROR through `flats` flat passages that stopped at a passage before a fix:
// it reaches END at every output, passes each passage, and stays within `bound` of the exact
// solution over all outputs and at END.
void expectPassesAtTightError(const char* integrator, const char* label, int windows, double end,
                              int outputs, int flats, double bound, double error = 1e-8,
                              const std::string& options = "") {
  const Outcome o = runA02(integrator, error, windows, end, outputs, options);
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.samples, outputs + 1) << o.output;
  EXPECT_EQ(o.flatPassages, flats);
  EXPECT_LT(o.largestError, bound);
  EXPECT_LT(o.endError, bound);
  std::printf("A02 N=%d %s ERROR=%g: largest B0 error %.2e m, %.2e m at %g s, %d flat\n", windows,
              label, error, o.largestError, o.endError, end, o.flatPassages);
}

// DSTIFF at N = 10, ERROR = 1e-8, 3 s (flat at t = 0.72, 1.24 and 2.69 s): before the
// noise rules of docs/integrators.md ("DSTIFF and ABAM", the flat passages) it stopped at the
// second flat passage, t = 1.2409 s, on repeated error-test failures down to h = 1e-7 s; now
// measured 3.1e-7 m over all 61 outputs (SI2 GSTIFF: 1.5e-7 m). Bound 1e-5 m, 1000 ERROR, two
// decades under the benchmark's 1e-3 m (about 0.5 s of CPU).
TEST(A02SingularPassage, DstiffPassesTenWindowsAtTightError) {
  expectPassesAtTightError("DSTIFF", "DSTIFF", 10, 3.0, 60, 3, 1e-5);
}
// DSTIFF at the benchmark's N = 40, ERROR = 1e-8, 1.5 s (flat at t = 0.7216 and 1.2440 s):
// before the predictor's noise and the spread noise of docs/integrators.md ("DSTIFF and ABAM",
// noise rules) it stopped at the first flat passage (t = 0.7221 s, Newton failures at
// h = 1e-7 s after error-test failures), whatever its end time; now it reaches 1.5 s within 5.8e-9
// m over all 31 outputs. Bound 1e-6 m, 100 ERROR, three decades under the benchmark's 1e-3 m (about
// 0.8 s of CPU).
TEST(A02SingularPassage, DstiffPassesFortyWindowsAtTightError) {
  expectPassesAtTightError("DSTIFF", "DSTIFF", 40, 1.5, 30, 2, 1e-6);
}
// HHT at the benchmark's N = 40, ERROR = 1e-9, 1.5 s (flat at t = 0.7216 and 1.2440 s): it
// stopped at the second flat passage (t = 1.244044 s, corrector failures down to h = 2e-8 s)
// after accepting solves that stalled along the near-null direction, whose end no step could
// leave; now it returns to the last state it handed over and steps across (docs/integrators.md,
// "Stepping across a singular instant"): measured 1.5 s within 1.8e-6 m at 1.5 s, 2.0e-6 m over
// all 31 outputs (about 3 s of CPU). Bound 2e-5 m, 10x the measured, under the benchmark's 1e-3 m.
TEST(A02SingularPassage, HhtPassesFortyWindowsAtOneBillionth) {
  expectPassesAtTightError("HHT", "HHT", 40, 1.5, 30, 2, 2e-5, 1e-9);
}
// SI2 GSTIFF at the benchmark's N = 40, ERROR = 1e-8, 7 s (seven flat passages, the last at 6.62
// s): after the set-up solves moved to KLU (a round-off change of the initial conditions) it
// stopped at t = 6.6187 s, a corrector failure at h = 1.6e-7 s after error-test failures of
// 10-31 x the estimate at every step from 5.5e-3 s down: the stalled solves' noise along the
// flat row's extra degrees of freedom, read as local error. Measured since the error test of a
// solve accepted at noise is widened by that noise (docs/integrators.md, "Singular
// configurations"): 7 s within 1.4e-7 m at 7 s, 5.0e-7 m over all 141 outputs (about 2 s of
// CPU). Bound 1e-5 m, 1000 ERROR, two decades under the benchmark's 1e-3 m.
TEST(A02SingularPassage, GstiffSi2PassesFortyWindowsAtTightError) {
  expectPassesAtTightError("SI2_GSTIFF", "SI2 GSTIFF", 40, 7.0, 140, 7, 1e-5);
}
// SI2 GSTIFF at N = 50, ERROR = 1e-8, 4 s (flat at t = 0.72, 1.24, 2.69 and 3.21 s): it stopped
// 1.8 ms after the fourth flat passage (t = 3.2119 s, corrector failures down to h = 3.5e-8 s),
// one of 23 of 36 A02 variants on which SI2 GSTIFF at 1e-8 stopped (bench/a02_census.py;
// docs/integrators.md, "Crossing a flat passage at tight tolerances"). Since the BDF takes a
// matrix formed for a rejected attempt as an older one and accepts a stalled solve whose
// unscaled residual fell 1e5-fold, it reaches 4 s (14 of 36 variants still stopped then, none
// since the step across below). Measured 1.3e-6 m over all 81 outputs, 2.2e-7 m at 4 s (about
// 1.6 s of CPU). Bound 1e-5 m, as the N = 40 row above.
TEST(A02SingularPassage, GstiffSi2PassesFiftyWindowsAtTightError) {
  expectPassesAtTightError("SI2_GSTIFF", "SI2 GSTIFF", 50, 4.0, 80, 4, 1e-5);
}
// SI2 GSTIFF at ERROR = 1e-8, 4 s, on two of the 14 A02 variants that still stopped after the
// rules of the test above (bench/a02_census.py): N = 60 on the default pivot order and N = 35
// without BTF both stopped at t = 3.2 s, the fourth flat passage, where an order-6 step had
// ended within 0.3 ms of the flat instant on a stalled solve and no step could leave its end.
// Since the BDF steps across a singular instant (docs/integrators.md, "Stepping across a singular
// instant": back to the state the call started from, with its history, and a step past the stuck
// point) all 36 variants reach 20 s. Measured over all 81 outputs: N = 60 1.3e-6 m, N = 35
// without BTF 7.6e-7 m (2.1e-7 and 2.0e-7 m at 4 s; about 3.5 s of wall time each). Bound 1e-5 m,
// as above.
TEST(A02SingularPassage, GstiffSi2StepsAcrossWhereNoStepCouldLeave) {
  expectPassesAtTightError("SI2_GSTIFF", "SI2 GSTIFF", 60, 4.0, 80, 4, 1e-5);
  expectPassesAtTightError("SI2_GSTIFF", "SI2 GSTIFF (no BTF)", 35, 4.0, 80, 4, 1e-5, 1e-8,
                           " --pivot-order nobtf");
}
// DSTIFF (SUNDIALS IDA) at N = 40 without BTF, ERROR = 1e-4, 20 s: it stopped at t = 18.4 s,
// the nineteenth flat passage, on repeated corrector failures after steps accepted on stalled
// solves. Since IdaIntegrator steps across as the BDF does (re-initialising IDA at the state the
// call started from, with a first step twice the way to where it failed; docs/integrators.md,
// "Stepping across in the BDF") it reaches 20 s: measured 8.0e-2 m over all 401 outputs and
// 2.5e-2 m at 20 s, as the default order's 6.2e-2 and 1.7e-2 m (ERROR = 1e-4 is not accurate
// enough for the benchmark with any BDF, docs/validation.md; this test is about reaching the
// end). Bound 0.2 m, 2.5x the measured, so a phase error growing past the default order's
// fails it (about 10 s of wall time).
TEST(A02SingularPassage, DstiffStepsAcrossWhereNoStepCouldLeave) {
  expectPassesAtTightError("DSTIFF", "DSTIFF (no BTF)", 40, 20.0, 400, 20, 0.2, 1e-4,
                           " --pivot-order nobtf");
}
// KLU's pivot order (`openmss run --pivot-order`, solvers/pivot_order.hpp) changes only the
// round-off. At N = 4 the CI rows hold on every order; measured largest B0 error over the 201
// outputs (default / no BTF / COLAMD): SI2 GSTIFF at 1e-6 9.1e-4 / 3.8e-4 / 3.8e-4 m, DSTIFF at
// 1e-8 4.3e-6 / 1.4e-5 / 9.0e-6 m. Bounds: the benchmark's 1e-3 m for SI2 GSTIFF (2.6x room on
// the other orders) and 1e-4 m, a decade under it, for DSTIFF (7x room). The request files
// differ from the default order's, so the setting reaches the solver and is not ignored. At
// N = 40 the flat passages are not crossed robustly on every order (docs/validation.md, "The
// flat passages are crossed partly on round-off luck"): not asserted there.
TEST(A02SingularPassage, CiRowsHoldOnOtherPivotOrders) {
  const std::string si2Default = runA02("SI2_GSTIFF", 1e-6).request;
  const std::string dstiffDefault = runA02("DSTIFF", 1e-8).request;
  for (const char* order : {"nobtf", "colamd"}) {
    SCOPED_TRACE(order);
    const std::string option = std::string(" --pivot-order ") + order;
    const Outcome si2 = runA02("SI2_GSTIFF", 1e-6, kWindows, kEnd, kOutputSteps, option);
    EXPECT_EQ(si2.status, 0) << si2.output;
    EXPECT_EQ(si2.samples, kOutputSteps + 1) << si2.output;
    EXPECT_EQ(si2.flatPassages, 10);
    EXPECT_LT(si2.largestError, kBenchmarkTolerance);
    EXPECT_NE(si2.request, si2Default);
    const Outcome dstiff = runA02("DSTIFF", 1e-8, kWindows, kEnd, kOutputSteps, option);
    EXPECT_EQ(dstiff.status, 0) << dstiff.output;
    EXPECT_EQ(dstiff.samples, kOutputSteps + 1) << dstiff.output;
    EXPECT_LT(dstiff.largestError, 1e-4);
    EXPECT_NE(dstiff.request, dstiffDefault);
    std::printf("A02 N=%d pivot order %s: SI2 GSTIFF 1e-6 largest %.2e m, DSTIFF 1e-8 %.2e m\n",
                kWindows, order, si2.largestError, dstiff.largestError);
  }
}
TEST(A02SingularPassage, MersonAtTheLoosestAndTightestError) {
  expectWithinBenchmark("MERSON", 1e-4);
  expectWithinBenchmark("MERSON", 1e-8);  // stopped at the second flat passage before
}
// HHT (docs/integrators.md, "HHT and NEWMARK") passes all ten flat passages. Its global error
// is that of a second-order method under a per-step local error test, so it falls about as
// ERROR^(2/3); with the I3 velocity test (docs/integrators.md, "HHT's velocity test") it is
// 2-3x smaller at the same ERROR. Measured largest B0 error (before the velocity test -> with
// it): 7.7e-2 -> 3.6e-2 m at 1e-6, 3.9e-3 -> 1.2e-3 m at 1e-8 (1.0e-3 -> 3.1e-4 m at t = 10 s),
// 7.4e-4 -> 3.7e-4 m at 1e-9. Bounds: at 1e-8, 2.5e-3 m over all outputs (fails without the
// velocity test) and the benchmark's 1e-3 m at t = 10 s, one of its comparison times (3.2x
// room); at 1e-9 the benchmark's 1e-3 m over all outputs (2.7x room).
TEST(A02SingularPassage, Hht) {
  const Outcome o = runA02("HHT", 1e-8);
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.samples, kOutputSteps + 1) << o.output;
  EXPECT_EQ(o.flatPassages, 10);
  EXPECT_LT(o.largestError, 2.5e-3);
  EXPECT_LT(o.endError, kBenchmarkTolerance);
  std::printf("A02 N=%d HHT ERROR=1e-08: largest B0 error %.2e m, %.2e m at %g s\n", kWindows,
              o.largestError, o.endError, kEnd);
  expectWithinBenchmark("HHT", 1e-9);
}
// The I3 velocity test (docs/integrators.md, "The I3 velocity test") brings I3 to the
// benchmark's 1e-3 m at ERROR = 1e-6. Measured at N = 4, 10 s (without the test -> with it):
// WSTIFF largest error over the outputs 7.2e-3 -> 9.5e-5 m; GSTIFF at t = 10 s 2.7e-3 ->
// 9.9e-5 m (its largest, 9.6e-3 -> 1.3e-3 m, is at a fast flat passage, between the
// benchmark's times: asserted at t = END, as the benchmark compares at 10 and 20 s). After the
// slow-convergence refresh of the Newton matrix (docs/integrators.md, "Order and cost per
// step"): WSTIFF 1.0e-4 m, GSTIFF 4.0e-4 m at t = 10 s (largest 1.7e-3 m).
TEST(A02SingularPassage, I3WithTheVelocityTestAtErrorOneMillionth) {
  expectWithinBenchmark("WSTIFF", 1e-6);
  expectWithinBenchmark("GSTIFF", 1e-6, kBenchmarkTolerance, true);
}
// The index-1 solve drops the nearly dependent rows near the flat configuration (docs/theory.md
// §9d, "Singular S"): at ERROR = 1e-8 MERSON then follows the exact solution to 4.2e-7 m
// (2.2e-4 m when those rows were kept, their small pivots amplifying the projection's residual
// into the accelerations). Bound: 1e-5 m, 1000 ERROR, two decades under the benchmark's.
TEST(A02SingularPassage, MersonDropsNearlyDependentRows) {
  expectWithinBenchmark("MERSON", 1e-8, 1e-5);
}

}  // namespace
