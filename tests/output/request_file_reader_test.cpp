// Request file reader: every .req real ADAMS wrote in the validation data, line-end variants,
// repeated output times and malformed files.

#include "output/request_file_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/validation_data.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;

const fs::path kJoints = openmss::testing::adamsJointsDir();

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string withoutCr(std::string text) {
  std::erase(text, '\r');
  return text;
}

// A small well-formed file with two requests and the given time blocks appended.
std::string smallFile(const std::string& blocks) {
  return " A.R3    2000-01-01 00:00:00               0         0  3D\n"
         "title\n"
         "    2     M_KGS_N_RACA 1.000000000000000E+00\n"
         "          1             1           201           101             1\n"
         "DISP\n"
         "          9             5             0             0             0\n"
         "\n" +
         blocks;
}

std::string block(const std::string& time, const std::string& value) {
  std::string record = " ";
  for (int c = 0; c < 6; ++c) record += "  " + value;
  return " " + time + "\n" + record + "\n" + record + "\n";
}

class RealAdamsRequestFile : public ::testing::TestWithParam<std::string> {};

TEST_P(RealAdamsRequestFile, ReadsHeaderDirectoryAndEveryStep) {
  const std::string name = GetParam();
  const fs::path path = kJoints / name / ("test_" + name + "_ADAMS.req");
  ASSERT_TRUE(fs::exists(path)) << path;

  std::string error;
  const auto data = readRequestFile(path.string(), &error);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(data->header.title, "ADAMS/View model name: test_" + name);
  EXPECT_EQ(data->header.unitsToken, "M_KGS_N_RACA");
  EXPECT_EQ(data->header.lengthScale, 1.0);
  EXPECT_EQ(data->header.stamp.size(), 19u);

  ASSERT_EQ(data->entries.size(), 5u);
  const int types[] = {1, 2, 3, 5, 5};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(data->entries[k].id, static_cast<long>(k + 1));
    EXPECT_EQ(data->entries[k].type, types[k]);
    EXPECT_EQ(data->entries[k].iMarker, types[k] == 5 ? 0 : 201);
    EXPECT_EQ(data->entries[k].jMarker, types[k] == 5 ? 0 : 101);
  }
  EXPECT_EQ(data->entries[0].comment, "DISPLACEMENT: X Y Z PSI THETA PHI (body-fixed-3-1-3)");
  EXPECT_EQ(data->entries[1].comment, "VELOCITY X Y Z WX WY WZ");
  EXPECT_EQ(data->entries[3].comment, "EULER PARAMETERS");

  // t = 0..5 every 0.01; a run with an IC step writes t = 0 twice.
  ASSERT_TRUE(data->steps.size() == 501 || data->steps.size() == 502) << data->steps.size();
  const std::vector<RequestFileStep> steps = lastStepPerTime(data->steps);
  ASSERT_EQ(steps.size(), 501u);
  for (std::size_t s = 0; s < steps.size(); ++s) {
    EXPECT_NEAR(steps[s].time, 0.01 * static_cast<double>(s), 1e-9) << "step " << s;
    EXPECT_EQ(steps[s].rows.size(), 5u);
  }
  // The same bytes with LF line ends read the same.
  const auto lf = parseRequestFile(withoutCr(readText(path)), path.string(), &error);
  ASSERT_TRUE(lf) << error;
  ASSERT_EQ(lf->steps.size(), data->steps.size());
  EXPECT_EQ(lf->steps.back().rows, data->steps.back().rows);
}

INSTANTIATE_TEST_SUITE_P(AdamsJoints, RealAdamsRequestFile,
                         ::testing::Values("Revolute_Case01", "Revolute_Case02", "Spherical_Case01",
                                           "Spherical_Case02", "Universal_Case01",
                                           "Universal_Case02"));

TEST(RequestFileReader, ReadsValuesAsPrinted) {
  const fs::path path = kJoints / "Revolute_Case01/test_Revolute_Case01_ADAMS.req";
  ASSERT_TRUE(fs::exists(path)) << path;
  std::string error;
  const auto data = readRequestFile(path.string(), &error);
  ASSERT_TRUE(data) << error;
  const std::array<double, 6> expected = {2.00000E+00, 0.00000E+00, -4.78373E-04,
                                          1.80000E+02, 9.00000E+01, -1.79986E+02};
  EXPECT_EQ(data->steps[1].time, 1.0e-2);
  EXPECT_EQ(data->steps[1].rows[0], expected);
  EXPECT_EQ(data->steps.back().rows[4][5], -4.82862E-15);
}

