// INTEGRATOR formulations (docs/integrators.md, "DSTIFF and ABAM"): DSTIFF always runs on the
// SI2 form, so SI2 is accepted with it and an explicit I3, which it cannot honour, is reported
// with a warning at its column; SI2 on an integrator outside GSTIFF, WSTIFF and DSTIFF stays an
// error at its column.

#include <gtest/gtest.h>

#include <string>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

const char* kPendulum =
    "pendulum\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-1\n";

struct Built {
  Model model;
  std::string errors, warnings;
};

Built build(const std::string& integrator) {
  Built b;
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(std::string(kPendulum) + integrator + "\nEND\n", "p.adm", ds, d);
  buildModel(ds, b.model, d);
  for (const auto& x : d.all())
    (x.severity == Severity::Error ? b.errors : b.warnings) += format(x) + "\n";
  return b;
}

TEST(IntegratorFormulation, DstiffAcceptsSi2) {
  const Built b = build("INTEGRATOR/DSTIFF, SI2, ERROR=1e-6");
  EXPECT_EQ(b.errors, "");
  EXPECT_EQ(b.warnings, "");
  EXPECT_EQ(b.model.integrator.type, IntegratorType::Dstiff);
  EXPECT_EQ(b.model.integrator.formulation, IntegratorFormulation::Si2);
}

TEST(IntegratorFormulation, DstiffWithoutAFormulationIsSilent) {
  const Built b = build("INTEGRATOR/DSTIFF, ERROR=1e-6");
  EXPECT_EQ(b.errors, "");
  EXPECT_EQ(b.warnings, "");
}

TEST(IntegratorFormulation, DstiffReportsAnExplicitI3AtItsColumn) {
  const Built b = build("INTEGRATOR/DSTIFF, I3");
  EXPECT_EQ(b.errors, "");
  // Line 10 of the data set; I3 starts at column 20.
  EXPECT_NE(b.warnings.find("p.adm:10:20: warning: INTEGRATOR: DSTIFF always runs on the SI2 "
                            "formulation"),
            std::string::npos)
      << b.warnings;
}

TEST(IntegratorFormulation, Si2IsRefusedOnHhtAtItsColumn) {
  const Built b = build("INTEGRATOR/HHT, SI2");
  EXPECT_NE(b.errors.find("p.adm:10:17: error: INTEGRATOR: the SI2 formulation applies to "
                          "GSTIFF, WSTIFF and DSTIFF, not to HHT"),
            std::string::npos)
      << b.errors;
}

}  // namespace
}  // namespace openmss::model
