// `openmss view` on the command line (src/app/view_command.cpp, docs/viewer.md): the scene of
// the piston from its .acf (line 1 names the model), the located errors of a bad GRAPHICS, and
// the usage errors (no results file, no model, a bad port), each with its exit status. Serving
// the page is tested in a browser (tests/viewer/browser_test.py).

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace openmss {
namespace {

const std::string kPistonAcf = OPENMSS_SOURCE_DIR "/examples/piston/piston.acf";

TEST(View, WritesThePistonSceneFromItsCommandFile) {
  const auto dir = testing::scratch("view-scene");
  const auto r = testing::run("view '" + kPistonAcf + "' --write-scene scene.json", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string scene = testing::slurp(dir / "scene.json");
  int cylinders = 0;
  for (auto at = scene.find("\"CYLINDER\""); at != std::string::npos;
       at = scene.find("\"CYLINDER\"", at + 1))
    ++cylinders;
  EXPECT_EQ(cylinders, 5);
  EXPECT_NE(scene.find("\"title\":\"PISTON COMPRESSOR SAMPLE DATA SET\""), std::string::npos);
}

TEST(View, ABadGraphicsIsALocatedErrorAndNoScene) {
  const auto dir = testing::scratch("view-bad");
  testing::write(dir / "bad.adm",
                 "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "GRAPHICS/1, CYLINDER, CM=99, LENGTH=1, RADIUS=1\nEND\n");
  const auto r = testing::run("view bad.res --write-scene scene.json", dir);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("bad.adm:4:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("CM=99 names no marker"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "scene.json"));
}

TEST(View, UsageErrorsNameWhatIsMissing) {
  const auto dir = testing::scratch("view-usage");
  auto r = testing::run("view '" + kPistonAcf + "' --outdir .", dir);  // no piston.res here
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("piston.res not found"), std::string::npos) << r.output;
  r = testing::run("view nowhere.res", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("model nowhere.adm not found; name it with --model"), std::string::npos)
      << r.output;
  r = testing::run("view x.res --port http", dir);
  EXPECT_EQ(r.status, 64);
  EXPECT_NE(r.output.find("--port http is not a port number"), std::string::npos) << r.output;
  r = testing::run("view", dir);
  EXPECT_EQ(r.status, 64);
}

}  // namespace
}  // namespace openmss
