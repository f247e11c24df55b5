// Every function expression in the real data sets of ../shared/validation parses: the corpus
// (23 data sets) and the nine ADAMS joint models. USER(...) expressions call user-written
// subroutines: they parse and keep their constant arguments; the model builder refuses them
// while no subroutine is loaded (never accepted silently).

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "expr/expression.hpp"
#include "language/reader.hpp"

namespace {

namespace fs = std::filesystem;

TEST(CorpusExpressions, EveryFunctionExpressionParses) {
  const fs::path root = fs::path(OPENMSS_SHARED_DIR) / "validation";
  if (!fs::exists(root / "corpus")) GTEST_SKIP() << "shared corpus absent: " << root / "corpus";
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
  EXPECT_GT(parsed, 600);
}

}  // namespace
