// The graphics file (output/graphics_file.cpp; docs/output-files.md, "Graphics file (.gra)"):
// the piston's records as the data set defines them, and its step records read back: the
// piston's graphic marker placed through the written pose lands where the slider-crank's
// closed form puts the piston skirt. A step with the wrong number of poses is refused.

#include "output/graphics_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "common/rotation.hpp"
#include "language/reader.hpp"
#include "model/graphics_builder.hpp"
#include "model/model_builder.hpp"
#include "output/request_header.hpp"
#include "support/cli_run.hpp"

namespace openmss {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(GraphicsFile, PistonRecordsAndAStepReadBack) {
  Diagnostics diags;
  language::Dataset ds;
  language::readDatasetFile(std::string(OPENMSS_SOURCE_DIR) + "/examples/piston/piston.adm", ds,
                            diags);
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, diags));
  const std::vector<model::Graphic> graphics = model::buildGraphics(ds, m, diags);
  const auto path = testing::scratch("gra") / "piston.gra";
  output::GraphicsFileWriter w;
  std::string err;
  ASSERT_TRUE(w.open(path.string(), output::requestFileHeader(m, nullptr), m, graphics, &err))
      << err;
  // The slider-crank at t = 0.25 (crank at 90 degrees, r = 2, L = 8): the piston pin at
  // bx = sqrt(64 - 4), the piston CM 1 in beyond it, axes x=Y y=Z z=X throughout.
  const double bx = std::sqrt(60.0), half = 0.5 * std::numbers::pi;
  std::vector<output::GraphicsPose> poses(3);
  poses[2].position = {bx + 1.0, 0.0, 0.0};
  poses[2].angles = {half, half, 0.0};
  w.writeStep(0.25, poses);
  w.writeStep(0.5, {poses[2]});  // one pose for three moving parts: refused
  EXPECT_NE(w.error().find("1 part poses for 3 moving parts"), std::string::npos) << w.error();
  w.close();
  const std::vector<std::string> l = lines(testing::slurp(path));
  // 3 header lines, 4 parts, 5 graphics, 5 markers x 2 lines, 5 size records, 1 + 3 step lines.
  ASSERT_EQ(l.size(), 3u + 4 + 5 + 10 + 5 + 4) << testing::slurp(path);
  EXPECT_EQ(l[0], " A.G8    2000-01-01 00:00:00  INLBS_PFRACA 3.937007874015748E+01")
      << "the .req header's stamp and units tag";
  EXPECT_EQ(l[2], "     4    5    0    0    5    0    0    0    3");
  EXPECT_EQ(l[3], "          1         0");            // ground
  EXPECT_EQ(l[7], "        101         1       102");  // GRAPHICS/0101, CYLINDER, CM=0102
  // The piston's graphic marker 0402: 2 in behind the CM along the body z axis.
  const auto at402 = std::find_if(
      l.begin(), l.end(), [](const std::string& s) { return s.starts_with("        402"); });
  ASSERT_NE(at402, l.end());
  EXPECT_EQ(*at402, "        402         4  0.00000E+00  0.00000E+00 -2.00000E+00       0");
  EXPECT_EQ(l[27], "  2.50000E-01");
  // Read the piston's pose back (5 digits) and place marker 0402: the skirt at bx - 1.
  std::istringstream step(l[30]);
  Eigen::Vector3d p, a;
  step >> p.x() >> p.y() >> p.z() >> a.x() >> a.y() >> a.z();
  const Eigen::Vector3d skirt =
      p + matrixFromEuler313(a.x(), a.y(), a.z()) * Eigen::Vector3d(0, 0, -2);
  // Tolerance: 5 significant digits of numbers near 10 (5e-5) and of angles near 1.6 (the
  // rotation of the 2 in offset: 2 x 1e-5).
  EXPECT_NEAR(skirt.x(), bx - 1.0, 1e-4);
  EXPECT_NEAR(skirt.y(), 0.0, 1e-4);
  EXPECT_NEAR(skirt.z(), 0.0, 1e-4);
}

}  // namespace
}  // namespace openmss
