// JOINT, JPRIM and MOTION statements (model/joint_builder.cpp, model/motion_builder.cpp): the
// kind each keyword selects, the type's own data (PD, PITCH), joint initial conditions, the
// motion's axis and form, and the located diagnostic of each wrong combination.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "support/built_model.hpp"

namespace openmss::model {
namespace {

using Built = testing::BuiltModel;

// Ground (markers 10-19) and two moving parts (markers 20-29 on PART/2, 30-39 on PART/3).
const char* kParts =
    "joints\n"
    "UNITS/SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2\n"
    "MARKER/21, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1\n"
    "MARKER/30, PART=3\n";  // the statements below start on line 11

Built build(const std::string& statements) {
  return testing::buildModelFromText(std::string(kParts) + statements + "END\n", "j.adm");
}

TEST(JointBuilder, EveryJointKeywordSelectsItsKind) {
  const std::vector<std::pair<std::string, JointType>> kinds = {
      {"REVOLUTE", JointType::Revolute},
      {"SPHERICAL", JointType::Spherical},
      {"UNIVERSAL", JointType::Universal},
      {"HOOKE", JointType::Hooke},
      {"TRANSLATIONAL", JointType::Translational},
      {"CYLINDRICAL", JointType::Cylindrical},
      {"FIXED", JointType::Fixed},
      {"CONVEL", JointType::Convel},
      {"PLANAR", JointType::Planar},
      {"RACKPIN, PD=0.2", JointType::RackPin},
      {"SCREW, PITCH=-0.01", JointType::Screw}};
  std::string text;
  for (size_t k = 0; k < kinds.size(); ++k)
    text += "JOINT/" + std::to_string(k + 1) + ", " + kinds[k].first + ", I=20, J=10\n";
  const Built b = build(text);
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.joints.size(), kinds.size());
  for (size_t k = 0; k < kinds.size(); ++k) {
    const Joint& j = b.model.joints[k];
    EXPECT_EQ(j.id, static_cast<long>(k + 1));
    EXPECT_EQ(j.type, kinds[k].second) << kinds[k].first;
    EXPECT_EQ(b.model.jointIndex.at(j.id), static_cast<int>(k));
    EXPECT_EQ(b.model.markers[j.iMarker].id, 20);
    EXPECT_EQ(b.model.markers[j.jMarker].id, 10);
  }
  EXPECT_EQ(b.model.joints[9].pitchDiameter, 0.2);
  EXPECT_EQ(b.model.joints[10].pitch, -0.01);  // negative: a left-handed screw
}

TEST(JointBuilder, JointInitialConditionsByType) {
  const Built b = build(
      "JOINT/1, REVOLUTE, I=20, J=10, IC=0.5, -1\n"
      "JOINT/2, TRANSLATIONAL, I=30, J=11, IC=0.25\n"
      "JOINT/3, CYLINDRICAL, I=21, J=30, ICTRAN=1, 2, ICROT=3, 4\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  const Joint& rev = b.model.joints[0];
  EXPECT_EQ(rev.icRotation, 0.5);
  EXPECT_EQ(rev.icRotationVelocity, -1.0);
  EXPECT_FALSE(rev.icTranslation);
  const Joint& tra = b.model.joints[1];
  EXPECT_EQ(tra.icTranslation, 0.25);
  EXPECT_FALSE(tra.icTranslationVelocity);  // displacement only
  EXPECT_FALSE(tra.icRotation);
  const Joint& cyl = b.model.joints[2];
  EXPECT_EQ(cyl.icTranslation, 1.0);
  EXPECT_EQ(cyl.icTranslationVelocity, 2.0);
  EXPECT_EQ(cyl.icRotation, 3.0);
  EXPECT_EQ(cyl.icRotationVelocity, 4.0);
}

TEST(JointBuilder, WrongCombinationsAreLocated) {
  const Built b = build(
      "JOINT/1, I=20, J=10\n"                       // 11: no type
      "JOINT/2, REVOLUTE, SPHERICAL, I=20, J=10\n"  // 12: two types
      "JOINT/3, REVOLUTE, I=20, J=10, PD=1\n"       // 13: PD on a revolute
      "JOINT/4, SCREW, I=20, J=10, PITCH=0\n"       // 14: zero pitch
      "JOINT/5, SPHERICAL, I=20, J=10, IC=1\n"      // 15: IC on a spherical joint
      "JOINT/6, CYLINDRICAL, I=20, J=10, IC=1\n"    // 16: IC on a cylindrical joint
      "JOINT/7, REVOLUTE, I=20, J=21\n"             // 17: same part
      "JOINT/8, RACKPIN, I=20, J=10\n"              // 18: PD missing
      "JPRIM/1, INLINE, INPLANE, I=20, J=10\n"      // 19: two primitive types
      "JPRIM/2, ATPOINT, I=10, J=11\n");            // 20: same part
  EXPECT_FALSE(b.ok);
  // Joints whose type and markers are valid are kept (their other errors still fail the
  // model), so that later references to them (MOTION, COUPLER, ...) say nothing more.
  std::vector<long> kept;
  for (const Joint& j : b.model.joints) kept.push_back(j.id);
  EXPECT_EQ(kept, (std::vector<long>{3, 5, 6, 7}));
  EXPECT_TRUE(b.model.jprims.empty());
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "j.adm:11:1: error: JOINT/1: the joint type is missing. Add one of CONVEL, "
          "CYLINDRICAL, FIXED, HOOKE, PLANAR, RACKPIN, REVOLUTE, SCREW, SPHERICAL, "
          "TRANSLATIONAL, UNIVERSAL.",
          "j.adm:12:1: error: JOINT/2: more than one joint type is given. Keep exactly one "
          "joint type.",
          "j.adm:13:32: error: JOINT/3: PD applies to RACKPIN joints only. Remove PD.",
          "j.adm:14:29: error: JOINT/4: PITCH must not be zero. Give the translation per turn, "
          "PITCH=<value> (negative: left-handed).",
          "j.adm:15:33: error: JOINT/5: IC applies to revolute and translational joints; this "
          "joint is SPHERICAL. Remove IC.",
          "j.adm:16:35: error: JOINT/6: IC applies to revolute and translational joints; this "
          "joint is CYLINDRICAL. Use ICTRAN= and ICROT= on a cylindrical joint.",
          "j.adm:17:1: error: JOINT/7: I and J markers are on the same part (PART/2). A joint "
          "connects two parts: put I and J on different parts.",
          "j.adm:18:1: error: JOINT/8: missing required argument PD. Add PD=<pitch diameter "
          "of the pinion>.",
          "j.adm:19:1: error: JPRIM/1: more than one joint primitive type is given. Give "
          "exactly one of ATPOINT, INLINE, INPLANE, ORIENTATION, PARALLEL_AXES, "
          "PERPENDICULAR.",
          "j.adm:20:1: error: JPRIM/2: I and J markers are on the same part (PART/1). A joint "
          "primitive connects two parts: put I and J on different parts."}));
}

