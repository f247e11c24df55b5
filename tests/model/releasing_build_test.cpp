// buildModelReleasingContacts (model/releasing_build.hpp), the build of `openmss check` and
// Session::loadModel: the same model and the same diagnostics as buildModel, with each CONTACT
// statement's arguments released once its contact is built (docs/performance.md, "Memory of a
// parsed data set").

#include "model/releasing_build.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

// Three spheres over a ground BOX: CONTACT/1 and /3 build; CONTACT/2 names a GRAPHICS that does
// not exist (line 13), so the build reports it at that CONTACT.
const char* kDeck =
    "pile\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, QP=-1,-1,-1\n"
    "GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1\n"
    "PART/2, MASS=0.1, CM=20, IP=1e-4,1e-4,1e-4, QG=0,0,0.06\n"
    "MARKER/20, PART=2\n"
    "GRAPHICS/20, ELLIPSOID, CM=20, XSCALE=0.1, YSCALE=0.1, ZSCALE=0.1\n"
    "PART/3, MASS=0.1, CM=30, IP=1e-4,1e-4,1e-4, QG=0,0,0.2\n"
    "MARKER/30, PART=3\n"
    "GRAPHICS/30, ELLIPSOID, CM=30, XSCALE=0.1, YSCALE=0.1, ZSCALE=0.1\n"
    "CONTACT/1, IGEOM=20, JGEOM=1, IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5\n"
    "REQUEST/1, DISPLACEMENT, I=20\n"
    "CONTACT/2, IGEOM=30, JGEOM=99, IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5\n"
    "CONTACT/3, IGEOM=30, JGEOM=20, IMPACT, STIFFNESS=2e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5\n"
    "END\n";

std::vector<std::string> formatted(const Diagnostics& d) {
  std::vector<std::string> out;
  for (const auto& x : d.all()) out.push_back(format(x));
  return out;
}

TEST(ReleasingBuild, SameModelAndDiagnosticsAsBuildModel) {
  Diagnostics readA, readB;
  language::Dataset a, b;
  language::readDatasetText(kDeck, "pile.adm", a, readA);
  language::readDatasetText(kDeck, "pile.adm", b, readB);
  ASSERT_FALSE(readA.hasErrors());
  Model kept, released;
  const bool okKept = buildModel(a, kept, readA);
  const bool okReleased = buildModelReleasingContacts(b, released, readB);
  EXPECT_FALSE(okKept);  // CONTACT/2
  EXPECT_EQ(okReleased, okKept);
  // The diagnostics, to the letter: the refusal still names file:line, CONTACT/2 and JGEOM.
  EXPECT_EQ(formatted(readB), formatted(readA));
  ASSERT_EQ(readA.errorCount(), 1);
  EXPECT_NE(formatted(readA)[0].find("pile.adm:13:"), std::string::npos) << formatted(readA)[0];
  EXPECT_NE(formatted(readA)[0].find("CONTACT/2"), std::string::npos) << formatted(readA)[0];
  // The contacts, field by field where the arguments put them.
  ASSERT_EQ(released.contacts.size(), 2u);
  ASSERT_EQ(kept.contacts.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(released.contacts[k].id, kept.contacts[k].id);
    EXPECT_EQ(released.contacts[k].stiffness, kept.contacts[k].stiffness);
    EXPECT_EQ(released.contacts[k].iPart, kept.contacts[k].iPart);
    EXPECT_EQ(released.contacts[k].jPart, kept.contacts[k].jPart);
    EXPECT_EQ(released.contacts[k].where.line, kept.contacts[k].where.line);
  }
  EXPECT_EQ(released.contacts[1].stiffness, 2e5);
  EXPECT_EQ(released.requests.size(), kept.requests.size());
  // Every CONTACT statement's arguments are released, its name, id and line kept; the other
  // statements are untouched.
  int contacts = 0;
  for (size_t k = 0; k < b.statements.size(); ++k) {
    const language::Statement& s = b.statements[k];
    EXPECT_EQ(s.name, a.statements[k].name);
    EXPECT_EQ(s.id, a.statements[k].id);
    EXPECT_EQ(s.where.line, a.statements[k].where.line);
    if (s.name == "CONTACT") {
      ++contacts;
      EXPECT_TRUE(s.args.empty()) << s.subject();
    } else {
      EXPECT_EQ(s.args.size(), a.statements[k].args.size()) << s.subject();
    }
  }
  EXPECT_EQ(contacts, 3);
}

}  // namespace
}  // namespace openmss::model
