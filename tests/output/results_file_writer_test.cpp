// The .res writer's pieces and the reader on a file laid out as ADAMS writes it:
// - numbers: the default text reads back as the same double, DECIMALPLACES as documented;
// - ids: allocated by quantity block (positions of every part, then velocities, ...);
// - the reader on a fixture that reproduces every structural feature seen in .res files
//   real ADAMS/Solver (C++) 2016 and 2022 wrote (the numbers are ours; docs/output-files.md).
// A real ADAMS .res is read by DISABLED_ReadsTheAdamsFileNamedByTheEnvironment when OPENMSS_ADAMS_RES
// names one (docs/output-files.md, "Reading a .res written by ADAMS").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "model/results_arguments.hpp"
#include "output/results_file.hpp"
#include "output/results_file_reader.hpp"
#include "output/results_layout.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;

TEST(ResultValueText, DefaultDigitsReadBackAsTheSameDouble) {
  std::mt19937_64 random(20261125);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  long compared = 0;
  for (int k = 0; k < 20000; ++k) {
    const double v = std::ldexp(mantissa(random), exponent(random));
    const std::string text = formatResultValue(v, 17);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    ++compared;
  }
  for (double v : {0.1, 1.0 / 3.0, -386.0885827, 1e-300, 5e-324, 1.7976931348623157e308}) {
    EXPECT_EQ(std::strtod(formatResultValue(v, 17).c_str(), nullptr), v);
    ++compared;
  }
  EXPECT_EQ(compared, 20006);
  EXPECT_EQ(formatResultValue(0.0, 17), "0");
  EXPECT_EQ(formatResultValue(-0.0, 17), "0");
  EXPECT_EQ(formatResultValue(0.01, 17), "0.01");
}

TEST(ResultValueText, FewerDecimalPlacesKeepThatManyDigitsAfterTheFirst) {
  EXPECT_EQ(formatResultValue(-386.0885827, 5), "-386.089");  // 6 significant digits
  EXPECT_EQ(formatResultValue(1.0745505424136453e-15, 3), "1.075E-15");
  EXPECT_EQ(formatResultValue(2.5, 3), "2.5");  // trailing zeros dropped
}

model::Model buildModel(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "m.adm", ds, d);
  model::Model m;
  model::buildModel(ds, m, d);
  EXPECT_FALSE(d.hasErrors());
  return m;
}

const char* kTwoParts =
    "two parts\n"
    "PART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3\n"
    "JOINT/1, REVOLUTE, I=20, J=10\nJOINT/2, REVOLUTE, I=30, J=11\n"
    "SFORCE/5, I=20, J=30, TRANSLATION, FUNCTION=1\n"
    "VARIABLE/9, FUNCTION=TIME\n"
    "REQUEST/4, DISPLACEMENT, I=20, J=10, CNAMES=\"\", DX, DY\n"
    "REQUEST/6, F2=TIME\nEND\n";

TEST(ResultsLayout, IdsAreAllocatedByQuantityBlockAsAdamsDoes) {
  const model::Model m = buildModel(kTwoParts);
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kTwoParts, "m.adm", ds, d);
  const model::ResultsSettings rs = model::readResultsSettings(ds, d);
  const ResultsLayout l = resultsLayout(m, rs);
  const auto id = [&](const std::string& entity, const std::string& component) {
    for (const ResultsEntity& e : l.entities)
      if (e.name == entity)
        for (int c : e.components)
          if (l.components[c].name == component) return c + 1;
    return -1;
  };
  EXPECT_EQ(id("time", "TIME"), 1);
  EXPECT_EQ(id("PART_2_XFORM", "X"), 2);
  EXPECT_EQ(id("PART_3_XFORM", "X"), 8);    // all positions first
  EXPECT_EQ(id("PART_2_XFORM", "VX"), 14);  // then all velocities
  EXPECT_EQ(id("PART_3_XFORM", "WZ"), 25);
  EXPECT_EQ(id("PART_2_XFORM", "ACCX"), 26);  // then all accelerations
  EXPECT_EQ(id("PART_3_XFORM", "WDZ"), 37);
  EXPECT_EQ(id("JOINT_1", "FX"), 38);
  EXPECT_EQ(id("JOINT_2", "TZ"), 49);
  EXPECT_EQ(id("SFORCE_5", "FX"), 50);
  EXPECT_EQ(id("VARIABLE_9", "Q"), 56);
  // CNAMES: "" leaves column 1 out, DX and DY rename 2 and 3, the rest keep the defaults.
  EXPECT_EQ(id("REQUEST_4", "mag"), -1);
  EXPECT_EQ(id("REQUEST_4", "DX"), 57);
  EXPECT_EQ(id("REQUEST_4", "DY"), 58);
  EXPECT_EQ(id("REQUEST_4", "z"), 59);
  EXPECT_EQ(id("REQUEST_4", "r3"), 63);
  EXPECT_EQ(id("REQUEST_6", "U1"), 64);
  EXPECT_EQ(id("REQUEST_6", "U8"), 71);
  EXPECT_EQ(l.components.size(), 71u);
  EXPECT_EQ(l.components[id("PART_2_XFORM", "VX") - 1].units, "meter/sec");
  EXPECT_EQ(l.components[id("PART_2_XFORM", "WDX") - 1].units, "rad/sec**2");
  EXPECT_EQ(l.components[id("JOINT_1", "TX") - 1].units, "newton-meter");
  EXPECT_EQ(l.components[id("VARIABLE_9", "Q") - 1].units, "");
}

