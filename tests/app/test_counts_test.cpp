// scripts/ctest_counts.sh, the last line of scripts/test.sh: skipped tests are counted as
// skipped, not as passed (ctest's own summary line counts them as passed). The logs below are
// ctest 3.25 console output in the layout `ctest --output-on-failure -j 2` prints (test lines
// trimmed).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;  // scratch, slurp, write (tests/support)

// Runs the script on `log`; its stdout (and stderr) and exit status.
Result counts(const std::string& log, const fs::path& dir) {
  write(dir / "ctest.log", log);
  const std::string cmd = "bash '" OPENMSS_SOURCE_DIR "/scripts/ctest_counts.sh' '" +
                          (dir / "ctest.log").string() + "' > '" + (dir / "out.txt").string() +
                          "' 2>&1";
  const int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.output = slurp(dir / "out.txt");
  return r;
}

TEST(TestCounts, SkippedTestsAreCountedApartFromPassedOnes) {
  const fs::path dir = scratch("counts");
  const Result r = counts(
      "Test project /work/build\n"
      "      Start  1: Suite.A\n"
      " 1/5 Test  #1: Suite.A ..........................   Passed    0.01 sec\n"
      " 2/5 Test  #2: Corpus.B .........................***Skipped   0.01 sec\n"
      " 3/5 Test  #3: Suite.C ..........................***Failed    0.02 sec\n"
      " 4/5 Test  #4: Corpus.D .........................***Skipped   0.01 sec\n"
      " 5/5 Test  #5: Suite.E ..........................   Passed    0.01 sec\n"
      "\n"
      "80% tests passed, 1 tests failed out of 5\n"
      "\n"
      "Label Time Summary:\n"
      "app    =   0.06 sec*proc (5 tests)\n"
      "\n"
      "Total Test time (real) =   0.07 sec\n"
      "\n"
      "The following tests did not run:\n"
      "\t  2 - Corpus.B (Skipped)\n"
      "\t  4 - Corpus.D (Skipped)\n"
      "\n"
      "The following tests FAILED:\n"
      "\t  3 - Suite.C (Failed)\n"
      "Errors while running CTest\n",
      dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "2 passed, 1 failed, 2 skipped\n");
  fs::remove_all(dir);
}

TEST(TestCounts, ARunWithoutSkipsOrFailures) {
  const fs::path dir = scratch("counts-clean");
  const Result r = counts(
      "100% tests passed, 0 tests failed out of 686\n"
      "\n"
      "Total Test time (real) = 300.00 sec\n",
      dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "686 passed, 0 failed, 0 skipped\n");
  fs::remove_all(dir);
}

TEST(TestCounts, ALogWithoutASummaryIsAnError) {
  const fs::path dir = scratch("counts-none");
  const Result r = counts("No tests were found!!!\n", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("no ctest summary line"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
