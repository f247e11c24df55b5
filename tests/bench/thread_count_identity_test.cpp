// Bit-identical outputs for any thread count (docs/architecture.md, "Threads"): the openmss
// program runs the nine ADAMS joint cases, the piston example, a spatial chain and a bushing
// chain with OPENMSS_THREADS=1 and =2, and once more with =2, and every .req, .res and .msg
// must be equal byte for byte across the three runs. The bushing chain (80 BUSHINGs and
// SPRINGDAMPERs) is above the size (32) where the Newton matrix's per-element force passes go to
// the thread pool (mechanics/local_newton_forces.cpp), so its second and third runs take that
// path: summing the passes' terms per thread instead of in element order made this test fail
// (docs/performance.md, "Force elements' Newton-matrix entries on two threads"). The small
// models check that the serial path is untouched by the setting and that a run repeats itself
// (the determinism guarantee).

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "model_generators.hpp"
#include "support/cli_run.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

// A case: the data set text (RESULTS/XRF added so a .res is written) and its command file.
struct Case {
  std::string name, adm, acf;
};

std::string withResults(std::string adm) {
  const std::size_t end = adm.rfind("\nEND");
  EXPECT_NE(end, std::string::npos);
  adm.insert(end + 1, "RESULTS/XRF\n");
  return adm;
}

std::vector<Case> cases() {
  std::vector<Case> all;
  const fs::path joints = openmss::testing::adamsJointsDir();
  for (const char* name : {"Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                           "Spherical_Case02", "Universal_Case01", "Universal_Case02",
                           "Prismatic_Case01", "Prismatic_Case02", "Cylindrical_Case01"}) {
    const std::string model = "test_" + std::string(name);
    // Half a second of each case at the integrator it was run with by ADAMS (gstiff 1e-4).
    all.push_back({name, withResults(slurp(joints / name / (model + ".adm"))),
                   "model.adm\nout\noutput/noseparator\nintegrator/gstiff, error=1.0e-4\n"
                   "simulate/transient, end=0.5, dtout=0.01\nstop\n"});
  }
  const fs::path piston = fs::path(OPENMSS_SOURCE_DIR) / "examples" / "piston";
  all.push_back({"piston", withResults(slurp(piston / "piston.adm")),
                 "model.adm\nout\nsimulate/dynamic, end=0.2, steps=20\nstop\n"});
  using namespace openmss::bench;
  all.push_back({"chain-spatial-60", withResults(spatialPendulumChainAdm(60)),
                 chainAcf("model.adm", "out", 0.5, 10, 1.0e-5)});
  all.push_back({"bushing-40", withResults(bushingChainAdm(40)),
                 chainAcf("model.adm", "out", 0.2, 10, 1.0e-5)});
  return all;
}

// Runs the case in a fresh folder with OPENMSS_THREADS=threads; returns the folder.
fs::path runWith(const Case& c, const char* threads) {
  const fs::path dir = scratch(c.name + "-threads-" + threads);
  write(dir / "model.adm", c.adm);
  write(dir / "run.acf", c.acf);
  setenv("OPENMSS_THREADS", threads, 1);
  const Result r = run("run run.acf --quiet", dir);
  unsetenv("OPENMSS_THREADS");
  EXPECT_EQ(r.status, 0) << c.name << " threads " << threads << "\n" << r.output;
  return dir;
}

TEST(ThreadCount, OutputsAreBitIdenticalForOneAndTwoThreadsAndRunToRun) {
  const std::vector<Case> all = cases();
  long compared = 0;
  for (const Case& c : all) {
    const fs::path one = runWith(c, "1"), two = runWith(c, "2"), again = runWith(c, "2");
    for (const char* ext : {".req", ".res", ".msg"}) {
      const fs::path file = fs::path("out") += ext;
      const std::string reference = slurp(one / file);
      ASSERT_FALSE(reference.empty()) << c.name << ": no " << ext;
      EXPECT_TRUE(slurp(two / file) == reference) << c.name << ": " << ext << " 1 vs 2 threads";
      EXPECT_TRUE(slurp(again / file) == reference) << c.name << ": " << ext << " run to run";
      compared += 2;
    }
    for (const fs::path& dir : {one, two, again}) fs::remove_all(dir);
  }
  // 12 models x 3 files x 2 comparisons.
  EXPECT_EQ(compared, 12 * 3 * 2);
  std::printf("[ files compared byte for byte: %ld ]\n", compared);
}

TEST(ThreadCount, AnUnacceptableValueIsRejectedBeforeAnyAnalysis) {
  const Case c = cases().front();
  const fs::path dir = scratch("threads-bad");
  write(dir / "model.adm", c.adm);
  write(dir / "run.acf", c.acf);
  for (const char* bad : {"0", "two", "-1", "100000"}) {
    setenv("OPENMSS_THREADS", bad, 1);
    const Result r = run("run run.acf --quiet", dir);
    unsetenv("OPENMSS_THREADS");
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_NE(r.output.find("OPENMSS_THREADS=" + std::string(bad) +
                            ": expected a whole number of threads from 1 to 256"),
              std::string::npos)
        << bad << "\n"
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.req")) << bad;
  }
  fs::remove_all(dir);
}

}  // namespace