TEST(ResultsArguments, UnsupportedArgumentsAreNamedWithTheirLine) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      "m\nRESULTS/XRF, FORMATTED, DECIMALPLACES=6, NOVELOCITIES, COMMENT=run one\n"
      "REQUEST/3, F2=TIME, CNAMES=Time, CUNITS=\"s\"\n"
      // ADAMS/View's padding: empty names past the eighth are dropped without a word.
      "REQUEST/4, F2=TIME, CNAMES=\"a\",\"\",\"c\",\"d\",\"e\",\"f\",\"g\",\"h\",\"\",\"\"\nEND\n",
      "m.adm", ds, d);
  ASSERT_FALSE(d.hasErrors());
  const model::ResultsSettings rs = model::readResultsSettings(ds, d);
  EXPECT_TRUE(rs.enabled);
  EXPECT_EQ(rs.decimalPlaces, 6);
  EXPECT_TRUE(rs.noVelocities);
  EXPECT_EQ(rs.comment, "run one");  // COMMENT takes the rest of the line, as in ADAMS
  EXPECT_FALSE(rs.noAccelerations);
  EXPECT_FALSE(rs.formatted);  // XRF given too: the XML layout, with a warning
  EXPECT_EQ(rs.requestNames.at(3), (std::vector<std::string>{"Time"}));
  EXPECT_EQ(rs.requestNames.at(4),
            (std::vector<std::string>{"a", "", "c", "d", "e", "f", "g", "h"}));
  std::string text;
  for (const auto& x : d.all()) text += format(x) + "\n";
  EXPECT_NE(text.find("m.adm:2:"), std::string::npos) << text;
  EXPECT_NE(text.find("XRF and FORMATTED both given"), std::string::npos) << text;
  EXPECT_NE(text.find("m.adm:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("CUNITS is not supported"), std::string::npos) << text;
  EXPECT_EQ(d.all().size(), 2u) << text;
  EXPECT_FALSE(d.hasErrors());

  language::Dataset bad;
  Diagnostics e;
  language::readDatasetText(
      "m\nRESULTS/DECIMALPLACES=18\nREQUEST/5, F2=TIME, "
      "CNAMES=\"a\",\"b\",\"c\",\"d\",\"e\",\"f\",\"g\",\"h\",\"i\"\nEND\n",
      "m.adm", bad, e);
  model::readResultsSettings(bad, e);
  EXPECT_TRUE(e.hasErrors());  // DECIMALPLACES out of range
  std::string badText;
  for (const auto& x : e.all()) badText += format(x) + "\n";
  EXPECT_NE(badText.find("m.adm:3:"), std::string::npos) << badText;  // the ninth name
  EXPECT_NE(badText.find("'i' (number 9)"), std::string::npos) << badText;
}

// Every structural feature of the ADAMS-written files: Bibliography with a Windows path and a
// multi-line Comment, two blanks before script=, Environment and Application, a time entity
// without entType, parts with block-allocated ids, Joint, Single_Component_Force,
// ADAMS_Variable (no unitsValue), Plant_Input/Plant_Output with a dotted entity, a
// modelInput_001 block whose step has a shape of its own (fewer values than the map, rows of
// 7), three-digit exponents, 17-decimal numbers, and TerminationStatus.
const char* kAdamsLayout = R"xrf(<?xml version="1.0" encoding="UTF-8"?>
<Results xmlns="http://www.mscsoftware.com/:xrf10">
<Bibliography>
<File URI="file://C:\some dir\Plant_1.res" schema="xrf" version="2.0.0.0" publicationDate="2020-01-02 03:04:05+01:00" />
<Corporation author="MSC.Software" URI="http://www.mscsoftware.com/" />
<Author user="someone" name="-unknown name-" />
<Revision version="1" derivedFrom="-unknown-">
<Comment>

</Comment>
</Revision>
</Bibliography>
<Analysis name="run" executionDate="2020-01-02 03:04:05" Solver="Adams 2016           Adams Solver (C++)"  script="-unknown-">
<Bibliography>
<Environment operatingSystem="MS Windows NT 6.2" hostname="HOST" />
<Application name="Adams View" version="2016.00.00" />
</Bibliography>
<ModelInfo title="Adams View model name: Plant" creationDate="-unknown-" checksum="-unknown-" />
<Units angle="rad" length="meter" mass="kg" time="sec" />
<StepMap name="map_001">
<Entity name="time">
<Component name="TIME" unitsValue="sec" id="1" />
</Entity>
<Entity name="PART_2_XFORM" entity="PART_2" entType="Part" objectId="2">
<Component name="X" unitsValue="meter" id="2" />
<Component name="Y" unitsValue="meter" id="3" />
<Component name="Z" unitsValue="meter" id="4" />
<Component name="PSI" unitsValue="rad" id="5" />
<Component name="THETA" unitsValue="rad" id="6" />
<Component name="PHI" unitsValue="rad" id="7" />
<Component name="VX" unitsValue="meter/sec" id="14" />
<Component name="VY" unitsValue="meter/sec" id="15" />
<Component name="VZ" unitsValue="meter/sec" id="16" />
<Component name="WX" unitsValue="rad/sec" id="17" />
<Component name="WY" unitsValue="rad/sec" id="18" />
<Component name="WZ" unitsValue="rad/sec" id="19" />
<Component name="ACCX" unitsValue="meter/sec**2" id="26" />
<Component name="ACCY" unitsValue="meter/sec**2" id="27" />
<Component name="ACCZ" unitsValue="meter/sec**2" id="28" />
<Component name="WDX" unitsValue="rad/sec**2" id="29" />
<Component name="WDY" unitsValue="rad/sec**2" id="30" />
<Component name="WDZ" unitsValue="rad/sec**2" id="31" />
</Entity>
<Entity name="PART_3_XFORM" entity="PART_3" entType="Part" objectId="3">
<Component name="X" unitsValue="meter" id="8" />
<Component name="Y" unitsValue="meter" id="9" />
<Component name="Z" unitsValue="meter" id="10" />
<Component name="PSI" unitsValue="rad" id="11" />
<Component name="THETA" unitsValue="rad" id="12" />
<Component name="PHI" unitsValue="rad" id="13" />
<Component name="VX" unitsValue="meter/sec" id="20" />
<Component name="VY" unitsValue="meter/sec" id="21" />
<Component name="VZ" unitsValue="meter/sec" id="22" />
<Component name="WX" unitsValue="rad/sec" id="23" />
<Component name="WY" unitsValue="rad/sec" id="24" />
<Component name="WZ" unitsValue="rad/sec" id="25" />
<Component name="ACCX" unitsValue="meter/sec**2" id="32" />
<Component name="ACCY" unitsValue="meter/sec**2" id="33" />
<Component name="ACCZ" unitsValue="meter/sec**2" id="34" />
<Component name="WDX" unitsValue="rad/sec**2" id="35" />
<Component name="WDY" unitsValue="rad/sec**2" id="36" />
<Component name="WDZ" unitsValue="rad/sec**2" id="37" />
</Entity>
<Entity name="JOINT_1" entity="JOINT_1" entType="Joint" objectId="1">
<Component name="FX" unitsValue="newton" id="38" />
<Component name="FY" unitsValue="newton" id="39" />
<Component name="FZ" unitsValue="newton" id="40" />
<Component name="TX" unitsValue="newton-meter" id="41" />
<Component name="TY" unitsValue="newton-meter" id="42" />
<Component name="TZ" unitsValue="newton-meter" id="43" />
</Entity>
<Entity name="SFORCE_1" entity="SFORCE_1" entType="Single_Component_Force" objectId="1">
<Component name="FX" unitsValue="newton" id="44" />
<Component name="FY" unitsValue="newton" id="45" />
<Component name="FZ" unitsValue="newton" id="46" />
<Component name="TX" unitsValue="newton-meter" id="47" />
<Component name="TY" unitsValue="newton-meter" id="48" />
<Component name="TZ" unitsValue="newton-meter" id="49" />
</Entity>
<Entity name="Gain" entity="Gain" entType="ADAMS_Variable" objectId="1">
<Component name="Q" id="50" />
</Entity>
<Entity name="plant_in" entity="Plant_1.plant_in" entType="Plant_Input" objectId="1">
<Component name="IN1" id="51" />
</Entity>
<Entity name="plant_out" entity="Plant_1.plant_out" entType="Plant_Output" objectId="1">
<Component name="OUT1" id="52" />
<Component name="OUT2" id="53" />
</Entity>
</StepMap>
<Data name="modelInput_001" id="1">
<Step type="input">
0
0 0 -0.20000000000000001 0 0 0
-1.2345678900000001E-014 2.5E-014 0 0 0 0
0 0 0 0 0 0
0 0 0 0 0 0
0 0 0 0 0 0 0
0 0 0 0 0 0 0
0 0 0 0 0 0
</Step>
</Data>
<Data name="initialConditions_001" id="2">
<Step type="initialConditions">
0
0 0 -0.20000000000000001 0 0 0
0 0 0 0 0 0
0 0 0 0 0 0
0 0 0 0 0 0
2.0E-015 0 0 0 0 0
0 0 0 0 0 -7.1234567890123456E-015
0 19.61330000000000040 0 0 0 0
0 -3.5 0 0 0 0
0.5
0
0 0
</Step>
</Data>
<Data name="dynamic_001" id="3">
<Step type="dynamic">
0.01
0 -0.0004903325 -0.20000000000000001 0 0 0
0 0 0 0 0 0
0 -0.0980665 0 0 0 0
0 0 0 0 0 0
0 -9.8066499999999994 0 0 0 0
0 0 0 0 0 0
0 19.61330000000000040 0 0 0 0
0 -3.5 0 0 0 0
0.5
0
0 0
</Step>
<Step type="dynamic">
0.02000000000000000
0 -0.00196133 -0.20000000000000001 0 0 0
0 0 0 0 0 0
0 -0.196133 0 0 0 0
0 0 0 0 0 0
0 -9.8066499999999994 0 0 0 0
0 0 0 0 0 0
0 19.61330000000000040 0 0 0 0
0 -3.5 0 0 0 0
0.25
1
-2 3
</Step>
</Data>
<TerminationStatus runTermObject="" runStatus="Successful" />
</Analysis>
</Results>
)xrf";

