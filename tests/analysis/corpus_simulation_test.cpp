// Every corpus data set (/work/shared/validation/corpus) whose statements the model builder
// accepts is simulated with its own command file, or, when it has none, with the default
// SIMULATE/DYNAMICS, END=1, DTOUT=0.01 (a data set holds no end time; docs/validation.md,
// "Corpus simulations"), and must reach its END without failure. Each one is listed with the
// time it reached, its integration steps (the sum of the .msg's "Integrator statistics" lines
// over its simulations) and its output steps (the run summary); the others with the statements
// that keep them out. Where real ADAMS wrote a .msg for the same command file, what the two
// runs share is compared (corpus_msg.hpp): the end time and the zero-DOF warning. Total time
// about 2 s of CPU (measured): no shortened END.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/cli_run.hpp"
#include "support/corpus_decks.hpp"
#include "support/corpus_msg.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

const fs::path kCorpus = openmss::testing::corpusDir();

TEST(CorpusSimulation, EverySupportedDataSetSimulatesToItsEnd) {
  if (!fs::exists(kCorpus)) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  std::vector<fs::path> sets;
  for (const auto& e : fs::directory_iterator(kCorpus))
    if (e.path().extension() == ".adm") sets.push_back(e.path());
  std::sort(sets.begin(), sets.end());
  ASSERT_FALSE(sets.empty());

  std::vector<std::string> simulated;
  int compared = 0;
  for (const fs::path& adm : sets) {
    const std::string base = adm.stem().string();
    const auto rejected = rejectedStatements(adm);
    if (!rejected.empty()) {
      std::string names;
      for (const auto& n : rejected) names += (names.empty() ? "" : " ") + n;
      std::cout << "rejected: " << base << ": " << names << "\n";
      continue;
    }
    const fs::path dir = scratch("corpus");
    fs::path acf = adm;
    acf.replace_extension(".acf");
    std::string commands, how;
    if (fs::exists(acf)) {
      commands = slurp(acf);
      const std::string name = modelNameOf(commands);
      fs::copy_file(adm, dir / (fs::path(name).has_extension() ? name : name + ".adm"));
      how = "its own " + acf.filename().string();
    } else {
      fs::copy_file(adm, dir / "model.adm");
      commands = "model\nmodel\nsimulate/dynamics, end=1, dtout=0.01\nstop\n";
      how = "the default SIMULATE/DYNAMICS, END=1, DTOUT=0.01";
    }
    write(dir / "run.acf", commands);
    // Without --quiet: the run summary line gives the time reached and the output steps.
    const Result r = run("run run.acf", dir);
    EXPECT_EQ(r.status, 0) << base << " with " << how << ":\n" << r.output;
    std::string msg;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".msg") msg = slurp(e.path());
    const MsgRun ours = readOpenMssRun(msg, r.output);
    EXPECT_GT(ours.simulations, 0) << base;
    if (r.status == 0 && ours.simulations > 0) {
      simulated.push_back(base);
      std::printf(
          "simulates to END: %s: end time %g, %ld integration steps, %ld output steps, "
          "%d simulation(s) (%s)\n",
          base.c_str(), ours.endTime, ours.integrationSteps, ours.outputSteps, ours.simulations,
          how.c_str());
      fs::path adamsMsg = adm;
      adamsMsg.replace_extension(".msg");
      if (fs::exists(adamsMsg)) compared += compareWithAdams(base, ours, slurp(adamsMsg));
    }
    fs::remove_all(dir);
  }
  // Real ADAMS .msg files exist for two of the simulated data sets (generic_model and
  // analysis_with_spikes); each gives two comparisons.
  std::printf("compared with real ADAMS .msg files: %d quantities\n", compared);
  EXPECT_GE(compared, 4);
  // The data sets that simulated when this test was written must keep doing so.
  for (const char* must : {"MarcinPiotrowski__MultiBodySystemDynamics__LWR_1",
                           "MarcinPiotrowski__MultiBodySystemDynamics__MODEL_1",
                           "MarcinPiotrowski__MultiBodySystemDynamics__MODEL_test10",
                           "MarcinPiotrowski__MultiBodySystemDynamics__MODEL_test7",
                           "MarcinPiotrowski__MultiBodySystemDynamics__force_test",
                           "MarcinPiotrowski__MultiBodySystemDynamics__lwr_6dof",
                           "MarcinPiotrowski__MultiBodySystemDynamics__test__LWR_6DOF_GRABER",
                           "alex-marinov__mbdyn__contrib__a2m__samples__bipendolo",
                           "bthornton191__adamspy__test__files__analysis_with_spikes__test_"
                           "analysis_with_spikes",
                           "bthornton191__adamspy__test__files__generic_model__generic_model"})
    EXPECT_NE(std::find(simulated.begin(), simulated.end(), must), simulated.end()) << must;
  EXPECT_GE(simulated.size(), 10u);
}

}  // namespace
