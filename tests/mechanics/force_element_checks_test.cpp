// Data-set checks of the force elements (model/force_element_builder.cpp): every problem of a
// faulty data set is reported in one pass, with the statement and what to change.

#include <gtest/gtest.h>

#include <string>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

// Every diagnostic of a data set, formatted.
std::string diagnose(const std::string& elements) {
  const std::string text =
      "faulty force elements\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "MARKER/11, PART=1, REULER=0,90D,0\n"
      "MARKER/12, PART=1, FLOATING\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2\n"
      "MARKER/21, PART=2, QP=1,0,0\n"
      "MARKER/22, PART=2, FLOATING\n" +
      elements + "END\n";
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "faulty.adm", ds, d);
  Model m;
  buildModel(ds, m, d);
  std::string out;
  for (const auto& x : d.all()) out += format(x) + "\n";
  return out;
}

void expectHas(const std::string& all, const std::string& what) {
  EXPECT_NE(all.find(what), std::string::npos) << "missing: " << what << "\nin:\n" << all;
}

TEST(ForceElementChecks, EveryProblemIsReportedInOnePass) {
  const std::string all = diagnose(
      "SPRINGDAMPER/1, TRANSLATIONAL, ROTATIONAL, I=20, J=10, K=1\n"
      "SPRINGDAMPER/2, TRANSLATIONAL, I=20, J=10, K=1, KT=3\n"
      "SPRINGDAMPER/3, ROTATIONAL, I=20, J=11, KT=1\n"
      "SPRINGDAMPER/4, TRANSLATIONAL, I=20, J=10, K=-1\n"
      "SPRINGDAMPER/5, TRANSLATIONAL, I=20, J=21, K=1\n"
      "BUSHING/1, I=21, J=10, K=1,-2,3\n"
      "FIELD/1, I=21, J=10, CRATIO=0.1\n"
      "FIELD/2, I=21, J=10, KMATRIX=" + [] {
        std::string k;
        for (int n = 0; n < 36; ++n) k += n ? ",1" : "1";
        return k;
      }() + ", CRATIO=0.1, CMATRIX=" + [] {
        std::string k;
        for (int n = 0; n < 36; ++n) k += n ? ",1" : "1";
        return k;
      }() + "\n"
      "BEAM/1, I=21, J=10, LENGTH=1, AREA=1, IXX=1, IYY=1, IZZ=1, GMODULUS=1\n"
      "BEAM/2, I=21, J=10, LENGTH=1, AREA=1, IXX=1, IYY=1, IZZ=1, EMODULUS=1, GMODULUS=1,"
      " FORMULATION=NONLINEAR\n"
      "VFORCE/1, I=20, JFLOAT=10, RM=10, FX=1\n"
      "VFORCE/2, I=20, JFLOAT=12, FX=1\n"
      "VTORQUE/1, I=20, JFLOAT=12, RM=10\n"
      "GFORCE/1, I=20, JFLOAT=22, RM=10, FX=1\n"
      "JOINT/1, SPHERICAL, I=20, J=12\n");
  expectHas(all, "SPRINGDAMPER/1: give exactly one of TRANSLATIONAL and ROTATIONAL");
  expectHas(all, "SPRINGDAMPER/2: KT belongs to a ROTATIONAL spring-damper");
  expectHas(all, "SPRINGDAMPER/3: the z axes of I and J must be parallel");
  expectHas(all, "SPRINGDAMPER/4: K must not be negative");
  expectHas(all, "SPRINGDAMPER/5: I and J are on the same part");
  expectHas(all, "BUSHING/1: K must not be negative");
  expectHas(all, "FIELD/1: missing required argument KMATRIX");
  expectHas(all, "FIELD/2: give CMATRIX or CRATIO, not both");
  expectHas(all, "BEAM/1: missing required argument EMODULUS");
  expectHas(all, "BEAM/2: FORMULATION=NONLINEAR is not supported yet");
  expectHas(all, "VFORCE/1: JFLOAT=10 must be a FLOATING marker");
  expectHas(all, "VFORCE/2: missing required argument RM");
  expectHas(all, "VTORQUE/1: no component is given");
  expectHas(all, "GFORCE/1: I and JFLOAT are on the same part");
  expectHas(all, "JOINT/1: J=12: marker 12 is FLOATING");
  // Each line names the file and line of the statement.
  expectHas(all, "faulty.adm:10:");
}

TEST(ForceElementChecks, ACorrectDataSetBuildsWithoutDiagnostics) {
  const std::string all = diagnose(
      "SPRINGDAMPER/1, TRANSLATIONAL, I=21, J=10, K=1, C=0.1, LENGTH=0.5, FORCE=2\n"
      "SPRINGDAMPER/2, ROTATIONAL, I=20, J=10, KT=1, CT=0.1, ANGLE=10D, TORQUE=2\n"
      "BUSHING/1, I=21, J=10, K=1,2,3\n"
      "BEAM/1, I=21, J=10, LENGTH=1, AREA=1, IXX=1, IYY=1, IZZ=1, EMODULUS=1, GMODULUS=1,"
      " CRATIO=0.01\n"
      "VFORCE/1, I=20, JFLOAT=12, RM=10, FX=1\\FZ=-DZ(20,10)\n"
      "GFORCE/1, I=21, JFLOAT=12, RM=20, TZ=SPDP(1,0,4,0)\n"
      "REQUEST/1, F2=BUSH(1,0,2,0)\\F3=BEAM(1,1,6,10)\\F4=GFORCE(1,0,8,0)\\F5=VFORCE(1,0,1,0)\n");
  // GFORCE/1 reads a force element in its function (docs/theory.md §4d): accepted.
  EXPECT_EQ(all.find("GFORCE/1"), std::string::npos) << all;
  EXPECT_EQ(all.find("REQUEST/1"), std::string::npos) << all;
  EXPECT_EQ(all.find("SPRINGDAMPER"), std::string::npos) << all;
  EXPECT_EQ(all.find("BEAM/1"), std::string::npos) << all;
}

}  // namespace
}  // namespace openmss::model