TEST(ResultsFileReader, ReadsAFileLaidOutAsAdamsWritesIt) {
  const fs::path file = fs::temp_directory_path() / "openmss-adams-layout.res";
  std::ofstream(file) << kAdamsLayout;
  ResultsFileData d;
  std::string err;
  ASSERT_TRUE(readResultsFile(file.string(), d, &err)) << err;
  EXPECT_EQ(d.title, "Adams View model name: Plant");
  EXPECT_EQ(d.analysisName, "run");
  EXPECT_EQ(d.lengthUnits, "meter");
  EXPECT_EQ(d.runStatus, "Successful");
  EXPECT_EQ(d.entities.size(), 8u);
  EXPECT_EQ(d.componentCount, 53);
  ASSERT_EQ(d.blocks.size(), 3u);
  EXPECT_EQ(d.blocks[0].name, "modelInput_001");
  EXPECT_EQ(d.blocks[0].steps.at(0).type, "input");
  EXPECT_EQ(d.blocks[2].steps.size(), 2u);
  // Values by entity and component, through the block-allocated ids.
  struct Expect {
    const char* entity;
    const char* component;
    int block, step;
    double value;
  };
  const Expect expected[] = {
      {"PART_2_XFORM", "Z", 1, 0, -0.2},
      {"PART_2_XFORM", "ACCX", 1, 0, 2.0E-15},
      {"PART_3_XFORM", "WDZ", 1, 0, -7.1234567890123456E-015},
      {"JOINT_1", "FY", 1, 0, 19.6133},
      {"SFORCE_1", "FY", 2, 1, -3.5},
      {"PART_2_XFORM", "Y", 2, 1, -0.00196133},
      {"PART_2_XFORM", "VY", 2, 0, -0.0980665},
      {"Gain", "Q", 2, 1, 0.25},
      {"plant_in", "IN1", 2, 1, 1.0},
      {"plant_out", "OUT1", 2, 1, -2.0},
      {"plant_out", "OUT2", 2, 1, 3.0},
  };
  long compared = 0;
  for (const Expect& e : expected) {
    const auto id = d.componentId(e.entity, e.component);
    ASSERT_TRUE(id.has_value()) << e.entity << "." << e.component;
    EXPECT_EQ(d.blocks[e.block].steps[e.step].values[*id - 1], e.value)
        << e.entity << "." << e.component;
    ++compared;
  }
  EXPECT_EQ(compared, 11);
  // The input step keeps its own 45 values; ids do not apply to it, so series() skips it.
  EXPECT_EQ(d.blocks[0].steps[0].values.size(), 45u);
  EXPECT_EQ(d.blocks[0].steps[0].values[7], -1.2345678900000001E-014);
  EXPECT_EQ(d.series(1), (std::vector<double>{0.0, 0.01, 0.02}));
  EXPECT_EQ(d.blocks[2].steps[1].time(), 0.02);
  EXPECT_EQ(d.series(1, "dynamic"), (std::vector<double>{0.01, 0.02}));
  EXPECT_EQ(d.findEntity("plant_in")->entity, "Plant_1.plant_in");
  EXPECT_EQ(d.findEntity("Gain")->components.at(0).units, "");
  fs::remove(file);
}

