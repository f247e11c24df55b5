// MATERIAL statements (model/material_builder.cpp): stored as data with their properties,
// each property checked against the range of an isotropic elastic solid, and a PART's
// MATERIAL= checked to name one (a warning: the reference has no effect on a rigid part).

#include "model/material_builder.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/built_model.hpp"

namespace openmss::model {
namespace {

const char* kHeader =
    "materials\n"
    "PART/1, GROUND, MATERIAL=steel\n"
    "MARKER/10, PART=1\n";

TEST(MaterialBuilder, MaterialsAreStoredAsDataAndPartsNameThem) {
  const auto b = testing::buildModelFromText(
      std::string(kHeader) +
          "MATERIAL/1, NAME=steel, YOUNGS_MODULUS=2.07E+11, POISSONS_RATIO=0.29\n"
          ", DENSITY=7801\n"
          "PART/2, MASS=1, CM=20, IP=1,1,1, MATERIAL=steel\n"
          "MARKER/20, PART=2\n"
          "END\n",
      "m.adm");
  ASSERT_TRUE(b.ok) << ::testing::PrintToString(b.messages());
  EXPECT_TRUE(b.messages().empty()) << ::testing::PrintToString(b.messages());
  language::Dataset ds;
  Diagnostics diags;
  language::readDatasetText(std::string(kHeader) +
                                "MATERIAL/1, NAME=steel, YOUNGS_MODULUS=2.07E+11, "
                                "POISSONS_RATIO=0.29\n, DENSITY=7801\nEND\n",
                            "m.adm", ds, diags);
  const std::vector<Material> materials = readMaterials(ds, diags);
  EXPECT_TRUE(diags.all().empty());
  ASSERT_EQ(materials.size(), 1u);
  const Material& m = materials[0];
  EXPECT_EQ(m.id, 1);
  EXPECT_EQ(m.name, "STEEL");
  EXPECT_EQ(m.density, 7801.0);
  EXPECT_EQ(m.youngsModulus, 2.07e11);
  EXPECT_EQ(m.poissonsRatio, 0.29);
  EXPECT_EQ(m.where.line, 4);
  // Data only: the part's mass is its MASS.
  EXPECT_EQ(b.part(2).mass, 1.0);
}

TEST(MaterialBuilder, PropertiesOutOfRangeAndUnknownNamesAreLocated) {
  const auto b = testing::buildModelFromText(
      std::string(kHeader) +
          "MATERIAL/1, NAME=rubber, DENSITY=-1, YOUNGS_MODULUS=0, POISSONS_RATIO=0.5\n"
          "PART/2, MASS=1, CM=20, IP=1,1,1, MATERIAL=wood\n"
          "MARKER/20, PART=2\n"
          "END\n",
      "m.adm");
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.messages(),
            (std::vector<std::string>{
                "m.adm:4:26: error: MATERIAL/1: DENSITY must be positive. Give DENSITY=<value> "
                "> 0.",
                "m.adm:4:38: error: MATERIAL/1: YOUNGS_MODULUS must be positive. Give "
                "YOUNGS_MODULUS=<value> > 0.",
                "m.adm:4:56: error: MATERIAL/1: POISSONS_RATIO must lie between -1 and 0.5. Give "
                "the ratio of an isotropic solid (steel 0.29, rubber close to 0.5).",
                "m.adm:2:17: warning: PART/1: MATERIAL=STEEL names no MATERIAL statement; it "
                "has no effect (the part's mass and inertia come from MASS and IP). Add "
                "MATERIAL/<id>, NAME=STEEL, or remove MATERIAL=.",
                "m.adm:5:34: warning: PART/2: MATERIAL=WOOD names no MATERIAL statement; it has "
                "no effect (the part's mass and inertia come from MASS and IP). Add "
                "MATERIAL/<id>, NAME=WOOD, or remove MATERIAL=."}));
}

}  // namespace
}  // namespace openmss::model
