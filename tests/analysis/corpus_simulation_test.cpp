// Every corpus data set (/work/shared/validation/corpus) whose statements the model builder
// accepts is simulated with its own command file, or, when it has none, with the default
// SIMULATE/DYNAMICS, END=1, DTOUT=0.01 (a data set holds no end time; docs/validation.md,
// "Corpus simulations"), and must reach its END without failure. The others are listed with
// the statements that keep them out. Total time about 2 s of CPU (measured): no shortened END.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
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
    const Result r = run("run run.acf --quiet", dir);
    EXPECT_EQ(r.status, 0) << base << " with " << how << ":\n" << r.output;
    bool ended = false;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".msg") ended |= slurp(e.path()).find(" End Simulation") !=
                                                   std::string::npos;
    EXPECT_TRUE(ended) << base;
    if (r.status == 0 && ended) {
      simulated.push_back(base);
      std::cout << "simulates to END: " << base << " (" << how << ")\n";
    }
    fs::remove_all(dir);
  }
  // The data sets that simulated when this test was written must keep doing so.
  for (const char* must : {"MarcinPiotrowski__MultiBodySystemDynamics__MODEL_1",
                           "MarcinPiotrowski__MultiBodySystemDynamics__MODEL_test10",
                           "MarcinPiotrowski__MultiBodySystemDynamics__MODEL_test7",
                           "MarcinPiotrowski__MultiBodySystemDynamics__force_test",
                           "MarcinPiotrowski__MultiBodySystemDynamics__lwr_6dof",
                           "bthornton191__adamspy__test__files__generic_model__generic_model"})
    EXPECT_NE(std::find(simulated.begin(), simulated.end(), must), simulated.end()) << must;
}

}  // namespace
