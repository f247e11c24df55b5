// SFORCE and REQUEST statements (model/sforce_builder.cpp, model/request_builder.cpp) and the
// statements that set the model directly (UNITS, ACCGRAV, OUTPUT): what each produces, and the
// located diagnostic of each wrong combination.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/built_model.hpp"

namespace openmss::model {
namespace {

using Built = testing::BuiltModel;

Built build(const std::string& text) {
  return testing::buildModelFromText(text, "f.adm");
}

const char* kParts =
    "forces\n"
    "UNITS/SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2\n"
    "MARKER/21, PART=2\n";  // the statements below start on line 8

TEST(SForceBuilder, KindsDirectionsAndFunctions) {
  const Built b = build(std::string(kParts) +
                        "SFORCE/1, TRANSLATION, I=20, J=10, FUNCTION=-10*DM(20,10)\n"
                        "SFORCE/2, ROTATION, ACTIONONLY, I=20, J=10, FUNCTION=-2*WZ(20,10)\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.sforces.size(), 2u);
  const SForce& f = b.model.sforces[0];
  EXPECT_FALSE(f.rotation);
  EXPECT_FALSE(f.actionOnly);
  EXPECT_EQ(b.model.markers[f.iMarker].id, 20);
  EXPECT_EQ(b.model.markers[f.jMarker].id, 10);
  ASSERT_EQ(f.function.measures.size(), 1u);
  EXPECT_EQ(f.function.measures[0].kind, MeasureKind::DM);
  const SForce& t = b.model.sforces[1];
  EXPECT_TRUE(t.rotation);
  EXPECT_TRUE(t.actionOnly);
  ASSERT_EQ(t.function.measures.size(), 1u);
  EXPECT_EQ(t.function.measures[0].kind, MeasureKind::WZ);
}

TEST(SForceBuilder, WrongForcesAreLocated) {
  const Built b = build(std::string(kParts) +
                        "SFORCE/1, I=20, J=10, FUNCTION=1\n"                             // 8
                        "SFORCE/2, TRANSLATION, I=20, J=99, FUNCTION=1\n"                // 9
                        "SFORCE/3, TRANSLATION, I=20, J=10, FUNCTION=USER(1)\n"          // 10
                        "SFORCE/4, TRANSLATION, I=20, J=10, FUNCTION=SFORCE(7,0,1,0)\n"  // 11
                        // SFORCE/2 is in the data set but refused (line 9): the reference
                        // says so instead of "does not exist".
                        "SFORCE/5, TRANSLATION, I=20, J=10, FUNCTION=SFORCE(2,0,1,0)\n"  // 12
                        "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "f.adm:8:1: error: SFORCE/1: give exactly one of TRANSLATION and ROTATION. Add "
          "TRANSLATION (a force along I-J) or ROTATION (a torque about zJ).",
          "f.adm:9:30: error: SFORCE/2: J=99: marker 99 does not exist. Use the id of a MARKER "
          "statement of this data set.",
          "f.adm:10:36: error: SFORCE/3: "
          "FUNCTION=USER(...) needs the user subroutine SFOSUB, and no user library is named: "
          "the statement has no ROUTINE=lib::name and no default library was given (openmss run "
          "--user-library LIB). Supply the library that defines SFOSUB (ROUTINE=lib::name on the "
          "statement, or openmss run --user-library LIB); docs/user-subroutines.md says how to "
          "build one.",
          "f.adm:11:45: error: SFORCE/4: SFORCE: SFORCE/7 does not exist. Use the id of a "
          "SFORCE statement of this data set.",
          "f.adm:12:45: error: SFORCE/5: SFORCE: SFORCE/2 (line 9) was not built: its statement "
          "has errors, reported at its line. Correct SFORCE/2; this reference then needs no "
          "change."}));
}

TEST(RequestBuilder, KindsMarkersAndColumns) {
  const Built b = build(std::string(kParts) +
                        "REQUEST/1, DISPLACEMENT, I=20, J=10, RM=10, COMMENT=body 2\n"
                        "REQUEST/2, FORCE, I=20\n"
                        "REQUEST/3, F2=DX(20), F3=NRHS\n"
                        "END\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.requests.size(), 3u);
  const Request& d = b.model.requests[0];
  EXPECT_EQ(d.kind, Request::Kind::Displacement);
  EXPECT_EQ(b.model.markers[d.iMarker].id, 20);
  EXPECT_EQ(b.model.markers[d.jMarker].id, 10);
  EXPECT_EQ(b.model.markers[d.rmMarker].id, 10);
  EXPECT_EQ(d.comment, "body 2");
  const Request& f = b.model.requests[1];
  EXPECT_EQ(f.kind, Request::Kind::Force);
  EXPECT_EQ(f.jMarker, -1);   // the ground origin
  EXPECT_EQ(f.rmMarker, -1);  // ground axes
  const Request& e = b.model.requests[2];
  EXPECT_EQ(e.kind, Request::Kind::Expressions);
  int columns = 0;
  for (const auto& c : e.columns) columns += c.has_value() ? 1 : 0;
  EXPECT_EQ(columns, 2);
  ASSERT_TRUE(e.columns[1] && e.columns[2]);
  EXPECT_EQ(e.columns[1]->measures.at(0).kind, MeasureKind::DX);
  // Integrator statistics are read in requests only (docs/expressions.md).
  EXPECT_EQ(e.columns[2]->measures.at(0).kind, MeasureKind::ResidualCount);
}

TEST(RequestBuilder, WrongRequestsAreLocated) {
  const Built b = build(std::string(kParts) +
                        "REQUEST/1, DISPLACEMENT, VELOCITY, I=20\n"  // 8
                        "REQUEST/2, COMMENT=nothing\n"               // 9
                        "REQUEST/3, DISPLACEMENT, F2=1\n"            // 10
                        "REQUEST/4, FUNCTION=USER(1)\n"              // 11
                        "REQUEST/5, F1=CPU\n"                        // 12
                        "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_TRUE(b.model.requests.empty());
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "f.adm:8:1: error: REQUEST/1: DISPLACEMENT, VELOCITY, ACCELERATION, FORCE and F1..F8 "
          "exclude each other. Keep one kind of request per REQUEST statement.",
          "f.adm:9:1: error: REQUEST/2: the request asks for nothing. Add DISPLACEMENT, "
          "VELOCITY, ACCELERATION or FORCE with I=, or F2=... expressions.",
          "f.adm:10:1: error: REQUEST/3: DISPLACEMENT, VELOCITY, ACCELERATION, FORCE and F1..F8 "
          "exclude each other. Keep one kind of request per REQUEST statement.",
          "f.adm:11:12: error: REQUEST/4: "
          "FUNCTION=USER(...) needs the user subroutine REQSUB, and no user library is named: "
          "the statement has no ROUTINE=lib::name and no default library was given (openmss run "
          "--user-library LIB). Supply the library that defines REQSUB (ROUTINE=lib::name on the "
          "statement, or openmss run --user-library LIB); docs/user-subroutines.md says how to "
          "build one.",
          "f.adm:12:15: error: REQUEST/5: CPU: CPU time is not available: it differs from run "
          "to run, and OpenMSS keeps its outputs bit-identical across runs. Remove CPU; NRHS "
          "(residual evaluations) or NJAC measure the solver's effort reproducibly."}));
}

