// SPLINE_READ (SPLINE/id, FILE=, BLOCK=, ROUTINE=) in both calling styles
// (tests/user/explicit_routines.c and .f): the spline the reader stores with PUT_SPLINE is the
// one the same values written with X= and Y= give, to the last bit; a reader's failure is a
// located error.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/built_model.hpp"
#include "support/cli_run.hpp"

namespace openmss {
namespace {

const std::string kC = OPENMSS_TEST_C_ROUTINES;
const std::string kF77 = OPENMSS_TEST_F77_ROUTINES;

bool build(const std::string& spline, model::Model& m, std::string* messages) {
  return testing::readAndBuildModel(
      "s\nPART/1, GROUND\n" + spline +
          "VARIABLE/1, FUNCTION=AKISPL(TIME, 0, 5) + CUBSPL(TIME, 0, 5, 1)\nEND\n",
      "s.adm", m, messages);
}

TEST(SplineReader, ReaderGivesTheSplineOfTheListedValues) {
  const std::filesystem::path dir = testing::scratch("spline-read");
  testing::write(dir / "points.txt", "0 1\n1 2.5\n2 2\n3 4.25\n4 3\n");
  model::Model listed;
  std::string messages;
  ASSERT_TRUE(build("SPLINE/5, X=0, 1, 2, 3, 4, Y=2, 5, 4, 8.5, 6\n", listed, &messages))
      << messages;
  int compared = 0;
  for (const std::string& lib : {kC, kF77}) {
    model::Model read;
    ASSERT_TRUE(build("SPLINE/5, FILE=\"" + (dir / "points.txt").string() +
                          "\", BLOCK=DOUBLE, ROUTINE=\"" + lib + "::\"\n",
                      read, &messages))
        << messages;
    for (double t : {-0.5, 0.0, 0.7, 1.5, 2.2, 3.9, 4.6}) {
      EXPECT_EQ(listed.variables[0].function.expression.evaluate(nullptr, t),
                read.variables[0].function.expression.evaluate(nullptr, t))
          << lib << " t=" << t;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 14);
}

TEST(SplineReader, ReaderFailuresAreLocatedErrors) {
  model::Model m;
  std::string all;
  EXPECT_FALSE(
      build("SPLINE/5, FILE=\"/nonexistent/points.txt\", ROUTINE=\"" + kC + "::\"\n", m, &all));
  EXPECT_NE(all.find("s.adm:3:"), std::string::npos) << all;
  EXPECT_NE(all.find("SPLINE_READ (Spline_read) of SPLINE/5 returned IERR = 1"), std::string::npos)
      << all;
  all.clear();
  EXPECT_FALSE(build("SPLINE/5, FILE=points.txt\n", m, &all));
  EXPECT_NE(all.find("without a SPLINE_READ reader"), std::string::npos) << all;
}

}  // namespace
}  // namespace openmss
