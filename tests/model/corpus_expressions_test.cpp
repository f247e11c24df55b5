// Every function expression in the real data sets parses: the nine ADAMS joint models
// (tests/validation/adams-joints) and the corpus (23 data sets, outside the repository). USER(...)
// expressions call user-written subroutines: they parse and keep their constant arguments; the
// model builder refuses them while no subroutine is loaded (never accepted silently).

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "expr/expression.hpp"
#include "language/reader.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;

struct Counts {
  int parsed = 0, user = 0, files = 0;
};

// Parses every expression argument of every .adm under root.
Counts parseEveryExpression(const fs::path& root) {
  int parsed = 0, user = 0, files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".adm") continue;
    ++files;
    openmss::language::Dataset ds;
    openmss::Diagnostics readDiags;
    openmss::language::readDatasetFile(entry.path().string(), ds, readDiags);
    for (const auto& s : ds.statements) {
      for (const auto& a : s.args) {
        if (!a.isExpression) continue;
        openmss::Diagnostics d;
        openmss::expr::Expression e;
        const bool ok = openmss::expr::Expression::parse(a.expression, a.valueWhere, s.subject(),
                                                         d, e);
        if (a.expression.rfind("USER", 0) == 0 || a.expression.rfind("user", 0) == 0) {
          // USER(...) parses and keeps its constants for the subroutine (expr4); the model
          // builder refuses it while no subroutine is loaded.
          ++user;
          EXPECT_TRUE(ok) << a.expression << "\n"
                          << (d.all().empty() ? "" : openmss::format(d.all()[0]));
          if (ok) {
            EXPECT_NE(e.userCall(), nullptr) << a.expression;
          }
          continue;
        }
        EXPECT_TRUE(ok) << entry.path().filename() << ":" << a.where.line << " " << s.subject()
                        << " " << a.name << "=" << a.expression << "\n"
                        << (d.all().empty() ? "" : openmss::format(d.all()[0]));
        if (ok) ++parsed;
      }
    }
  }
  std::cout << files << " data sets: " << parsed << " expressions parse, " << user
            << " USER(...) expressions keep their arguments" << std::endl;
  return {parsed, user, files};
}

TEST(CorpusExpressions, EveryFunctionExpressionOfTheJointModelsParses) {
  const Counts c = parseEveryExpression(openmss::testing::adamsJointsDir());
  EXPECT_EQ(c.files, 9);
  // Their REQUEST columns F2=ORIENT(...), JOINT(...), ...: 96 expressions in the nine files.
  EXPECT_EQ(c.parsed, 96);
  EXPECT_EQ(c.user, 0);
}

TEST(CorpusExpressions, EveryFunctionExpressionOfTheCorpusParses) {
  if (!fs::exists(openmss::testing::corpusDir()))
    GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  const Counts c = parseEveryExpression(openmss::testing::corpusDir());
  EXPECT_EQ(c.files, 23);
  EXPECT_GT(c.parsed, 600);
}

}  // namespace
