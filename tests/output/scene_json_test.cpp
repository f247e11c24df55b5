// The viewer's scene (output/scene_json.cpp, docs/viewer.md "scene.json"): the piston's parts,
// graphics and markers written exactly as the data set places them (worked out by hand from
// its comments), the same bytes on every write, and JSON string escapes.

#include "output/scene_json.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "language/reader.hpp"
#include "model/graphics_builder.hpp"
#include "model/model_builder.hpp"

namespace openmss {
namespace {

std::string pistonScene() {
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetFile(std::string(OPENMSS_SOURCE_DIR) + "/examples/piston/piston.adm",
                            dataset, diags);
  model::Model m;
  EXPECT_TRUE(model::buildModel(dataset, m, diags));
  const std::vector<model::Graphic> graphics = model::buildGraphics(dataset, m, diags);
  std::ostringstream out;
  output::writeSceneJson(m, graphics, out);
  return out.str();
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SceneJson, PistonPartsGraphicsAndMarkersAsTheDataSetPlacesThem) {
  const std::string s = pistonScene();
  EXPECT_EQ(count(s, "\"ground\":"), 4);            // four parts
  EXPECT_EQ(count(s, "\"kind\":\"CYLINDER\""), 5);  // five cylinders
  // The piston: CM at x = 11 with axes x=Y y=Z z=X (REULER 90D, 90D, 0); its cylinder's
  // marker has the same axes, 2 in behind the CM along X, i.e. along the body z axis.
  EXPECT_NE(s.find("{\"id\":4,\"ground\":false,\"position\":[11,0,0],"
                   "\"orientation\":[0,0,1,1,0,0,0,1,0]}"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("{\"id\":401,\"kind\":\"CYLINDER\",\"part\":4,\"marker\":402,"
                   "\"position\":[0,0,-2],\"orientation\":[1,0,0,0,1,0,0,0,1],\"radius\":1.5,"
                   "\"length\":4,\"rangle\":6.2831853071795862,\"sides\":20}"),
            std::string::npos)
      << s;
  // The ground's cylinder: the ground frame is the global one.
  EXPECT_NE(s.find("{\"id\":101,\"kind\":\"CYLINDER\",\"part\":1,\"marker\":102,"
                   "\"position\":[5,0,0],\"orientation\":[0,0,1,1,0,0,0,1,0],\"radius\":1.55,"),
            std::string::npos)
      << s;
  EXPECT_EQ(s, pistonScene());  // deterministic
}

TEST(SceneJson, StringsAreEscaped) {
  EXPECT_EQ(output::jsonString("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
}

}  // namespace
}  // namespace openmss
