// FRICTION statements as the model builder reads them (docs/theory.md, "Joint friction"):
// ADAMS's defaults, INPUTS and EFFECT, and every refusal as a located message naming the
// statement and what to change — a joint kind FRICTION does not apply to, a missing joint, a
// missing coefficient, out-of-range values, arguments that have no effect on the joint kind.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

struct Built {
  Model model;
  std::vector<std::string> errors;
};

Built build(const std::string& body) {
  const std::string text =
      "friction\nPART/1, GROUND\nMARKER/10, PART=1\nPART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2\n"
      "JOINT/1, REVOLUTE, I=20, J=10\nJOINT/2, FIXED, I=20, J=10\n"
      "JOINT/3, TRANSLATIONAL, I=20, J=10\nJOINT/4, SPHERICAL, I=20, J=10\n" +
      body + "END\n";
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetText(text, "f.adm", dataset, diags);
  Built b;
  buildModel(dataset, b.model, diags);
  for (const auto& d : diags.all())
    if (d.severity == Severity::Error) b.errors.push_back(format(d));
  return b;
}

TEST(FrictionBuilder, DefaultsAndSwitchesAreRead) {
  const Built b = build(
      "FRICTION/5, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2\n"
      "FRICTION/6, JOINT=3, MU_STATIC=0.4, MU_DYNAMIC=0.1, FRICTION_FORCE_PRELOAD=7, "
      "INPUTS=PRELOAD:BENDING_MOMENT, EFFECT=SLIDING, INACTIVE=STATIC, INITIAL_OVERLAP=2\n"
      "FRICTION/7, JOINT=4, MU_STATIC=0.4, MU_DYNAMIC=0.1, INPUTS=NONE, BALL_RADIUS=0.3\n");
  ASSERT_TRUE(b.errors.empty()) << b.errors[0];
  ASSERT_EQ(b.model.frictions.size(), 3u);
  const Friction& f = b.model.frictions[0];
  EXPECT_EQ(f.id, 5);
  EXPECT_EQ(f.joint, 0);
  EXPECT_EQ(f.stictionVelocity, 0.1);  // ADAMS's defaults
  EXPECT_EQ(f.preload, 0.0);
  EXPECT_EQ(f.frictionArm, 1.0);
  EXPECT_EQ(f.bendingArm, 1.0);
  EXPECT_EQ(f.pinRadius, 1.0);
  EXPECT_EQ(f.effect, Friction::Effect::All);
  EXPECT_TRUE(f.usePreload && f.useReactionForce && f.useBendingMoment && f.useTorsionalMoment);
  EXPECT_FALSE(f.inactiveStatic);
  const Friction& g = b.model.frictions[1];
  EXPECT_EQ(g.preload, 7.0);
  EXPECT_TRUE(g.usePreload && g.useBendingMoment);
  EXPECT_FALSE(g.useReactionForce || g.useTorsionalMoment);
  EXPECT_EQ(g.effect, Friction::Effect::Sliding);
  EXPECT_TRUE(g.inactiveStatic);
  EXPECT_EQ(g.initialOverlap, 2.0);
  const Friction& h = b.model.frictions[2];
  EXPECT_FALSE(h.usePreload || h.useReactionForce || h.useBendingMoment || h.useTorsionalMoment);
  EXPECT_EQ(h.ballRadius, 0.3);
}

TEST(FrictionBuilder, AJointKindFrictionDoesNotApplyToIsRefusedAtTheArgument) {
  const Built b = build("FRICTION/1, JOINT=2, MU_STATIC=0.3, MU_DYNAMIC=0.2\n");
  ASSERT_EQ(b.errors.size(), 1u);
  EXPECT_EQ(b.errors[0],
            "f.adm:10:13: error: FRICTION/1: JOINT/2 is a FIXED joint, and FRICTION acts only on "
            "translational, revolute, cylindrical, spherical, Hooke and universal joints. Put "
            "the friction on a joint of one of those kinds, or model it with an SFORCE or "
            "GFORCE.");
  EXPECT_TRUE(b.model.frictions.empty());
}