TEST(JointBuilder, EveryPrimitiveKeywordSelectsItsKind) {
  const std::vector<std::pair<std::string, JPrimType>> kinds = {
      {"ATPOINT", JPrimType::AtPoint},
      {"INLINE", JPrimType::InLine},
      {"INPLANE", JPrimType::InPlane},
      {"ORIENTATION", JPrimType::Orientation},
      {"PARALLEL_AXES", JPrimType::ParallelAxes},
      {"PERPENDICULAR", JPrimType::Perpendicular}};
  std::string text;
  for (size_t k = 0; k < kinds.size(); ++k)
    text += "JPRIM/" + std::to_string(k + 1) + ", " + kinds[k].first + ", I=20, J=30\n";
  const Built b = build(text);
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.jprims.size(), kinds.size());
  for (size_t k = 0; k < kinds.size(); ++k) {
    EXPECT_EQ(b.model.jprims[k].type, kinds[k].second) << kinds[k].first;
    EXPECT_EQ(b.model.jprimIndex.at(static_cast<long>(k + 1)), static_cast<int>(k));
  }
}

TEST(MotionBuilder, AxisAndFormOfJointAndMarkerMotions) {
  const Built b = build(
      "JOINT/1, REVOLUTE, I=20, J=10\n"
      "JOINT/2, TRANSLATIONAL, I=30, J=11\n"
      "JOINT/3, CYLINDRICAL, I=21, J=30\n"
      "MOTION/1, JOINT=1, FUNCTION=TIME\n"
      "MOTION/2, JOINT=2, VELOCITY, ICDISP=0.5, FUNCTION=1\n"
      "MOTION/3, JOINT=3, ROTATION, ACCELERATION, ICDISP=1, ICVEL=2, FUNCTION=0\n"
      "MOTION/4, I=30, J=20, B2, FUNCTION=SIN(TIME)\n"
      "MOTION/5, I=30, J=20, Y, FUNCTION=2*TIME\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.motions.size(), 5u);
  const auto& m = b.model.motions;
  // Joint motions act about (5) or along (2) the joint's z axis, between its markers.
  EXPECT_EQ(m[0].joint, 0);
  EXPECT_TRUE(m[0].rotation);
  EXPECT_EQ(m[0].axis, 5);
  EXPECT_EQ(m[0].iMarker, b.model.joints[0].iMarker);
  EXPECT_EQ(m[0].form, Motion::Form::Displacement);
  EXPECT_FALSE(m[1].rotation);
  EXPECT_EQ(m[1].axis, 2);
  EXPECT_EQ(m[1].form, Motion::Form::Velocity);
  EXPECT_EQ(m[1].icDisp, 0.5);
  EXPECT_TRUE(m[2].rotation);
  EXPECT_EQ(m[2].axis, 5);
  EXPECT_EQ(m[2].form, Motion::Form::Acceleration);
  EXPECT_EQ(m[2].icDisp, 1.0);
  EXPECT_EQ(m[2].icVel, 2.0);
  // Marker-pair motions: X, Y, Z = 0..2, B1, B2, B3 = 3..5.
  EXPECT_EQ(m[3].joint, -1);
  EXPECT_EQ(m[3].axis, 4);
  EXPECT_TRUE(m[3].rotation);
  EXPECT_EQ(b.model.markers[m[3].iMarker].id, 30);
  EXPECT_EQ(m[4].axis, 1);
  EXPECT_FALSE(m[4].rotation);
}

TEST(MotionBuilder, WrongMotionsAreLocated) {
  const Built b = build(
      "JOINT/1, REVOLUTE, I=20, J=10\n"                             // 11
      "JOINT/2, SPHERICAL, I=30, J=11\n"                            // 12
      "MOTION/1, JOINT=1, DISPLACEMENT, VELOCITY, FUNCTION=TIME\n"  // 13: two forms
      "MOTION/2, JOINT=1, ICDISP=1, FUNCTION=TIME\n"                // 14: ICDISP warns
      "MOTION/3, JOINT=2, FUNCTION=TIME\n"                          // 15: spherical
      "MOTION/4, JOINT=9, FUNCTION=TIME\n"                          // 16: unknown joint
      "MOTION/5, I=20, J=10, FUNCTION=TIME\n"                       // 17: no direction
      "MOTION/6, JOINT=1, FUNCTION=DX(20)\n"                        // 18: not of TIME
      "MOTION/7, JOINT=1, FUNCTION=DELAY(TIME, 1, 0)\n"             // 19: DELAY
      "MOTION/8, JOINT=1, I=20, FUNCTION=TIME\n");                  // 20: JOINT and I
  EXPECT_FALSE(b.ok);
  ASSERT_EQ(b.model.motions.size(), 1u);  // MOTION/2 only: its ICDISP is a warning
  EXPECT_EQ(b.model.motions[0].id, 2);
  EXPECT_EQ(
      b.messages(),
      (std::vector<std::string>{
          "j.adm:13:1: error: MOTION/1: DISPLACEMENT, VELOCITY and ACCELERATION exclude each "
          "other. Keep one of them (DISPLACEMENT is the default).",
          "j.adm:14:20: warning: MOTION/2: ICDISP has no effect on a displacement motion (its "
          "function gives the displacement). Remove ICDISP, or make the motion VELOCITY or "
          "ACCELERATION.",
          "j.adm:15:1: error: MOTION/3: a joint motion needs a revolute, translational or "
          "cylindrical joint; JOINT/2 is SPHERICAL. Drive a revolute, translational or "
          "cylindrical joint, or use I=, J= with X, Y, Z, B1, B2 or B3.",
          "j.adm:16:11: error: MOTION/4: JOINT/9 does not exist (or is invalid). Use the id of "
          "a JOINT statement of this data set.",
          "j.adm:17:1: error: MOTION/5: a marker-pair motion needs its direction. Give exactly "
          "one of X, Y, Z (translation of I in J's axes) or B1, B2, B3 (body 1-2-3 rotation "
          "angles of I relative to J).",
          "j.adm:18:29: error: MOTION/6: a MOTION function may depend on TIME only, but it "
          "calls DX. Rewrite the function in terms of TIME.",
          "j.adm:19:29: error: MOTION/7: DELAY is not supported in MOTION functions yet. Write "
          "the delayed motion directly as a function of TIME (e.g. SIN(TIME-0.5) for "
          "DELAY(SIN(TIME), 0.5, 0)).",
          "j.adm:20:1: error: MOTION/8: JOINT= excludes I= and J=. Give JOINT=<id> (with "
          "TRANSLATION or ROTATION on a cylindrical joint), or I=<id>, J=<id> with one of X, "
          "Y, Z, B1, B2, B3."}));
}

}  // namespace
}  // namespace openmss::model
