// Every corpus command file (/work/shared/validation/corpus/*.acf) with its data set, end to end
// (issue 15): each command of the file is one the solver runs (never "not supported yet"), and
// the data set either builds, and then `openmss run` carries out every command to the end and
// `openmss check` finds nothing, or the test names the statements the data set still lacks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "language/schema.hpp"
#include "model/model_builder.hpp"
#include "support/cli_run.hpp"
#include "support/corpus_decks.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

std::string withoutCarriageReturns(std::string s) {
  s.erase(std::remove(s.begin(), s.end(), '\r'), s.end());
  return s;
}

// The corpus keeps files flat as <origin>__<name>.adm: the data set of `acf` is the one with
// the command file's own base name, else the one that ends in __<model name>.adm.
fs::path dataSetOf(const fs::path& acf, const std::string& model) {
  fs::path same = acf;
  same.replace_extension(".adm");
  if (fs::exists(same)) return same;
  for (const auto& e : fs::directory_iterator(acf.parent_path())) {
    const std::string n = e.path().filename().string();
    if (n.size() > model.size() + 6 && n.ends_with("__" + model + ".adm")) return e.path();
  }
  return {};
}

TEST(CorpusCommandFiles, EveryCommandRunsOrTheDataSetNamesWhatItLacks) {
  const fs::path corpus = corpusDir();
  if (!fs::exists(corpus)) GTEST_SKIP() << corpusAbsentMessage();
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.path().extension() == ".acf") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  int commandsChecked = 0, ranToEnd = 0, lacking = 0;
  for (const fs::path& acf : files) {
    const std::string base = acf.stem().string();
    const std::string text = withoutCarriageReturns(slurp(acf));
    // Every command is one the solver carries out.
    language::CommandFile cf;
    Diagnostics readDiags;
    language::readCommandFile(acf.string(), cf, readDiags);
    EXPECT_FALSE(readDiags.hasErrors()) << base;
    for (const auto& c : cf.commands) {
      const auto* spec = language::findCommandSpec(c.name);
      ASSERT_NE(spec, nullptr) << base << ": " << c.name;
      EXPECT_TRUE(spec->solverSupported) << base << ":" << c.where.line << ": " << c.name;
      ++commandsChecked;
    }
    const std::string model = modelNameOf(text);
    const fs::path adm = dataSetOf(acf, model);
    ASSERT_FALSE(adm.empty()) << base << ": no data set " << model;
    const auto rejected = rejectedStatements(adm);
    if (!rejected.empty()) {
      std::string names;
      for (const auto& n : rejected) names += (names.empty() ? "" : " ") + n;
      std::cout << "data set lacks: " << base << ": " << names << "\n";
      ++lacking;
      continue;
    }
    const fs::path dir = scratch("corpus-acf");
    fs::copy_file(adm, dir / (fs::path(model).has_extension() ? model : model + ".adm"));
    write(dir / "run.acf", text);
    const Result checked = run("check run.acf", dir);
    EXPECT_EQ(checked.status, 0) << base << ":\n" << checked.output;
    const Result r = run("run run.acf --quiet", dir);
    EXPECT_EQ(r.status, 0) << base << ":\n" << r.output;
    if (r.status == 0) {
      ++ranToEnd;
      std::cout << "runs every command: " << base << "\n";
    }
    fs::remove_all(dir);
  }
  std::cout << files.size() << " command files, " << commandsChecked << " commands; " << ranToEnd
            << " run to the end, " << lacking << " wait for their data set\n";
  EXPECT_EQ(ranToEnd + lacking, static_cast<int>(files.size()));
  EXPECT_GT(commandsChecked, 100);
  EXPECT_GE(ranToEnd, 2);  // generic_model and analysis_with_spikes when this was written
}

}  // namespace
