// Data-set checks of the user equations (VARIABLE, DIFF, ARRAY, LSE, TFSISO, PINPUT, POUTPUT):
// every independent error in one pass, each at its file:line:column with what to change, and
// no follow-on error for a reference to an element that already has one.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

TEST(UserEquationChecks, EveryErrorIsReportedOnceWithItsLine) {
  const std::string text =
      "bad user equations\n"
      "UNITS/ SYSTEM=NONE\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "VARIABLE/1, FUNCTION=VARVAL(7) + DIF(3)\n"  // 5: unknown VARIABLE, DIFF
      "DIFF/1, FUNCTION=ARYVAL(2, 5), IC=1, 2\n"   // 6: position 5 of 1; IC warning
      "ARRAY/2, U, VARIABLES=1, 9\n"               // 7: unknown VARIABLE
      "ARRAY/3, X, U\n"                            // 8: two types
      "ARRAY/4, X\n"                               // 9
      "ARRAY/5, IC, NUMBERS=1, 2, 3\n"             // 10
      "LSE/1, X=5, A=1\n"                          // 11: X names an IC array
      "TFSISO/2, X=4, U=2, Y=6, NUMERATOR=1, 2, 3, DENOMINATOR=1, 0\n"  // 12: three errors
      "MATRIX/1, FULL=RORDER, ROWS=2, COLUMNS=3, VALUES=1,2,3,4,5,6\n"
      "ARRAY/7, Y\n"                // 14: owned by nobody
      "LSE/3, X=4, A=1\n"           // 15: A not square
      "PINPUT/1, VARIABLES=1, 5\n"  // 16: unknown VARIABLE
      "POUTPUT/2, VARIABLES=1\n"
      "VARIABLE/2, FUNCTION=POUVAL(2, 2) + PINVAL(3, 1) + FX(10)\n"  // 18: two errors (FX reads)
      "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "u.adm", dataset, diags);
  ASSERT_FALSE(diags.hasErrors());
  Model model;
  EXPECT_FALSE(buildModel(dataset, model, diags));
  std::string all;
  for (const auto& d : diags.all()) all += format(d) + "\n";
  const std::vector<std::string> expected = {
      "u.adm:5:22: error: VARIABLE/1: VARVAL: VARIABLE/7 does not exist.",
      "u.adm:5:34: error: VARIABLE/1: DIF: DIFF/3 does not exist.",
      "u.adm:6:18: error: DIFF/1: ARYVAL: position 5 is outside ARRAY/2 (it has 1 entries).",
      "u.adm:6:32: warning: DIFF/1: the second IC value",
      "u.adm:7:26: error: ARRAY/2: VARIABLE/9 does not exist.",
      "u.adm:8:1: error: ARRAY/3: X, U, Y and IC exclude each other.",
      "u.adm:11:8: error: LSE/1: X=5 must name an X array; ARRAY/5 is IC.",
      "u.adm:12:21: error: TFSISO/2: ARRAY/6 does not exist.",
      "u.adm:12:45: error: TFSISO/2: the last DENOMINATOR coefficient (highest power of s) is "
      "zero.",
      "u.adm:12:26: error: TFSISO/2: the NUMERATOR has more coefficients than the DENOMINATOR",
      "u.adm:14:1: error: ARRAY/7: this Y array belongs to no LSE, TFSISO or GSE",
      "u.adm:15:13: error: LSE/3: A is 2x3 but must be 2x2 (A is square).",
      "u.adm:16:24: error: PINPUT/1: VARIABLE/5 does not exist.",
      "u.adm:18:22: error: VARIABLE/2: POUVAL: position 2 is outside POUTPUT/2 (it has 1 "
      "entries).",
      "u.adm:18:37: error: VARIABLE/2: PINVAL: PINPUT/3 does not exist.",
  };
  for (const auto& e : expected) EXPECT_NE(all.find(e), std::string::npos) << e << "\n" << all;
  EXPECT_EQ(diags.errorCount(), static_cast<int>(expected.size()) - 1) << all;
  // ARRAY/4 is named by LSE/3 and TFSISO/2 (both with errors): no "belongs to no LSE" for it.
  EXPECT_EQ(all.find("ARRAY/4"), std::string::npos) << all;
}

}  // namespace
}  // namespace openmss::model