TEST(ResultsFileReader, RefusesWhatIsNotAResultsFile) {
  const fs::path file = fs::temp_directory_path() / "openmss-not-xrf.res";
  ResultsFileData d;
  std::string err;
  std::ofstream(file) << "<Results><Analysis/></Results>\n";
  EXPECT_FALSE(readResultsFile(file.string(), d, &err));
  EXPECT_NE(err.find("XRF namespace"), std::string::npos) << err;
  std::ofstream(file) << "<Results xmlns=\"http://www.mscsoftware.com/:xrf10\"><Analysis>\n";
  EXPECT_FALSE(readResultsFile(file.string(), d, &err));
  EXPECT_NE(err.find("not well-formed"), std::string::npos) << err;
  std::ofstream(file) << "<Results xmlns=\"http://www.mscsoftware.com/:xrf10\"><Analysis>"
                         "<StepMap><Entity name=\"time\"><Component name=\"TIME\" id=\"1\"/>"
                         "<Component name=\"A\" id=\"2\"/></Entity></StepMap>"
                         "<Data name=\"dynamic_001\" id=\"1\"><Step type=\"dynamic\">\n0\n"
                         "</Step></Data></Analysis></Results>\n";
  EXPECT_FALSE(readResultsFile(file.string(), d, &err));
  EXPECT_NE(err.find("holds 1 values for 2 components"), std::string::npos) << err;
  fs::remove(file);
}

// The check against a .res real ADAMS wrote, for a file that cannot be in the repository:
//   OPENMSS_ADAMS_RES=/path/to/file.res build/tests/test_output --gtest_also_run_disabled_tests
//     --gtest_filter=ResultsFileReader.DISABLED_ReadsTheAdamsFileNamedByTheEnvironment
// (one command line). Disabled, so that the suite never counts it: without a file it would
// compare nothing (CTest leaves disabled tests out of its totals).
TEST(ResultsFileReader, DISABLED_ReadsTheAdamsFileNamedByTheEnvironment) {
  const char* path = std::getenv("OPENMSS_ADAMS_RES");
  ASSERT_NE(path, nullptr) << "OPENMSS_ADAMS_RES names no ADAMS-written .res";
  ResultsFileData d;
  std::string err;
  ASSERT_TRUE(readResultsFile(path, d, &err)) << err;
  long values = 0;
  for (const auto& b : d.blocks) values += static_cast<long>(b.steps.size()) * d.componentCount;
  EXPECT_GT(values, 0);
  std::printf("[ %s: %zu entities, %ld components, %zu data blocks, %ld values ]\n", path,
              d.entities.size(), d.componentCount, d.blocks.size(), values);
}

}  // namespace
}  // namespace openmss::output
