// Data-set checks of SENSOR (and of a GSE without arrays): every independent error in one pass at its
// file:line:column with what to change; a valid sensor is built with its arguments; SENVAL(id)
// binds to it from any expression.

#include <gtest/gtest.h>

#include <string>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

std::string buildAndReport(const std::string& text, Model& model, bool* ok) {
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "s.adm", dataset, diags);
  *ok = buildModel(dataset, model, diags);
  std::string all;
  for (const auto& d : diags.all()) all += format(d) + "\n";
  return all;
}

const char* kHeader =
    "sensors\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=1, IP=1,1,1, CM=20, QG=0,0,10\nMARKER/20, PART=2\n";

TEST(SensorChecks, AValidSensorKeepsItsArgumentsAndSenvalBindsToIt) {
  Model m;
  bool ok = false;
  const std::string all = buildAndReport(
      std::string(kHeader) +
          "SENSOR/7, FUNCTION=DZ(20), VALUE=5, LE, ERROR=1e-4, HALT, PRINT, DT=0.5,\n"
          ", STEPSIZE=1e-3, BISECTION, EVALUATE=VZ(20)\n"
          "REQUEST/1, F2=SENVAL(7)\nSFORCE/1, I=20, J=10, TRANSLATION, FUNCTION=SENVAL(7)\n"
          "END\n",
      m, &ok);
  ASSERT_TRUE(ok) << all;
  ASSERT_EQ(m.sensors.size(), 1u);
  const Sensor& s = m.sensors[0];
  EXPECT_EQ(s.id, 7);
  EXPECT_EQ(s.test, Sensor::Test::Le);
  EXPECT_DOUBLE_EQ(s.value, 5.0);
  EXPECT_DOUBLE_EQ(s.error, 1e-4);
  EXPECT_TRUE(s.halt && s.print && s.bisection);
  EXPECT_FALSE(s.restart || s.returnToCommands);
  EXPECT_DOUBLE_EQ(s.outputInterval.value_or(0), 0.5);
  EXPECT_DOUBLE_EQ(s.stepSize.value_or(0), 1e-3);
  ASSERT_TRUE(s.evaluate.has_value());
  ASSERT_EQ(m.requests.size(), 1u);
  ASSERT_EQ(m.requests[0].columns[1]->measures.size(), 1u);
  EXPECT_EQ(m.requests[0].columns[1]->measures[0].kind, MeasureKind::SenVal);
  EXPECT_EQ(m.requests[0].columns[1]->measures[0].element, 0);
}

TEST(SensorChecks, DefaultsAreEqAndAnErrorOfOneThousandth) {
  Model m;
  bool ok = false;
  const std::string all = buildAndReport(
      std::string(kHeader) + "SENSOR/1, FUNCTION=DZ(20), VALUE=5, RETURN\nEND\n", m, &ok);
  ASSERT_TRUE(ok) << all;
  EXPECT_EQ(m.sensors[0].test, Sensor::Test::Eq);
  EXPECT_DOUBLE_EQ(m.sensors[0].error, 1e-3);  // ADAMS default (docs/theory.md §9c)
  EXPECT_TRUE(m.sensors[0].returnToCommands);
}

TEST(SensorChecks, EveryErrorIsReportedWithItsLine) {
  Model m;
  bool ok = true;
  const std::string all = buildAndReport(
      std::string(kHeader) +
          "SENSOR/1, FUNCTION=DZ(20), EQ, GE, HALT\n"                      // 7: VALUE; EQ+GE
          "SENSOR/2, FUNCTION=DZ(20), VALUE=1, ERROR=0, CODGEN, YYDUMP\n"  // 8: three
          "SENSOR/3, FUNCTION=USER(1), VALUE=1, DT=-1, HALT\n"             // 9: SENSUB, DT
          "SENSOR/4, FUNCTION=DZ(99) + SENVAL(8), VALUE=1, HALT\n"         // 10: two ids
          "SENSOR/5, FUNCTION=DZ(20), VALUE=1\n"                           // 11: no action
          "END\n",
      m, &ok);
  EXPECT_FALSE(ok);
  for (const char* want : {
           "s.adm:7:1: error: SENSOR/1: VALUE is missing",
           "s.adm:7:1: error: SENSOR/1: EQ, GE and LE exclude each other",
           "s.adm:8:37: error: SENSOR/2: ERROR must be positive",
           "s.adm:8:46: error: SENSOR/2: CODGEN (a new pivot sequence",
           "s.adm:8:54: error: SENSOR/2: YYDUMP (a dump of the state vector",
           "s.adm:9:11: error: SENSOR/3: FUNCTION=USER(...) needs the user subroutine SENSUB",
           "s.adm:9:38: error: SENSOR/3: DT (the new output interval) must be positive",
           "s.adm:10:20: error: SENSOR/4: DZ: marker 99 does not exist",
           "s.adm:10:29: error: SENSOR/4: SENVAL: SENSOR/8 does not exist",
           "s.adm:11:1: warning: SENSOR/5: the sensor has no action"})
    EXPECT_NE(all.find(want), std::string::npos) << want << "\n" << all;
}

// GSE is built now (tests/user/gse_test.cpp); a GSE without its arrays is still an error at
// its statement, each missing array named.
TEST(SensorChecks, GseWithoutItsArraysIsAnError) {
  Model m;
  bool ok = true;
  const std::string all = buildAndReport(
      std::string(kHeader) + "GSE/1, NS=1, NO=1, FUNCTION=USER(1)\nEND\n", m, &ok);
  EXPECT_FALSE(ok);
  for (const char* want : {"s.adm:7:1: error: GSE/1: NS=1 needs X=",
                           "s.adm:7:1: error: GSE/1: NO=1 needs Y="})
    EXPECT_NE(all.find(want), std::string::npos) << want << "\n" << all;
}

}  // namespace
}  // namespace openmss::model
