// The nine validation models of adams-joints must read without a single diagnostic, with the
// statements, arguments and values ADAMS read from them.

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "language/reader.hpp"
#include "support/validation_data.hpp"

namespace openmss::language {
namespace {

namespace fs = std::filesystem;

const fs::path kJoints = openmss::testing::adamsJointsDir();
const char* const kCases[] = {"Cylindrical_Case01", "Prismatic_Case01", "Prismatic_Case02",
                              "Revolute_Case01",    "Revolute_Case02",  "Spherical_Case01",
                              "Spherical_Case02",   "Universal_Case01", "Universal_Case02"};

const Statement* findStatement(const Dataset& ds, const std::string& name, long id) {
  for (const auto& s : ds.statements)
    if (s.name == name && s.id && *s.id == id) return &s;
  return nullptr;
}

std::string allDiagnostics(const Diagnostics& d) {
  std::string out;
  for (const auto& x : d.all()) out += format(x) + "\n";
  return out;
}

TEST(ValidationModels, AllNineDataSetsAndCommandFilesReadCleanly) {
  ASSERT_TRUE(fs::is_directory(kJoints)) << kJoints;
  for (const char* c : kCases) {
    const fs::path dir = kJoints / c;
    Dataset ds;
    Diagnostics diags;
    EXPECT_TRUE(readDatasetFile((dir / ("test_" + std::string(c) + ".adm")).string(), ds, diags));
    EXPECT_TRUE(diags.all().empty()) << c << "\n" << allDiagnostics(diags);
    EXPECT_TRUE(ds.sawEnd) << c;
    EXPECT_EQ(ds.title, "ADAMS/View model name: test_" + std::string(c));

    CommandFile cf;
    Diagnostics cdiags;
    EXPECT_TRUE(readCommandFile((dir / ("test_" + std::string(c) + ".acf")).string(), cf, cdiags));
    EXPECT_TRUE(cdiags.all().empty()) << c << "\n" << allDiagnostics(cdiags);
    EXPECT_EQ(cf.modelFile, "test_" + std::string(c) + ".adm");
    EXPECT_EQ(cf.outputPrefix, "test_" + std::string(c) + "_ADAMS");
    ASSERT_EQ(cf.commands.size(), 4u) << c;
    EXPECT_EQ(cf.commands[0].name, "OUTPUT");
    EXPECT_TRUE(cf.commands[0].has("NOSEPARATOR"));
    EXPECT_EQ(cf.commands[1].name, "INTEGRATOR");
    EXPECT_TRUE(cf.commands[1].has("GSTIFF"));
    ASSERT_NE(cf.commands[1].find("ERROR"), nullptr);
    EXPECT_DOUBLE_EQ(cf.commands[1].find("ERROR")->values.at(0).number, 1.0e-4);
    EXPECT_DOUBLE_EQ(cf.commands[1].find("HMAX")->values.at(0).number, 1e-5);
    EXPECT_EQ(cf.commands[2].name, "SIMULATE");
    EXPECT_TRUE(cf.commands[2].has("TRANSIENT"));
    EXPECT_DOUBLE_EQ(cf.commands[2].find("END")->values.at(0).number, 5.0);
    EXPECT_DOUBLE_EQ(cf.commands[2].find("DTOUT")->values.at(0).number, 0.01);
    EXPECT_EQ(cf.commands[3].name, "STOP");
  }
}

TEST(ValidationModels, RevoluteCase01HasTheStatementsAdamsRead) {
  const fs::path file = kJoints / "Revolute_Case01" / "test_Revolute_Case01.adm";
  ASSERT_TRUE(fs::exists(file)) << file;
  Dataset ds;
  Diagnostics diags;
  ASSERT_TRUE(readDatasetFile(file.string(), ds, diags)) << allDiagnostics(diags);

  const Statement* units = ds.statements.at(0).name == "UNITS" ? &ds.statements[0] : nullptr;
  ASSERT_NE(units, nullptr);
  EXPECT_EQ(units->find("FORCE")->values.at(0).text, "NEWTON");
  EXPECT_EQ(units->find("LENGTH")->values.at(0).text, "METER");

  const Statement* ground = findStatement(ds, "PART", 1);
  ASSERT_NE(ground, nullptr);
  EXPECT_TRUE(ground->has("GROUND"));

  const Statement* marker = findStatement(ds, "MARKER", 102);
  ASSERT_NE(marker, nullptr);
  const Argument* reuler = marker->find("REULER");
  ASSERT_NE(reuler, nullptr);
  ASSERT_EQ(reuler->values.size(), 3u);
  EXPECT_DOUBLE_EQ(reuler->values[0].number, std::numbers::pi);
  EXPECT_DOUBLE_EQ(reuler->values[1].number, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(reuler->values[2].number, std::numbers::pi);
  EXPECT_TRUE(reuler->values[0].degrees);
  EXPECT_EQ(reuler->separators, (std::vector<char>{',', ','}));
  EXPECT_EQ(marker->find("PART")->values.at(0).number, 1.0);

  const Statement* pendulum = findStatement(ds, "PART", 2);
  ASSERT_NE(pendulum, nullptr);
  EXPECT_EQ(pendulum->find("IP")->values.size(), 3u);
  EXPECT_EQ(pendulum->where.line, 38);
  EXPECT_EQ(pendulum->lastLine, 39);

  const Statement* joint = findStatement(ds, "JOINT", 1);
  ASSERT_NE(joint, nullptr);
  EXPECT_TRUE(joint->has("REVOLUTE"));
  EXPECT_EQ(joint->find("I")->values.at(0).number, 102.0);

  const Statement* r1 = findStatement(ds, "REQUEST", 1);
  ASSERT_NE(r1, nullptr);
  EXPECT_TRUE(r1->has("DISPLACEMENT"));
  EXPECT_EQ(r1->find("COMMENT")->values.at(0).text,
            "DISPLACEMENT: X Y Z PSI THETA PHI (body-fixed-3-1-3)");

  const Statement* r4 = findStatement(ds, "REQUEST", 4);
  ASSERT_NE(r4, nullptr);
  EXPECT_EQ(r4->find("F6")->expression, "ORIENT(27,4,0201,0101)");
  EXPECT_EQ(r4->find("COMMENT")->values.at(0).text, "EULER PARAMETERS");

  const Statement* r5 = findStatement(ds, "REQUEST", 5);
  ASSERT_NE(r5, nullptr);
  const char* expected[] = {"F2", "JOINT(1,0,2,0)", "F3", "JOINT(1,0,3,0)", "F4", "JOINT(1,0,4,0)",
                            "F6", "JOINT(1,0,6,0)", "F7", "JOINT(1,0,7,0)", "F8", "JOINT(1,0,8,0)"};
  for (int k = 0; k < 12; k += 2) {
    const Argument* f = r5->find(expected[k]);
    ASSERT_NE(f, nullptr) << expected[k];
    EXPECT_TRUE(f->isExpression);
    EXPECT_EQ(f->expression, expected[k + 1]);
  }
  EXPECT_EQ(r5->find("COMMENT")->values.at(0).text, "RForce X Y Z RTorque X Y Z");
  EXPECT_TRUE(r5->find("COMMENT")->isText);

  const Statement* grav = nullptr;
  for (const auto& s : ds.statements)
    if (s.name == "ACCGRAV") grav = &s;
  ASSERT_NE(grav, nullptr);
  EXPECT_DOUBLE_EQ(grav->find("KGRAV")->values.at(0).number, -9.80665);
  EXPECT_EQ(ds.statements.back().name, "OUTPUT");
  EXPECT_TRUE(ds.statements.back().has("REQSAVE"));
}

}  // namespace
}  // namespace openmss::language
