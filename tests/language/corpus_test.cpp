// Reads every real data set and command file of the shared corpus: none may crash the reader,
// and each is either clean or every diagnostic names a file and a line.

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "language/reader.hpp"
#include "language/schema.hpp"
#include "support/validation_data.hpp"

namespace openmss::language {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = openmss::testing::corpusDir();

std::vector<fs::path> corpusFiles(const std::string& extension) {
  std::vector<fs::path> files;
  if (!fs::is_directory(kCorpus)) return files;
  for (const auto& e : fs::directory_iterator(kCorpus))
    if (e.path().extension() == extension) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

void expectLocated(const Diagnostics& diags) {
  for (const auto& d : diags.all()) {
    EXPECT_FALSE(d.where.file.empty()) << format(d);
    EXPECT_GT(d.where.line, 0) << format(d);
  }
}

TEST(Corpus, EveryDataSetReadsWithoutCrashAndWithLocatedDiagnostics) {
  auto files = corpusFiles(".adm");
  if (files.empty()) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  int clean = 0;
  std::map<std::string, int> unsupported;
  for (const auto& f : files) {
    Dataset ds;
    Diagnostics diags;
    readDatasetFile(f.string(), ds, diags);
    expectLocated(diags);
    if (diags.all().empty()) ++clean;
    for (const auto& d : diags.all()) std::cout << "  " << format(d) << "\n";
    for (const auto& s : ds.statements)
      if (!findStatementSpec(s.name)->solverSupported) ++unsupported[s.name];
  }
  std::cout << "[corpus] " << clean << " of " << files.size()
            << " data sets read without any diagnostic\n[corpus] statements read that the "
               "solver does not support yet:";
  for (const auto& [name, count] : unsupported) std::cout << " " << name << "(" << count << ")";
  std::cout << "\n";
}

TEST(Corpus, EveryCommandFileReadsWithoutCrashAndWithLocatedDiagnostics) {
  auto files = corpusFiles(".acf");
  if (files.empty()) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  int clean = 0;
  std::map<std::string, int> unsupported;
  for (const auto& f : files) {
    CommandFile cf;
    Diagnostics diags;
    readCommandFile(f.string(), cf, diags);
    expectLocated(diags);
    if (diags.all().empty()) ++clean;
    for (const auto& d : diags.all()) std::cout << "  " << format(d) << "\n";
    for (const auto& c : cf.commands)
      if (!findCommandSpec(c.name)->solverSupported) ++unsupported[c.name];
  }
  std::cout << "[corpus] " << clean << " of " << files.size()
            << " command files read without any diagnostic\n[corpus] commands read that the "
               "solver does not support yet:";
  for (const auto& [name, count] : unsupported) std::cout << " " << name << "(" << count << ")";
  std::cout << "\n";
}

}  // namespace
}  // namespace openmss::language
