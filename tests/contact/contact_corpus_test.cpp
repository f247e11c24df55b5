// The corpus data sets (/work/shared/validation/corpus) that hold CONTACT statements, and what
// keeps each CONTACT out (docs/theory.md §6c): all of them name EXTERNAL Parasolid shells
// (.xmt_txt files that are not in the corpus); every such refusal is a located message naming
// the GRAPHICS. The 40 pairs of CYLINDER/FRUSTUM solids of the two FRS5 analyses (20 each,
// parallel axes side by side) were refused too until frustum-frustum contact was read; none is
// now. No CONTACT of the corpus fails for another reason (a regression test for the solids this
// module reads).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/validation_data.hpp"

namespace openmss::contact_test {
namespace {

namespace fs = std::filesystem;

TEST(ContactCorpus, EveryRefusedContactNamesAMissingShellFile) {
  const fs::path dir = openmss::testing::corpusDir();
  if (!fs::exists(dir)) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  std::vector<fs::path> sets;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".adm") sets.push_back(e.path());
  std::sort(sets.begin(), sets.end());
  int decks = 0, refusals = 0, shells = 0, pairs = 0, frustumPairs = 0;
  for (const fs::path& adm : sets) {
    Diagnostics diags;
    language::Dataset dataset;
    language::readDatasetFile(adm.string(), dataset, diags);
    const bool hasContact = std::any_of(dataset.statements.begin(), dataset.statements.end(),
                                        [](const auto& s) { return s.name == "CONTACT"; });
    if (!hasContact) continue;
    ++decks;
    model::Model m;
    model::buildModel(dataset, m, diags);
    for (const model::Contact& c : m.contacts)
      frustumPairs += c.iSolids.front().shape == model::ContactSolid::Shape::Frustum &&
                      c.jSolids.front().shape == model::ContactSolid::Shape::Frustum;
    for (const auto& d : diags.all()) {
      if (d.severity != Severity::Error || d.subject.rfind("CONTACT/", 0) != 0) continue;
      ++refusals;
      const std::string text = format(d);
      EXPECT_GT(d.where.line, 0) << text;
      const bool shell = text.find(".xmt_txt', which is missing") != std::string::npos;
      const bool pair = text.find("two CYLINDER/FRUSTUM solids") != std::string::npos;
      shells += shell;
      pairs += pair;
      EXPECT_TRUE(shell || pair) << adm.filename().string() << ": " << text;
    }
  }
  std::printf(
      "corpus CONTACT: %d data sets, %d refusals (%d missing shell files, %d frustum "
      "pairs); %d frustum-frustum CONTACTs built\n",
      decks, refusals, shells, pairs, frustumPairs);
  EXPECT_EQ(decks, 4);  // the two LAUL analyses, camelot, adams_vscode's test
  EXPECT_EQ(refusals, shells + pairs);
  // Counted on the corpus as held: 405 refusals before frustum pairs were read (365 shells,
  // 40 frustum pairs); the shells remain.
  EXPECT_EQ(shells, 365);
  EXPECT_EQ(pairs, 0);
  EXPECT_EQ(refusals, 365);
  EXPECT_EQ(frustumPairs, 40);  // built as elements now (FRS5: 20 in each analysis)
}

}  // namespace
}  // namespace openmss::contact_test
