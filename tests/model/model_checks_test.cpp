// Model-level checks after reading (docs/language.md, "From data set to model"): one data set
// with seven independent errors must report all seven in one pass, each with file:line:column,
// the statement and its id, and what to change.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

TEST(ModelChecks, SixIndependentErrorsAndAWarningAreReportedInOnePass) {
  const std::string text =
      "Seven independent model errors\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "MARKER/11, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2\n"
      "MARKER/21, PART=99\n"               // unknown part
      "PART/3, MASS=2, CM=10, IP=1,1,1\n"  // CM on another part
      "PART/4, GROUND\n"                   // a second ground
      "PART/5, MASS=1, CM=50, IP=1,1,5\n"  // 1 + 1 < 5: no such body (ADAMS runs it)
      "MARKER/50, PART=5\n"
      "PART/6, CM=60, IP=1,1,1\n"  // no MASS: massless, checked at set-up
      "MARKER/60, PART=6\n"
      "JOINT/1, REVOLUTE, I=10, J=11\n"   // both markers on ground
      "JOINT/2, SPHERICAL, I=20, J=77\n"  // unknown marker
      "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "m.adm", dataset, diags);
  ASSERT_FALSE(diags.hasErrors());  // the reader finds nothing: these are model errors
  Model model;
  EXPECT_FALSE(buildModel(dataset, model, diags));
  std::vector<std::string> lines;
  for (const auto& d : diags.all()) lines.push_back(format(d));
  EXPECT_EQ(lines,
            (std::vector<std::string>{
                "m.adm:9:1: error: PART/4: a data set may have only one ground part; PART/1 is "
                "ground already. Remove GROUND from one of them.",
                "m.adm:7:12: error: MARKER/21: PART/99 does not exist. Use the id of a PART "
                "statement of this data set.",
                "m.adm:8:17: error: PART/3: CM marker 10 is not a marker of this part. Give a "
                "MARKER with PART=3.",
                "m.adm:10:24: warning: PART/5: the principal moments break the triangle "
                "inequality (no rigid body has them); the run uses them as given, as ADAMS "
                "does. Check IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz] if this is not deliberate.",
                "m.adm:14:1: error: JOINT/1: I and J markers are on the same part (PART/1). A "
                "joint connects two parts: put I and J on different parts.",
                "m.adm:15:27: error: JOINT/2: J=77: marker 77 does not exist. Use the id of a "
                "MARKER statement of this data set."}));
}

TEST(ModelChecks, ADataSetWithoutGroundSaysSo) {
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText("No ground\nPART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nEND\n",
                            "g.adm", dataset, diags);
  Model model;
  EXPECT_FALSE(buildModel(dataset, model, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "g.adm: error: the data set has no ground part. Add PART/<id>, GROUND.");
}

}  // namespace
}  // namespace openmss::model