TEST(RequestFileReader, ReadsAFileWithoutRequests) {
  // Real ADAMS output of a model without REQUEST statements, inch/pound units, LF line ends.
  const fs::path path = openmss::testing::corpusDir() /
                        "bthornton191__adamspy__test__existing_model__camelot_1_pull0_offset0.req";
  if (!fs::exists(path)) GTEST_SKIP() << openmss::testing::corpusAbsentMessage();
  std::string error;
  const auto data = readRequestFile(path.string(), &error);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(data->header.title, "Adams View model name: camelot_1");
  EXPECT_EQ(data->header.unitsToken, "INLBS_PFRACA");
  EXPECT_DOUBLE_EQ(data->header.lengthScale, 1.0 / 0.0254);
  EXPECT_TRUE(data->entries.empty());
  ASSERT_GT(data->steps.size(), 10u);
  EXPECT_EQ(data->steps[1].time, 1.0e-3);
}

TEST(RequestFileReader, KeepsRepeatedTimesAndCanDropAllButTheLast) {
  std::string error;
  const auto data = parseRequestFile(
      smallFile(block("  0.00000E+00", "1.00000E+00") + block("  0.00000E+00", "2.00000E+00") +
                block("  1.00000E-02", "3.00000E+00")),
      "repeated", &error);
  ASSERT_TRUE(data) << error;
  ASSERT_EQ(data->steps.size(), 3u);
  EXPECT_EQ(data->entries[1].comment, "");
  const std::vector<RequestFileStep> steps = lastStepPerTime(data->steps);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].rows[0][0], 2.0) << "the later record of t=0 is kept";
  EXPECT_EQ(steps[1].rows[1][5], 3.0);
}

TEST(RequestFileReader, ReadsValuesThatFillTheirWholeField) {
  // A three-digit negative exponent leaves no blank between two values.
  std::string error;
  const std::string record =
      "   1.00000E+00-1.00000E-300  3.00000E+00  4.00000E+00"
      "  5.00000E+00-6.00000E-300";
  const auto data =
      parseRequestFile(smallFile(" 0.0\n" + record + "\n" + record + "\n"), "touching", &error);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(data->steps[0].rows[0][1], -1.0e-300);
  EXPECT_EQ(data->steps[0].rows[1][5], -6.0e-300);
}

TEST(RequestFileReader, AcceptsAZeroWordCommentWithoutItsRecord) {
  std::string error;
  const std::string text =
      " A.R3    2000-01-01 00:00:00               0         0  3D\n"
      "title\n"
      "    1     M_KGS_N_RACA 1.000000000000000E+00\n"
      "          4             5             0             0             0\n"
      "   0.00000E+00\n"
      "   1.0 2.0 3.0 4.0 5.0 6.0\n";
  const auto data = parseRequestFile(text, "no-comment", &error);
  ASSERT_TRUE(data) << error;
  ASSERT_EQ(data->steps.size(), 1u);
  EXPECT_EQ(data->steps[0].rows[0][5], 6.0);
}

struct MalformedCase {
  std::string what;
  std::string text;
  std::string expectedMessage;
};

class MalformedRequestFile : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedRequestFile, SaysWhereAndWhat) {
  std::string error;
  const auto data = parseRequestFile(GetParam().text, "bad.req", &error);
  EXPECT_FALSE(data);
  EXPECT_NE(error.find(GetParam().expectedMessage), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Errors, MalformedRequestFile,
    ::testing::Values(
        MalformedCase{"empty", "", "bad.req: empty file"},
        MalformedCase{"not a request file", "hello\n", "bad.req:1: not a request file"},
        MalformedCase{"no count", " A.R3\ntitle\nfive M_KGS_N_RACA 1.0\n",
                      "bad.req:3: expected the number of requests"},
        MalformedCase{"short directory",
                      " A.R3\ntitle\n    2     M_KGS_N_RACA 1.0\n 1 1 2 3 1\nABCD\n",
                      "directory ends after 1 of 2 requests"},
        MalformedCase{"bad directory record", " A.R3\ntitle\n    1     M_KGS_N_RACA 1.0\n 1 1 2\n",
                      "bad.req:4: expected a directory record of five integers"},
        MalformedCase{"five values", smallFile(" 0.0\n 1 2 3 4 5\n"),
                      "bad.req:9: expected six numbers for REQUEST/1 at time 0.0"},
        MalformedCase{"not a number", smallFile(" 0.0\n 1 2 3 4 5 x\n"),
                      "bad.req:9: expected six numbers"},
        MalformedCase{"cut short", smallFile(" 0.0\n 1 2 3 4 5 6\n"),
                      "output step is cut short: no record for REQUEST/9 at time 0.0"},
        MalformedCase{"bad time record", smallFile(" 0.0 1.0\n"),
                      "bad.req:8: expected a time record (one number) after 0 complete"}),
    [](const ::testing::TestParamInfo<MalformedCase>& param) {
      std::string name = param.param.what;
      for (char& c : name) {
        if (c == ' ') c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace openmss::output