TEST(FrictionBuilder, AMissingJointIsRefusedAtTheArgument) {
  const Built b = build("FRICTION/1, JOINT=9, MU_STATIC=0.3, MU_DYNAMIC=0.2\n");
  ASSERT_EQ(b.errors.size(), 1u);
  EXPECT_EQ(b.errors[0],
            "f.adm:10:13: error: FRICTION/1: joint 9 does not exist. Use the id of a JOINT "
            "statement of this data set.");
}

TEST(FrictionBuilder, MissingAndOutOfRangeValuesAreNamed) {
  const Built b = build(
      "FRICTION/1, JOINT=1, MU_DYNAMIC=0.2\n"
      "FRICTION/2, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=-0.2, STICTION_TRANSITION_VELOCITY=0\n"
      "FRICTION/3, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2, BALL_RADIUS=0.1\n"
      "FRICTION/4, JOINT=4, MU_STATIC=0.3, MU_DYNAMIC=0.2, PIN_RADIUS=0.1\n"
      "FRICTION/5, JOINT=3, MU_STATIC=0.3, MU_DYNAMIC=0.2, INPUTS=ALL:PRELOAD\n");
  ASSERT_EQ(b.errors.size(), 6u) << b.errors[0];
  auto has = [&](const std::string& s) {
    for (const auto& e : b.errors)
      if (e.find(s) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has("f.adm:10:1: error: FRICTION/1: missing required argument MU_STATIC"));
  EXPECT_TRUE(has("f.adm:11:37: error: FRICTION/2: MU_DYNAMIC must not be negative"));
  EXPECT_TRUE(has("FRICTION/2: STICTION_TRANSITION_VELOCITY must be greater than zero"));
  EXPECT_TRUE(has("FRICTION/3: BALL_RADIUS has no effect on a REVOLUTE joint"));
  EXPECT_TRUE(has("FRICTION/4: PIN_RADIUS has no effect on a SPHERICAL joint"));
  EXPECT_TRUE(has("FRICTION/5: INPUTS: ALL cannot be combined with other inputs"));
  EXPECT_TRUE(b.model.frictions.empty());
}

TEST(FrictionBuilder, ReadBackIndicesAreChecked) {
  const Built b = build(
      "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2\n"
      "REQUEST/1, F2=FRICTION(1,6)\\F3=FRICTION(1,23)\\F4=FRICTION(2,1)\n");
  ASSERT_EQ(b.errors.size(), 2u);
  EXPECT_NE(b.errors[0].find("FRICTION: the index must be 1 to 22"), std::string::npos)
      << b.errors[0];
  EXPECT_NE(b.errors[1].find("FRICTION: FRICTION/2 does not exist"), std::string::npos)
      << b.errors[1];
  // A valid read-back binds to the friction's index and component.
  const Built ok = build(
      "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2\n"
      "REQUEST/1, F2=FRICTION(1,6)\n");
  ASSERT_TRUE(ok.errors.empty()) << ok.errors[0];
  ASSERT_EQ(ok.model.requests.size(), 1u);
  ASSERT_TRUE(ok.model.requests[0].columns[1]);
  const auto& measures = ok.model.requests[0].columns[1]->measures;
  ASSERT_EQ(measures.size(), 1u);
  EXPECT_EQ(measures[0].kind, MeasureKind::FrictionOutput);
  EXPECT_EQ(measures[0].element, 0);
  EXPECT_EQ(measures[0].component, 6);
}

TEST(FrictionBuilder, InlineJointFrictionIsRefusedUnlessOff) {
  const Built b = build(
      "JOINT/5, REVOLUTE, I=20, J=10, FRICTION=ON, MU_STAT_ROT=0.3\n"
      "JOINT/6, REVOLUTE, I=20, J=10, FRICTION=OFF, MU_STAT_ROT=0.3\n");
  ASSERT_EQ(b.errors.size(), 1u);
  EXPECT_NE(b.errors[0].find("f.adm:10:32: error: JOINT/5: inline joint friction (FRICTION=ON) "
                             "is not supported. Write a FRICTION statement on this joint"),
            std::string::npos)
      << b.errors[0];
}

}  // namespace
}  // namespace openmss::model
