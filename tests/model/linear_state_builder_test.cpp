// LSE and TFSISO statements (model/linear_state_builder.cpp): the matrices an LSE takes from its
// MATRIX statements, the sizes it gives its X and Y arrays, its initial states, and the
// controllable canonical form of a TFSISO, against matrices written out by hand
// (docs/theory.md §4a). All values are small ratios of integers that the builder forms with one
// division each, so they are compared exactly.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

Model buildOk(const std::string& statements) {
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(
      "linear states\nUNITS/SYSTEM=NONE\nPART/1, GROUND\n" + statements + "END\n", "l.adm", dataset,
      diags);
  Model model;
  const bool ok = buildModel(dataset, model, diags);
  std::string all;
  for (const auto& d : diags.all()) all += format(d) + "\n";
  EXPECT_TRUE(ok) << all;
  return model;
}

Eigen::MatrixXd matrix(int rows, int cols, std::vector<double> byRows) {
  Eigen::MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) m(r, c) = byRows[static_cast<size_t>(r * cols + c)];
  return m;
}

TEST(LinearStateBuilder, TfsisoControllableCanonicalForm) {
  // H(s) = (1 + 2 s) / (4 + 6 s + 2 s^2): divided by the leading 2, x1' = x2,
  // x2' = u - 2 x1 - 3 x2, y = 0.5 x1 + x2 (strictly proper: D = 0).
  // G(s) = (1 + s^2) / (2 + 3 s + s^2) = 1 + (-1 - 3 s) / (2 + 3 s + s^2): C = [-1, -3], D = 1.
  const Model m = buildOk(
      "VARIABLE/1, FUNCTION=1\n"
      "ARRAY/1, U, VARIABLES=1\n"
      "ARRAY/2, X\n"
      "ARRAY/3, Y\n"
      "ARRAY/4, X\n"
      "ARRAY/5, Y\n"
      "TFSISO/1, X=2, U=1, Y=3, NUMERATOR=1, 2, DENOMINATOR=4, 6, 2\n"
      "TFSISO/2, X=4, U=1, Y=5, NUMERATOR=1, 0, 1, DENOMINATOR=2, 3, 1\n");
  ASSERT_EQ(m.linearStates.size(), 2u);
  const LinearStateElement& h = m.linearStates[0];
  EXPECT_EQ(h.a, matrix(2, 2, {0, 1, -2, -3}));
  EXPECT_EQ(h.b, matrix(2, 1, {0, 1}));
  EXPECT_EQ(h.c, matrix(1, 2, {0.5, 1}));
  EXPECT_EQ(h.d, matrix(1, 1, {0}));
  EXPECT_EQ(h.ic, Eigen::VectorXd::Zero(2));
  const LinearStateElement& g = m.linearStates[1];
  EXPECT_EQ(g.a, matrix(2, 2, {0, 1, -2, -3}));
  EXPECT_EQ(g.c, matrix(1, 2, {-1, -3}));
  EXPECT_EQ(g.d, matrix(1, 1, {1}));
  // The arrays take their sizes from the element, and the states follow each other.
  EXPECT_EQ(m.arrays[static_cast<size_t>(h.xArray)].size, 2);
  EXPECT_EQ(m.arrays[static_cast<size_t>(h.yArray)].size, 1);
  EXPECT_EQ(h.firstState, 0);
  EXPECT_EQ(g.firstState, 2);
}

TEST(LinearStateBuilder, LseTakesItsMatricesAndInitialStates) {
  const Model m = buildOk(
      "VARIABLE/1, FUNCTION=1\n"
      "VARIABLE/2, FUNCTION=2\n"
      "DIFF/1, FUNCTION=0\n"
      "ARRAY/1, U, VARIABLES=1, 2\n"
      "ARRAY/2, X\n"
      "ARRAY/3, Y, SIZE=1\n"
      "ARRAY/4, IC, NUMBERS=0.5, -0.25\n"
      "MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=2, VALUES=0, 1, -4, -0.5\n"
      "MATRIX/2, FULL=RORDER, ROWS=2, COLUMNS=2, VALUES=1, 0, 0, 2\n"
      "MATRIX/3, FULL=CORDER, ROWS=1, COLUMNS=2, VALUES=3, 4\n"
      "LSE/1, X=2, U=1, Y=3, IC=4, A=1, B=2, C=3, STATIC_HOLD\n");
  ASSERT_EQ(m.linearStates.size(), 1u);
  const LinearStateElement& e = m.linearStates[0];
  EXPECT_EQ(e.kind, LinearStateElement::Kind::Lse);
  EXPECT_EQ(e.a, matrix(2, 2, {0, 1, -4, -0.5}));
  EXPECT_EQ(e.b, matrix(2, 2, {1, 0, 0, 2}));
  EXPECT_EQ(e.c, matrix(1, 2, {3, 4}));
  EXPECT_EQ(e.d, Eigen::MatrixXd::Zero(1, 2));  // no D: zero, outputs x inputs
  EXPECT_EQ(e.ic, (Eigen::VectorXd(2) << 0.5, -0.25).finished());
  EXPECT_TRUE(e.staticHold);
  EXPECT_EQ(m.arrays[static_cast<size_t>(e.xArray)].size, 2);
  EXPECT_EQ(e.firstState, 1);  // after the one DIFF
}

}  // namespace
}  // namespace openmss::model