// UCF = f t^2 / (m l) for FORCE, MASS, LENGTH, TIME worth f N, m kg, l m, t s (Force * UCF =
// Mass * Acceleration). The factors are exact definitions (NIST SP 811), so the expected values
// below follow from them by hand; 1e-12 relative allows the few roundings of the quotient.
TEST(UnitsAndGravity, ConsistencyFactorsFromTheUnitDefinitions) {
  struct Case {
    std::string units;
    double ucf;
  };
  const double gn = 9.80665;  // standard gravity: 1 lbf = 1 lbm * gn, 1 kgf = 1 kg * gn
  const std::vector<Case> cases = {
      {"SYSTEM=MKS", 1.0},
      {"SYSTEM=CGS", 1.0},          // 1 dyn = 1 g cm/s^2
      {"SYSTEM=IPS", gn / 0.0254},  // lbf / (lbm in/s^2) = 386.088...
      {"SYSTEM=FPS", gn / 0.3048},  // 32.174...
      {"FORCE=KILOGRAM_FORCE, MASS=KILOGRAM, LENGTH=MILLIMETER, TIME=SECOND", gn / 1e-3},
      {"FORCE=NEWTON, MASS=TONNE, LENGTH=MILLIMETER, TIME=SECOND", 1.0},  // N = t mm/s^2
      {"FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=MILLISECONDS", 1e-6},
      {"UCF=2.5", 2.5}};
  int compared = 0;
  for (const Case& c : cases) {
    const Built b = build("units\nUNITS/" + c.units + "\nPART/1, GROUND\nEND\n");
    ASSERT_TRUE(b.ok) << c.units << ::testing::PrintToString(b.messages());
    EXPECT_NEAR(b.model.units.ucf, c.ucf, 1e-12 * c.ucf) << c.units;
    ++compared;
  }
  EXPECT_EQ(compared, 8);
  const Built ips = build("units\nUNITS/SYSTEM=IPS\nPART/1, GROUND\nEND\n");
  EXPECT_EQ(ips.model.units.description, "INCH, POUND_MASS, SECOND, POUND_FORCE");
}

TEST(UnitsAndGravity, GravityOutputAndUnitErrors) {
  const Built b = build(
      "settings\n"
      "UNITS/FORCE=NEWTON, MASS=KILOGRAM\n"  // 2: two of four
      "ACCGRAV/JGRAV=-9.80665\n"
      "OUTPUT/REQSAVE, NOSEPARATOR, GRSAVE\n"  // 4: GRSAVE asks for the .gra
      "PART/1, GROUND\n"
      "END\n");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.model.gravity, Eigen::Vector3d(0, -9.80665, 0));
  EXPECT_TRUE(b.model.output.reqsave);
  EXPECT_TRUE(b.model.output.noseparator);
  EXPECT_TRUE(b.model.output.grsave);
  EXPECT_EQ(b.messages(),
            (std::vector<std::string>{
                "f.adm:2:1: error: UNITS: FORCE, MASS, LENGTH and TIME must be given together. "
                "Give all four, or SYSTEM=, or UCF=."}));
}

}  // namespace
}  // namespace openmss::model
