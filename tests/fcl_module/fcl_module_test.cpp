// The FCL narrow phase as a run-time module (docs/architecture.md, "FCL module"), in an
// executable of its own so that the process starts without it:
// - a model whose CONTACT is analytic (a sphere on a BOX) never opens the module, and its depth
//   is the closed form;
// - a pair that needs FCL (an ELLIPSOID of unequal scales on a BOX) is refused, located and
//   naming the pair and the path tried, when the module cannot be opened (OPENMSS_FCL_MODULE
//   pointing nowhere);
// - the same model without the override opens the module and FCL's depth is the closed form.

#include "user/fcl_module.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "contact/contact_support.hpp"
#include "mechanics/contact/contact_loads.hpp"

namespace openmss::contact_test {
namespace {

// A solid on part 2 (CM marker 20 at QG = (0, 0, z)) above a ground BOX whose top is z = 0;
// the CONTACT is line 9.
std::string deck(const std::string& graphics, double z) {
  char part[200];
  std::snprintf(part, sizeof part, "PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,%.17g\n",
                z);
  return std::string("drop\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n") +
         "PART/1, GROUND\nMARKER/10, PART=1, QP=-1,-1,-1\n"
         "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n" +
         part + "MARKER/20, PART=2\n" + graphics +
         "CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, "
         "EXPONENT=1.5\nEND\n";
}

double initialDepth(const model::Model& m) {
  mechanics::MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState();
  return mechanics::contact::contactLoads(m, s.layout(), m.contacts[0], y.data(), false).maxDepth;
}

TEST(FclModule, OpenedOnlyForAPairThatNeedsIt) {
  // Lowest points 1e-3 below the BOX's top: the depth is 1e-3 for both solids.
  const std::string sphere = "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.2, YSCALE=0.2, ZSCALE=0.2\n";
  const std::string flat = "GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.6, YSCALE=0.4, ZSCALE=0.2\n";
  ASSERT_FALSE(user::fclModuleLoaded());  // the process starts without libfcl
  const model::Model analytic = build(deck(sphere, 0.099));
  // Analytic sphere-box depth: exact but for rounding of 0.1 - 0.099.
  EXPECT_NEAR(initialDepth(analytic), 1e-3, 1e-15);
  EXPECT_FALSE(user::fclModuleLoaded());

  ::setenv("OPENMSS_FCL_MODULE", "/nonexistent/openmss_fcl.so", 1);
  const testing::BuiltModel refused = testing::buildModelFromText(deck(flat, 0.099), "fcl.adm");
  expectOneError(refused, 9, "GRAPHICS/2 against GRAPHICS/1 needs the FCL narrow phase");
  EXPECT_NE(::testing::PrintToString(refused.messages()).find("/nonexistent/openmss_fcl.so"),
            std::string::npos);
  EXPECT_FALSE(user::fclModuleLoaded());

  ::unsetenv("OPENMSS_FCL_MODULE");
  const model::Model library = build(deck(flat, 0.099));
  EXPECT_TRUE(user::fclModuleLoaded());
  // FCL's MPR to 1e-12 (fcl_narrow_phase.cpp): the depth to 1e-9 of its size and more.
  EXPECT_NEAR(initialDepth(library), 1e-3, 1e-12);
}

}  // namespace
}  // namespace openmss::contact_test
