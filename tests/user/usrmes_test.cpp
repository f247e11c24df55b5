// USRMES from user routines in both calling styles (tests/user/element_routines.c Usrmes_req,
// element_routines.f USRREQ): the message is printed with its type and the element id when
// MSGFLG is true, and not at all when it is false (docs/user-subroutines.md, "Other utilities").

#include <gtest/gtest.h>

#include <string>

#include "support/cli_run.hpp"

namespace openmss {
namespace {

TEST(Usrmes, PrintsWhenAskedInBothCallingStyles) {
  const std::filesystem::path dir = testing::scratch("usrmes");
  const std::string c = OPENMSS_TEST_C_ROUTINES, f = OPENMSS_TEST_F77_ROUTINES;
  testing::write(dir / "m.adm",
                 "usrmes\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "PART/2, MASS=1, IP=1,1,1, CM=20\nMARKER/20, PART=2\n"
                 "REQUEST/1, FUNCTION=USER(0), ROUTINE=\"" +
                     c + "::Usrmes_req\"\nREQUEST/2, FUNCTION=USER(0), ROUTINE=\"" + f +
                     "::Usrreq\"\nOUTPUT/ REQSAVE\nEND\n");
  const testing::Result r = testing::run("run m.adm --end 1 --steps 4", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("USRMES INFO (id 1): C REQSUB says hello"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("USRMES WARNING (id 2): FORTRAN REQSUB says hello"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("never printed"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace openmss
