// CONTACT at model building and in the Newton matrix (docs/theory.md §6c):
// - the solids it reads from GRAPHICS (sphere radius from the ELLIPSOID diameters, box extents);
// - bad input: one located message each for a 2-D CIRCLE against a solid, a missing shell
//   file, a negative stiffness (and the other refusals of the builder);
// - the CONTACT(id, jflag, comp, rm) read-back against the law on a resting, penetrating sphere;
// - the exact partials of the IMPACT law and the friction curve in the Newton matrix against
//   central differences of the residual, for sphere-box and box-box contacts with sliding;
//   the sparse Newton matrix on its structural pattern equals the dense one.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/request_values.hpp"
#include "contact/contact_support.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {
namespace {

const char* kHeader =
    "contact input\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, QP=-1,-1,-1\n"
    "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
    "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.1\n"
    "MARKER/20, PART=2\n"
    "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
    "GRAPHICS/3, CIRCLE, CM=20, RADIUS=0.1\n"
    "GRAPHICS/4, EXTERNAL, RM=20, FILE=missing_shell.xmt_txt, ELEMENT=SOLID1\n"
    "GRAPHICS/5, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0, ZSCALE=0.2\n";

testing::BuiltModel deck(const std::string& contact) {
  return testing::buildModelFromText(std::string(kHeader) + contact + "END\n", "contact.adm");
}

TEST(ContactModel, ReadsSpheresAndBoxesFromGraphics) {
  const testing::BuiltModel b = deck(
      "CONTACT/7, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-3, "
      "EXPONENT=2.2, COULOMB_FRICTION=DYNAMICS_ONLY, MU_STATIC=0.3, MU_DYNAMIC=0.2, "
      "STICTION_TRANSITION_VELOCITY=0.1, FRICTION_TRANSITION_VELOCITY=1\n");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  ASSERT_EQ(b.model.contacts.size(), 1u);
  const model::Contact& c = b.model.contacts[0];
  EXPECT_EQ(c.id, 7);
  ASSERT_EQ(c.iSolids.size(), 1u);
  ASSERT_EQ(c.jSolids.size(), 1u);
  EXPECT_EQ(c.iSolids[0].shape, model::ContactSolid::Shape::Sphere);
  EXPECT_DOUBLE_EQ(c.iSolids[0].size.x(), 0.1);  // XSCALE is the diameter
  EXPECT_EQ(c.jSolids[0].shape, model::ContactSolid::Shape::Box);
  EXPECT_EQ(c.jSolids[0].size, Eigen::Vector3d(2, 2, 1));
  EXPECT_EQ(c.friction, model::Contact::Friction::DynamicsOnly);
  EXPECT_DOUBLE_EQ(c.exponent, 2.2);
  EXPECT_EQ(b.model.markers[c.iMarker].id, 20);
  EXPECT_EQ(b.model.markers[c.jMarker].id, 10);
}

TEST(ContactModel, RefusesACircleAgainstASolid) {
  // A CIRCLE is 2-D geometry (docs/theory.md §6c, "2-D contact"): not against a BOX.
  expectOneError(deck("CONTACT/1, IGEOM=3, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=10, "
                      "DMAX=1e-3, EXPONENT=2\n"),
                 11, "GRAPHICS/3 is 2-D geometry and GRAPHICS/1 a 3-D solid");
}

TEST(ContactModel, RefusesAMissingShellFileByName) {
  expectOneError(deck("CONTACT/1, IGEOM=4, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=10, "
                      "DMAX=1e-3, EXPONENT=2\n"),
                 11, "'missing_shell.xmt_txt', which is missing");
}

TEST(ContactModel, RefusesANegativeStiffness) {
  expectOneError(deck("CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=-1e5, DAMPING=10, "
                      "DMAX=1e-3, EXPONENT=2\n"),
                 11, "STIFFNESS = -100000.000000 must not be negative");
}

TEST(ContactModel, RefusesTheOtherUnsupportedInputs) {
  // An unknown GRAPHICS, an ellipsoid without volume, one part on both sides, no law.
  expectOneError(deck("CONTACT/1, IGEOM=9, JGEOM=1, POISSON, PENALTY=1e5, "
                      "RESTITUTION_COEFFICIENT=0.5\n"),
                 11, "GRAPHICS/9, which does not exist");
  expectOneError(deck("CONTACT/1, IGEOM=5, JGEOM=1, POISSON, PENALTY=1e5, "
                      "RESTITUTION_COEFFICIENT=0.5\n"),
                 11, "is an ELLIPSOID with scales 0.200000, 0.000000, 0.200000: it has no volume");
  expectOneError(deck("CONTACT/1, IGEOM=2, JGEOM=2, POISSON, PENALTY=1e5, "
                      "RESTITUTION_COEFFICIENT=0.5\n"),
                 11, "same part");
  expectOneError(deck("CONTACT/1, IGEOM=2, JGEOM=1\n"), 11, "normal force law is missing");
  expectOneError(deck("CONTACT/1, IGEOM=2, JGEOM=1, POISSON, PENALTY=1e5, "
                      "RESTITUTION_COEFFICIENT=1.5\n"),
                 11, "RESTITUTION_COEFFICIENT");
}

TEST(ContactModel, ReadBackGivesTheForceOnEachPart) {
  // Sphere centre 1e-3 below touching: d = 1e-3, at rest, so Fn = k d^e exactly.
  const model::Model m = build(
      "read-back\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=-1,-1,-1\n"
      "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
      "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.099\n"
      "MARKER/20, PART=2\n"
      "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
      "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=50, DMAX=1e-3, "
      "EXPONENT=1.5\n"
      "REQUEST/1, F1=CONTACT(1,0,1,0)\\F2=CONTACT(1,0,4,0)\\F3=CONTACT(1,1,4,0)\\"
      "F4=CONTACT(1,1,6,0)\\F5=CONTACT(1,1,7,0)\\F6=CONTACT(1,0,5,0)\\F7=FZ(20)\n"
      "END\n");
  ASSERT_EQ(m.requests.size(), 1u);
  mechanics::MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
  const std::array<double, 8> c = analysis::requestColumns(s, m.requests[0], 0.0, y, yp);
  const double fn = 1e5 * std::pow(1e-3, 1.5);
  // The force acts midway between the surfaces, (0, 0, -d/2): about the J marker (the box
  // corner at (-1, -1, -1)) the reaction -Fn e_z has the moment (-Fn, Fn, 0).
  const double expected[7] = {fn, fn, -fn, -fn, fn, 0.0, fn};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(c[k], expected[k], 1e-12 * fn) << "F" << k + 1;
}

const char* kFrictionLaw =
    "COULOMB_FRICTION=ON, MU_STATIC=0.5, MU_DYNAMIC=0.3, STICTION_TRANSITION_VELOCITY=0.1, "
    "FRICTION_TRANSITION_VELOCITY=1\n";

TEST(ContactModel, SphereOnBoxPartialsAreExact) {
  // Penetration 2e-3 (> DMAX: full damping) then 5e-4 (in the damping ramp); slip on the
  // dynamic branch, on the transition branch and on the stiction branch.
  for (const double z : {0.098, 0.0995})
    for (const double vx : {2.0, 0.5, 0.05}) {
      const std::string deck = std::string(
                                   "sphere on box\n"
                                   "PART/1, GROUND\n"
                                   "MARKER/10, PART=1, QP=-1,-1,-1\n"
                                   "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
                                   "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, "
                                   "QG=0.1,0.2,") +
                               std::to_string(z) +
                               "\nMARKER/20, PART=2\n"
                               "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, "
                               "ZSCALE=0.2\n"
                               "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=50, "
                               "DMAX=1e-3, EXPONENT=1.5, " +
                               kFrictionLaw + "END\n";
      Eigen::VectorXd v(6);
      v << vx, -0.3 * vx, -0.2, 1.0, -2.0, 0.5;
      checkJacobian(deck, v);
    }
}

TEST(ContactModel, BoxOnBoxPartialsAreExact) {
  // A tilted block (REULER) with two corners in the floor, sliding and turning.
  const std::string deck = std::string(
                               "box on box\n"
                               "PART/1, GROUND\n"
                               "MARKER/10, PART=1, QP=-1,-1,-1\n"
                               "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
                               "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.006, "
                               "QG=0,0,0.058, REULER=0,5D,0\n"
                               "MARKER/20, PART=2\n"
                               "MARKER/21, PART=2, QP=-0.1,-0.1,-0.05\n"
                               "GRAPHICS/2, BOX, CORNER=21, X=0.2, Y=0.2, Z=0.1\n"
                               "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, "
                               "DAMPING=50, DMAX=1e-3, EXPONENT=1.5, ") +
                           kFrictionLaw + "END\n";
  Eigen::VectorXd v(6);
  v << 0.7, 0.2, -0.1, 0.3, 0.2, 1.0;
  checkJacobian(deck, v);
}

TEST(ContactModel, SparsePatternHoldsTheContactEntries) {
  // A sphere (part 2) in a moving box (part 3) and a third, free body (part 4): the contact
  // couples parts 2 and 3 only, and the pattern must hold every entry it creates.
  const model::Model m = build(
      std::string(
          "sparse pattern\n"
          "PART/1, GROUND\n"
          "PART/3, MASS=5, CM=30, IP=1,1,1, QG=0,0,-0.5\n"
          "MARKER/30, PART=3\n"
          "MARKER/31, PART=3, QP=-1,-1,-0.5\n"
          "GRAPHICS/1, BOX, CORNER=31, X=2, Y=2, Z=1\n"
          "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0.1,0.2,0.098, VX=1, VY=0.3, VZ=-0.2, "
          "WX=1, WY=2\n"
          "MARKER/20, PART=2\n"
          "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n"
          "PART/4, MASS=1, CM=40, IP=1,1,1, QG=5,5,5\n"
          "MARKER/40, PART=4\n"
          "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=50, DMAX=1e-3, "
          "EXPONENT=1.5, ") +
      kFrictionLaw + "END\n");
  mechanics::MultibodySystem s(m);
  // A dynamic analysis (DYNAMICS_ONLY friction acts): the mode is the run state's.
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&run);
  const Eigen::VectorXd y = s.initialState();
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());
  const mechanics::JacobianPattern pattern = mechanics::newtonMatrixPattern(s);
  Eigen::SparseMatrix<double> sparse = pattern.matrix();
  mechanics::SparseJacobianWork work;
  Eigen::MatrixXd dense;
  s.newtonMatrix(0.0, y, yp, 30.0, dense);
  s.newtonMatrixSparse(0.0, y, yp, 30.0, pattern, sparse, work);
  const double difference = (Eigen::MatrixXd(sparse) - dense).cwiseAbs().maxCoeff();
  std::printf("contact sparse pattern: max |sparse - dense| %.3e, largest entry %.3e\n", difference,
              dense.cwiseAbs().maxCoeff());
  EXPECT_LE(difference, 1e-12 * dense.cwiseAbs().maxCoeff());
  EXPECT_TRUE(s.rowsOutsidePattern(0.0, y, yp, 30.0, sparse, work).empty());
}

}  // namespace
}  // namespace openmss::contact_test
