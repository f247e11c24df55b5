// SPLINE, CURVE, MATRIX and STRING in the model (src/model/data_element_builder.cpp): what is
// built from the data set, every input error in one pass with its exact text, unknown data
// ids in expressions located at their column, and every data element of the validation corpus.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/data_element_builder.hpp"
#include "model/model_builder.hpp"
#include "support/validation_data.hpp"

namespace openmss::model {
namespace {

std::vector<std::string> messages(const Diagnostics& diags) {
  std::vector<std::string> out;
  for (const auto& d : diags.all()) out.push_back(format(d));
  return out;
}

TEST(DataElements, BuildsSplinesFamiliesMatricesCurvesAndStrings) {
  const std::string text =
      "data elements\n"
      "PART/1, GROUND\n"
      "SPLINE/5, X=0,1,2,3, Y=-1,0,1,4,9, Y=1,0,1,2,3\n"
      "SPLINE/6, X=0,1,2,3, Y=0,1,4,9, LINEAR_EXTRAPOLATE\n"
      "STRING/3, STRING=Hello World\n"
      "MATRIX/1, FULL=RORDER, ROWS=4, COLUMNS=3, VALUES=0,0,0, 450,-50,0\n"
      ", 850,-50,0, 1300,0,0\n"
      "MATRIX/2, FULL=CORDER, ROWS=2, COLUMNS=3, VALUES=1,2,3,4,5,6\n"
      "MATRIX/4, SPARSE, ROWS=3, COLUMNS=3, I=1,3, J=2,3, VALUES=7,8\n"
      "CURVE/1, OPEN, MATRIX=1, CURVE_POINTS, ORDER=2\n"
      "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "d.adm", dataset, diags);
  Model model;
  ASSERT_TRUE(buildModel(dataset, model, diags)) << messages(diags).front();
  ASSERT_EQ(model.splines.size(), 2u);
  const Spline& family = *model.splines[model.splineIndex.at(5)].spline;
  EXPECT_EQ(family.curveCount(), 2u);
  EXPECT_EQ(family.z(), (std::vector<double>{-1.0, 1.0}));
  // z = 0 is halfway between the curves y = x^2 and y = x: at x = 2, (4 + 2) / 2.
  EXPECT_NEAR(family.evaluate(SplineMethod::Cubic, 2.0, 0.0, 0).g, 3.0, 1e-14);
  const Spline& single = *model.splines[model.splineIndex.at(6)].spline;
  EXPECT_TRUE(single.linearExtrapolation());
  EXPECT_EQ(model.strings.at(0).text, "Hello World");
  const Eigen::MatrixXd& rows = model.matrices[model.matrixIndex.at(1)].values;
  EXPECT_EQ(rows(2, 0), 850.0);
  EXPECT_EQ(rows(2, 1), -50.0);
  const Eigen::MatrixXd& columns = model.matrices[model.matrixIndex.at(2)].values;
  EXPECT_EQ(columns(1, 0), 2.0);  // column order: (1,1) (2,1) (1,2) ...
  EXPECT_EQ(columns(0, 2), 5.0);
  const Eigen::MatrixXd& sparse = model.matrices[model.matrixIndex.at(4)].values;
  EXPECT_EQ(sparse(0, 1), 7.0);
  EXPECT_EQ(sparse(2, 2), 8.0);
  EXPECT_EQ(sparse.sum(), 15.0);
  ASSERT_EQ(model.curves.size(), 1u);
  double d[5];
  model.curves[0].curve->derivatives(1.0, 0, d);
  EXPECT_NEAR(d[0], 1300.0, 1e-12);
}

TEST(DataElements, EveryInputErrorIsReportedInOnePass) {
  const std::string text =
      "bad data\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "MARKER/11, PART=1, QP=1,0,0\n"
      "SPLINE/1, X=0,1,2, Y=0,1,2\n"
      "SPLINE/2, X=0,2,1,3, Y=0,1,2,3\n"
      "SPLINE/3, X=0,1,2,3, Y=0,1,2\n"
      "SPLINE/4, X=0,1,2,3, Y=2,0,1,2,3, Y=1,0,1,2,3\n"
      "SPLINE/5, FILE=road.rsp\n"
      "MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=3, VALUES=1,2,3\n"
      "MATRIX/2, FULL=RORDER, ROWS=4, COLUMNS=2, VALUES=1,2,3,4,5,6,7,8\n"
      "CURVE/1, MATRIX=2\n"
      "CURVE/2, MATRIX=9\n"
      "CURVE/3, FUNCTION=USER(1)\n"
      "SFORCE/1, TRANSLATION, I=11, J=10, FUNCTION=3*AKISPL(DM(11,10), 0, 99)\n"
      "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "bad.adm", dataset, diags);
  ASSERT_FALSE(diags.hasErrors()) << messages(diags).front();
  Model model;
  EXPECT_FALSE(buildModel(dataset, model, diags));
  const std::vector<std::string> expected = {
      "bad.adm:5:11: error: SPLINE/1: X has 3 values, a SPLINE needs at least 4. Add points: the "
      "interpolation methods need four or more.",
      "bad.adm:6:11: error: SPLINE/2: X must increase strictly, but value 3 (1) is not above the "
      "one before it. Sort the points by X and remove repeated X values.",
      "bad.adm:7:22: error: SPLINE/3: Y has 3 values, but X has 4 (a curve of a family has 5: "
      "its z first). Give one y per x: Y=y1,...,yn for one curve, or Y=z,y1,...,yn for each "
      "curve of a family.",
      "bad.adm:8:35: error: SPLINE/4: the z values of a family of curves (first value of each "
      "Y) must increase. Order the Y= arguments by increasing z.",
      "bad.adm:9:11: error: SPLINE/5: SPLINE data from a FILE (BLOCK, CHANNEL) is not supported "
      "yet without a SPLINE_READ reader. List the values in the data set with X=x1,...,xn and "
      "Y=y1,...,yn, or give ROUTINE=lib::name for a user SPLINE_READ that reads the file.",
      "bad.adm:10:43: error: MATRIX/1: VALUES has 3 numbers, but ROWS*COLUMNS = 6. Give every "
      "entry of the matrix.",
      "bad.adm:12:10: error: CURVE/1: MATRIX/2 has 2 columns; a CURVE needs 3 (x, y, z of each "
      "point). Give the points as rows x, y, z (z = 0 for a planar curve).",
      "bad.adm:13:10: error: CURVE/2: MATRIX/9 does not exist. Use the id of a MATRIX "
      "statement of this data set.",
      "bad.adm:14:10: error: CURVE/3: FUNCTION=USER(...) needs the user subroutine CURSUB, and "
      "no user library is named: the statement has no ROUTINE=lib::name and no default library "
      "was given (openmss run --user-library LIB). Supply the library that defines CURSUB "
      "(ROUTINE=lib::name on the statement, or openmss run --user-library LIB); "
      "docs/user-subroutines.md says how to build one.",
      "bad.adm:15:47: error: SFORCE/1: AKISPL: SPLINE/99 does not exist. Use the id of a "
      "SPLINE statement of this data set.",
  };
  EXPECT_EQ(messages(diags), expected);
}

TEST(DataElements, MotionFunctionsBindSplinesAndReportUnknownIds) {
  const std::string text =
      "motion\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2\n"
      "JOINT/1, REVOLUTE, I=20, J=10\n"
      "MOTION/1, JOINT=1, ROTATION, FUNCTION=CUBSPL(TIME, 0, 8) + CURVE(TIME, 0, 1, 3)\n"
      "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "m.adm", dataset, diags);
  Model model;
  EXPECT_FALSE(buildModel(dataset, model, diags));
  EXPECT_EQ(messages(diags),
            (std::vector<std::string>{
                "m.adm:7:39: error: MOTION/1: CUBSPL: SPLINE/8 does not exist. Use the id of a "
                "SPLINE statement of this data set.",
                "m.adm:7:60: error: MOTION/1: CURVE: CURVE/3 does not exist. Use the id of a "
                "CURVE statement of this data set."}));
}

// Every SPLINE, MATRIX, STRING and CURVE of the validation corpus, through the data-element
// builder alone (the files hold statements the solver does not support yet). The only
// refusals are the user-subroutine curves (FUNCTION=USER, CURSUB) whose library the corpus
// does not hold (adrill_solver): each must name CURSUB and the library.
TEST(DataElements, EveryCorpusDataElementBuilds) {
  const std::filesystem::path corpus = openmss::testing::corpusDir();
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  int splines = 0, matrices = 0, curves = 0, strings = 0, files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    if (entry.path().extension() != ".adm") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    Diagnostics readDiags;
    language::Dataset dataset;
    language::readDatasetText(buffer.str(), entry.path().filename().string(), dataset, readDiags);
    std::size_t expectedSplines = 0, expectedMatrices = 0, expectedCurves = 0, expectedStrings = 0;
    for (const auto& s : dataset.statements) {
      expectedSplines += s.name == "SPLINE";
      expectedMatrices += s.name == "MATRIX";
      expectedStrings += s.name == "STRING";
      expectedCurves += s.name == "CURVE" && !s.has("FUNCTION");
    }
    if (expectedSplines + expectedMatrices + expectedCurves + expectedStrings == 0) continue;
    ++files;
    Diagnostics diags;
    Model model;
    buildDataElements(dataset, model, diags);
    for (const auto& d : diags.all()) {
      EXPECT_NE(format(d).find("cannot load the user library adrill_solver for CURSUB"),
                std::string::npos)
          << format(d);
    }
    EXPECT_EQ(model.splines.size(), expectedSplines) << entry.path();
    EXPECT_EQ(model.matrices.size(), expectedMatrices) << entry.path();
    EXPECT_EQ(model.curves.size(), expectedCurves) << entry.path();
    EXPECT_EQ(model.strings.size(), expectedStrings) << entry.path();
    splines += static_cast<int>(model.splines.size());
    matrices += static_cast<int>(model.matrices.size());
    curves += static_cast<int>(model.curves.size());
    strings += static_cast<int>(model.strings.size());
  }
  std::printf("corpus: %d files, %d SPLINE, %d MATRIX, %d CURVE, %d STRING built\n", files, splines,
              matrices, curves, strings);
  EXPECT_GT(splines, 0);
  EXPECT_GT(curves, 0);
}

}  // namespace
}  // namespace openmss::model
